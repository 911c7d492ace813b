#!/usr/bin/env bash
# Gradescope runs this once when it builds the autograder image (Ubuntu, as root), with the
# autograder zip unpacked in /autograder/source. Two ways, as make_autograder_zip packed it:
# - with --deb, the zip has tackle's .deb (built for the image's release, docs/grading.md):
#   apt installs it and its Depends (the libraries and python3, no build tools);
# - else the zip has tackle's source (source/tackle): this builds it with the repository's
#   own set-up, which installs what it needs from the distribution's packages.
# AUTOGRADER (default /autograder) can be overridden to try it anywhere.
set -euo pipefail
root=${AUTOGRADER:-/autograder}
debs=("$root"/source/tackle_*.deb)
if [ -f "${debs[0]}" ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${debs[0]}"
else
  "$root/source/tackle/scripts/setup"
  ln -sfn "$root/source/tackle" "$root/tackle"
fi
