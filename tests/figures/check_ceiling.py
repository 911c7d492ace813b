#!/usr/bin/env python3
"""The figures' legibility, held at its ceiling: generates the 40 mechanisms (generate.py, seed
44) into WORKDIR, runs the legibility measure (legibility.py) over every example and them in
SVG and TikZ, and fails when a count of ceiling.json is exceeded (it says which, and the
defects' lines). A count below its ceiling is said too, so that the ceiling is lowered.

Usage: check_ceiling.py TACKLE SOURCE_DIR WORKDIR
Exit: 0 within the ceiling, 1 above it, 2 on a usage error or a measure that could not run."""
import glob
import json
import os
import subprocess
import sys


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    tackle, src, work = argv[1:]
    here = os.path.join(src, "tests", "figures")
    generated = os.path.join(work, "figures-generated")
    os.makedirs(generated, exist_ok=True)
    gen = subprocess.run([sys.executable, os.path.join(here, "generate.py"), generated, "--check", tackle],
                         capture_output=True, text=True)
    if gen.returncode != 0:
        print("generate.py failed:\n" + gen.stdout + gen.stderr, file=sys.stderr)
        return 2
    files = sorted(glob.glob(os.path.join(src, "examples", "*.yaml"))) + sorted(
        glob.glob(os.path.join(generated, "*.yaml")))
    summary = os.path.join(work, "figures-legibility.json")
    run = subprocess.run([sys.executable, os.path.join(here, "legibility.py"), tackle, *files, "--json", summary],
                         capture_output=True, text=True)
    if run.returncode not in (0, 1):
        print("legibility.py could not run:\n" + run.stdout + run.stderr, file=sys.stderr)
        return 2
    with open(summary) as f:
        measured = json.load(f)["by_format"]
    with open(os.path.join(here, "ceiling.json")) as f:
        ceiling = json.load(f)
    over = []
    for fmt in ("svg", "tikz"):
        for kind, limit in ceiling[fmt].items():
            got = measured[fmt][kind]
            if got > limit:
                over.append(f"{fmt}: {got} {kind} (the ceiling is {limit})")
            elif got < limit:
                print(f"{fmt}: {got} {kind}, below the ceiling of {limit}: lower it in tests/figures/ceiling.json")
    if over:
        print("legibility above its ceiling:\n  " + "\n  ".join(over))
        print(run.stdout)
        return 1
    print("legibility within its ceiling: " + json.dumps(measured))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
