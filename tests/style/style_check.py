#!/usr/bin/env python3
"""The project's style, kept: every C++ source as .clang-format formats it, and no function in
src/ too long to read at once (Universal Ctags' count: none over 150 lines, at most 8 over 100),
no source file in src/ over 800 lines.
Exits 77 (skipped) when clang-format or Universal Ctags is not installed."""
import pathlib
import shutil
import subprocess
import sys

root = pathlib.Path(sys.argv[1])
LONGEST, LONG, MOST_LONG = 150, 100, 8
LONGEST_FILE = 800


def sources(*folders):
    return sorted(str(p) for f in folders for ext in ("cpp", "hpp") for p in (root / f).rglob(f"*.{ext}"))


def unformatted():
    r = subprocess.run(["clang-format", "--dry-run", "-Werror", "--style=file"] + sources("src", "tests", "bench"),
                       cwd=root, capture_output=True, text=True)
    return sorted({line.split(":")[0] for line in r.stderr.splitlines() if ": error:" in line})


def function_lengths():
    r = subprocess.run(["ctags", "--languages=C++", "--c++-kinds=f", "--fields=+ne", "-R", "-f", "-", "src"],
                       cwd=root, capture_output=True, text=True, check=True)
    lengths = []
    for line in r.stdout.splitlines():
        fields = line.split("\t")
        start = next((f[5:] for f in fields[3:] if f.startswith("line:")), None)
        end = next((f[4:] for f in fields[3:] if f.startswith("end:")), None)
        if start and end:
            lengths.append((int(end) - int(start) + 1, f"{fields[1]}:{start}", fields[0]))
    return sorted(lengths, reverse=True)


def main():
    ctags = shutil.which("ctags")
    if not shutil.which("clang-format") or not ctags or "Universal" not in subprocess.run(
            [ctags, "--version"], capture_output=True, text=True).stdout:
        print("clang-format or Universal Ctags is not installed: style not checked")
        return 77
    failed = False
    for f in unformatted():
        print(f"{f}: not as .clang-format formats it (run clang-format -i {f})")
        failed = True
    lengths = function_lengths()
    for n, where, name in lengths:
        if n > LONGEST:
            print(f"{where}: {name} is {n} lines (at most {LONGEST})")
            failed = True
    long = [x for x in lengths if x[0] > LONG]
    if len(long) > MOST_LONG:
        print(f"{len(long)} functions are over {LONG} lines (at most {MOST_LONG}): "
              + ", ".join(f"{name} {n}" for n, _, name in long))
        failed = True
    for f in sources("src"):
        n = sum(1 for _ in open(f, encoding="utf-8"))
        if n > LONGEST_FILE:
            print(f"{f}: {n} lines (at most {LONGEST_FILE} in a file)")
            failed = True
    print(f"{len(lengths)} functions; the longest {lengths[0][2]} ({lengths[0][0]} lines); {len(long)} over {LONG}")
    return 1 if failed else 0


sys.exit(main())
