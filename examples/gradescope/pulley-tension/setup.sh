#!/usr/bin/env bash
# Gradescope runs this once when it builds the autograder image (Ubuntu, as root), with the
# autograder zip unpacked in /autograder/source. make_autograder_zip puts tackle's source in
# the zip (source/tackle); this builds it with the repository's own set-up, which installs
# what it needs from the distribution's packages.
set -euo pipefail
/autograder/source/tackle/scripts/setup
ln -sfn /autograder/source/tackle /autograder/tackle
