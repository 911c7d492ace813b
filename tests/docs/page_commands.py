"""A page of the documentation as a script (docs/tutorial.md, docs/cookbook.md, docs/syntax.md):
its files are written and its commands run, in the page's order, in an empty directory, and
every output line it shows must be there.

The page's conventions, which this test reads:
- A fenced block right after a line that ends with `NAME`: (a file name in backticks, then a
  colon) is that file. When the line says "the end of", the block is appended to the file;
  else it replaces it. When NAME is a path in the source tree (it has a /), the block is an
  excerpt of that file instead: it must appear in it word for word (a `...` line between
  parts leaves lines out).
- A ```console block holds commands, each on a line that starts with `$ `: `$ tackle ARGS`
  runs the program under test, `$ cat FILE` shows a file the commands wrote. The lines after
  a command, up to the next one, are its output as shown: each must be a whole line of the
  output (standard output or standard error), in order; `...` stands for lines left out. No
  other command may be shown in a console block (the test could not run it).
- A command exits with 0, or with 1 when what it shows is a located error (`FILE:LINE:COL: `).

- A line `![...](cookbook/NAME.svg)` shows the sketch of the file NAME.yaml written before it:
  the SVG in docs/cookbook/ must be the one `tackle sheet NAME.yaml --format markdown` draws
  now (`--write-sketches` writes them instead).

Each page adds its own checks: the tutorial's finished description must give the answers of
the bundled example it rebuilds (examples/sample-12.3-two-mass-pulley.yaml); every
description the cookbook writes must solve (`tackle solve` exits with 0) and be shown solved.

Usage: page_commands.py TACKLE_PROGRAM SOURCE_DIR [PAGE [--write-sketches]]   (PAGE: docs/tutorial.md)"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

TACKLE, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
PAGE_NAME = sys.argv[3] if len(sys.argv) > 3 else "docs/tutorial.md"
PAGE = os.path.join(SOURCE, PAGE_NAME)
WRITE_SKETCHES = "--write-sketches" in sys.argv[4:]
SKETCH = re.compile(r"!\[[^\]]*\]\((cookbook/([A-Za-z0-9_-]+)\.svg)\)")
# The least a page must hold (commands, files, excerpts): a page that lost its blocks would pass.
LEAST = {"docs/tutorial.md": (20, 4, 2), "docs/cookbook.md": (24, 12, 0), "docs/syntax.md": (6, 2, 0)}
LOCATED = re.compile(r"^\S+:\d+:\d+: ")
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def blocks(text):
    """(info string, body, the last non-blank line before the fence, line number) of each fenced block."""
    lines = text.split("\n")
    out, before, i = [], "", 0
    while i < len(lines):
        if lines[i].startswith("```"):
            info, start, body = lines[i][3:].strip(), i + 1, []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            out.append((info, body, before, start))
            before = ""
        elif lines[i].strip():
            before = lines[i]
        i += 1
    return out


def shown_in(shown, output):
    """Whether each shown line is a whole line of the output, in order ('...' skips)."""
    got = [line.rstrip() for line in output.split("\n")]
    at = 0
    for want in shown:
        if want == "...":
            continue
        while at < len(got) and got[at] != want.rstrip():
            at += 1
        if at == len(got):
            return want
        at += 1
    return None


def run(command, shown, where, work, solved):
    """Runs one console command; checks its status and the output shown."""
    words = shlex.split(command)
    if words[:2] == ["tackle", "solve"] and len(words) > 2:
        solved.add(words[2])
    if words[0] == "cat" and len(words) == 2:
        with open(os.path.join(work, words[1]), encoding="utf-8") as f:
            streams = [f.read()]
        status, expected = 0, 0
    elif words[0] == "tackle":
        r = subprocess.run([TACKLE] + words[1:], cwd=work, capture_output=True, text=True, stdin=subprocess.DEVNULL)
        streams, status = [r.stdout, r.stderr], r.returncode
        shown_lines = [s for s in shown if s != "..."]
        expected = 1 if shown_lines and LOCATED.match(shown_lines[0]) else 0
    else:
        fail(f"{where}: '$ {command}': the test runs only '$ tackle ...' and '$ cat FILE'")
        return
    if status != expected:
        fail(f"{where}: '$ {command}' exited with {status}, expected {expected}\n" + "".join(streams)[-2000:])
    # Shown lines come from one stream (a command's report, or its errors).
    missing = [shown_in(shown, s) for s in streams]
    if all(m is not None for m in missing):
        fail(f"{where}: '$ {command}': this shown line is not in the output (in order): {missing[0]!r}\n"
             + "--- output:\n" + "".join(streams)[:3000])


def check_sketches(page, work):
    """Each sketch the page shows is the one tackle draws now from the file it names."""
    count = 0
    for match in SKETCH.finditer(page):
        svg_path, name = os.path.join(SOURCE, "docs", match.group(1)), match.group(2)
        r = subprocess.run([TACKLE, "sheet", name + ".yaml", "--format", "markdown"], cwd=work,
                           capture_output=True, text=True, stdin=subprocess.DEVNULL)
        drawn = re.search(r"<svg.*?</svg>", r.stdout, re.S)
        if r.returncode != 0 or not drawn:
            fail(f"{PAGE_NAME}: tackle draws no sketch of {name}.yaml:\n{r.stderr[-2000:]}")
            continue
        count += 1
        if WRITE_SKETCHES:
            with open(svg_path, "w", encoding="utf-8") as f:
                f.write(drawn.group(0) + "\n")
            continue
        try:
            with open(svg_path, encoding="utf-8") as f:
                shown = f.read()
        except OSError:
            shown = None
        if shown != drawn.group(0) + "\n":
            fail(f"{PAGE_NAME}: docs/{match.group(1)} is not the sketch tackle draws now of {name}.yaml "
                 f"(run tests/docs/page_commands.py TACKLE . {PAGE_NAME} --write-sketches)")
    return count


def main():
    with open(PAGE, encoding="utf-8") as f:
        page = f.read()
    commands = files = excerpts = 0
    written, solved = [], set()
    with tempfile.TemporaryDirectory() as work:
        for info, body, before, line in blocks(page):
            where = f"{PAGE_NAME}:{line}"
            named = re.search(r"`([^`\s]+)`:\s*$", before)
            if info == "console":
                command, shown = None, []
                for text in body + ["$ "]:
                    if text.startswith("$ "):
                        if command:
                            run(command, shown, where, work, solved)
                            commands += 1
                        command, shown = text[2:].strip(), []
                    else:
                        shown.append(text)
            elif named and "/" in named.group(1):
                with open(os.path.join(SOURCE, named.group(1)), encoding="utf-8") as f:
                    source = f.read()
                # ('...' lines leave lines out: the parts must appear in the file in order.)
                parts, at = "\n".join(body).split("\n...\n"), 0
                for part in parts:
                    at = source.find(part, at)
                    if at < 0:
                        fail(f"{where}: this block is not an excerpt of {named.group(1)} (word for word): {part[:200]!r}")
                        break
                    at += len(part)
                excerpts += 1
            elif named:
                mode = "a" if "the end of" in before else "w"
                with open(os.path.join(work, named.group(1)), mode, encoding="utf-8") as f:
                    f.write("\n".join(body) + "\n")
                files += 1
                written.append(named.group(1))
        sketches = check_sketches(page, work)
        if PAGE_NAME == "docs/tutorial.md":
            # The finished description is sample 12.3: the same answers as the bundled example.
            mine = subprocess.run([TACKLE, "solve", "pulley.yaml"], cwd=work, capture_output=True, text=True)
            bundled = subprocess.run([TACKLE, "solve", os.path.join(SOURCE, "examples/sample-12.3-two-mass-pulley.yaml")],
                                     capture_output=True, text=True)
            if mine.returncode != 0 or mine.stdout != bundled.stdout:
                fail("the tutorial's pulley.yaml does not solve as examples/sample-12.3-two-mass-pulley.yaml:\n"
                     + mine.stdout + mine.stderr + "--- the example:\n" + bundled.stdout)
        if PAGE_NAME == "docs/cookbook.md":
            # Every description solves, and the page shows it solved (with the numbers it states).
            for name in written:
                if name not in solved:
                    fail(f"{PAGE_NAME}: {name} is written but never shown solved ('$ tackle solve {name}')")
            if sketches < len(written):
                fail(f"{PAGE_NAME}: {sketches} sketches for {len(written)} descriptions")
    # A page that lost its blocks would pass everything above.
    least = LEAST.get(PAGE_NAME, (1, 0, 0))
    if commands < least[0] or files < least[1] or excerpts < least[2]:
        fail(f"only {commands} commands, {files} files and {excerpts} excerpts found in {PAGE_NAME}")
    print(f"{PAGE_NAME}: {commands} commands run, {files} files written, {excerpts} excerpts checked, "
          f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
