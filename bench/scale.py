#!/usr/bin/env python3
"""Scale benchmark: tackle against its peers on the same equations, in the same run.

  python3 bench/scale.py [--kinds chain,cascade,tackle,carts] [--sizes chain=16,32,64,128,256 ...]
                         [--peers ginac,sympy,maxima,giac] [--timeout 60] [--repeat 3] [--files F,...]
                         [--instructions]

For each kind (bench/generate.py) and size n it writes the description, then times, whole
process and best of --repeat runs:
  tackle solve    `build/tackle solve FILE`  (peak memory: the process's own maximum resident size)
  tackle derive   `build/tackle derive FILE`
and, on the equations tackle writes (`derive --format json`: `equations` and `solved_for`),
the peers:
  ginac           build/bench/ginac_lsolve: GiNaC's lsolve(), each value put in normal form
  sympy           python3 with SymPy: linsolve()
  maxima          maxima --batch-string: linsolve()
  giac            giac: linsolve()
Each peer's time includes its start-up, printed once on its own (a 1-unknown system). A run
past --timeout is shown as "> T". The growth exponent between the two largest sizes that
finished is printed for each column. Timings are for reading; nothing here passes or fails.
With --instructions, the instructions `tackle solve` executes are counted too (valgrind's
callgrind, one run each): a count does not move with the machine's load, as times do by a
tenth or more from run to run.
"""
import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("TACKLE_BUILD_DIR", os.path.join(ROOT, "build"))
TACKLE = os.path.join(BUILD, "tackle")
GINAC = os.path.join(BUILD, "bench", "ginac_lsolve")
DEFAULT_SIZES = {"chain": [16, 32, 64, 128, 256], "cascade": [4, 8, 16, 32, 64], "tackle": [4, 16, 64],
                 "carts": [8, 16, 32, 64]}


def run(cmd, timeout, stdin=None):
    """(seconds, completed) of one whole-process run: from starting the process to reaping it,
    with no wrapper program timed along (`/usr/bin/time` took 0.7 to 0.9 ms of its own, a
    quarter of a small problem's time; the peak memory is measured in a run of its own,
    `peak_of`). Input and output go through files, so that the parent does nothing
    while the process runs. A run past the timeout is killed with everything it started (its
    own process group), so that it cannot go on taking a core from the runs after it."""
    with tempfile.TemporaryFile() as fin, tempfile.TemporaryFile() as fout, tempfile.TemporaryFile() as ferr:
        if stdin:
            fin.write(stdin.encode())
            fin.seek(0)
        timed_out = threading.Event()
        started = []

        def kill():
            timed_out.set()
            try:
                os.killpg(started[0].pid, signal.SIGKILL)
            except (IndexError, ProcessLookupError):
                pass

        timer = threading.Timer(timeout, kill)  # started before the clock: its thread is not timed
        timer.start()
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, stdin=fin if stdin else subprocess.DEVNULL, stdout=fout, stderr=ferr,
                                start_new_session=True)
        started.append(proc)
        _, status = os.waitpid(proc.pid, 0)
        seconds = time.perf_counter() - start
        timer.cancel()
        proc.returncode = os.waitstatus_to_exitcode(status)
        if timed_out.is_set():
            return None, None
        fout.seek(0)
        ferr.seek(0)
        p = subprocess.CompletedProcess(cmd, proc.returncode, fout.read().decode(errors="replace"),
                                        ferr.read().decode(errors="replace"))
    if p.returncode != 0:
        sys.stderr.write(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr[-2000:]}\n")
        return None, p
    return seconds, p


def peak_of(cmd, timeout):
    """Peak resident memory (KB) of one run, from /usr/bin/time (the resource usage of a child
    that Python starts counts Python's own memory, which the child had before its exec), or
    None."""
    if not os.path.exists("/usr/bin/time"):
        return None
    try:
        p = subprocess.run(["/usr/bin/time", "-f", "%M"] + cmd, stdin=subprocess.DEVNULL, capture_output=True,
                           text=True, timeout=timeout, start_new_session=True)
    except subprocess.TimeoutExpired:
        return None
    last = p.stderr.strip().splitlines()[-1:] or [""]
    return int(last[0]) if p.returncode == 0 and last[0].isdigit() else None


def best(cmd, timeout, repeat, stdin=None):
    """(best time, completed) of up to `repeat` runs."""
    times, out = [], None
    for _ in range(repeat):
        t, p = run(cmd, timeout, stdin)
        if t is None:
            return None, None
        times.append(t)
        out = p
        if t > 5:  # one run of a slow case is enough
            break
    return min(times), out


NAME = re.compile(r"\b(ddot|dot)\(([A-Za-z_][A-Za-z_0-9]*)\)")


def plain(text):
    """ddot(x_1) -> ddot_x_1: names every peer reads as one symbol."""
    return NAME.sub(lambda m: f"{m.group(1)}_{m.group(2)}", text)


def equations_of(path):
    """The equations tackle solves and the unknowns it solves them for (`derive --format
    json` writes both; the JSON's `unknowns` are the answers asked for, which may be fewer)."""
    out = subprocess.run([TACKLE, "derive", "--format", "json", path], capture_output=True, text=True, check=True)
    d = json.loads(out.stdout)
    eqs = [(plain(e["lhs"]), plain(e["rhs"])) for e in d["equations"] if e.get("kind") != "definition"]
    unknowns = [plain(u) for u in d["solved_for"]]
    return unknowns, eqs


def peer_command(peer, unknowns, eqs, workdir):
    if peer == "ginac":
        f = os.path.join(workdir, "system.txt")
        with open(f, "w") as o:
            o.write(" ".join(unknowns) + "\n")
            for l, r in eqs:
                o.write(f"{l} = {r}\n")
        return [GINAC, f], None
    if peer == "sympy":
        f = os.path.join(workdir, "system.py")
        with open(f, "w") as o:
            o.write("from sympy import sympify, linsolve, Eq, true\n")
            o.write(f"u = [sympify(n) for n in {unknowns!r}]\n")
            o.write(f"e = [Eq(sympify(l), sympify(r)) for l, r in {eqs!r}]\n")
            o.write("e = [q for q in e if q is not true]  # an equation that reads 0 = 0\n")
            o.write("s = linsolve(e, u)\nprint(len(list(s)[0]))\n")
        return [sys.executable, f], None
    if peer == "maxima":
        body = "display2d:false$ s: linsolve([" + ", ".join(f"{l} = {r}" for l, r in eqs) + "], [" + ", ".join(unknowns) + "])$ length(s);"
        return ["maxima", "--very-quiet", "--batch-string=" + body], None
    if peer == "giac":
        f = os.path.join(workdir, "system.giac")
        with open(f, "w") as o:
            o.write("s:=linsolve([" + ", ".join(f"{l}={r}" for l, r in eqs) + "],[" + ", ".join(unknowns) + "]):;\nsize(s);\n")
        return ["giac", f], None
    raise ValueError(peer)


def available(peer):
    return {"ginac": os.path.exists(GINAC), "maxima": shutil.which("maxima") is not None,
            "giac": shutil.which("giac") is not None}.get(peer, True) and (peer != "sympy" or _has_sympy())


def _has_sympy():
    try:
        import sympy  # noqa: F401
        return True
    except ImportError:
        return False


COLLECTED = re.compile(r"Collected : (\d+)")


def instructions(cmd, timeout):
    """Instructions executed by one run (callgrind's count, which does not move with the
    machine's load as times do), or None when valgrind is missing or the run fails."""
    if shutil.which("valgrind") is None:
        return None
    try:
        p = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + cmd,
                           capture_output=True, text=True, timeout=timeout * 20)
    except subprocess.TimeoutExpired:
        return None
    m = COLLECTED.search(p.stderr)
    return int(m.group(1)) if p.returncode == 0 and m else None


def show_count(n):
    if n is None:
        return "-"
    return f"{n / 1e9:.2f} G" if n >= 1e9 else f"{n / 1e6:.1f} M"


def exponent(rows, column, sizes):
    done = [(n, rows[n][column]) for n in sizes if rows[n].get(column)]
    if len(done) < 2:
        return "-"
    (n1, t1), (n2, t2) = done[-2], done[-1]
    return f"{math.log(t2 / t1) / math.log(n2 / n1):.2f}"


def show(t, timeout):
    if t is None:
        return f"> {timeout:g} s"
    if t < 0.1:
        return f"{t * 1000:.1f} ms"
    return f"{t * 1000:.0f} ms" if t < 1 else f"{t:.2f} s"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kinds", default="chain,cascade,tackle,carts")
    ap.add_argument("--sizes", action="append", default=[], help="KIND=N,N,...")
    ap.add_argument("--peers", default="ginac,sympy,maxima,giac")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--files", default="examples/sample-12.8-sign-board.yaml,examples/atwood-machine.yaml",
                    help="descriptions timed as they are, next to the peers on their equations")
    ap.add_argument("--instructions", action="store_true",
                    help="also count the instructions of tackle solve (valgrind's callgrind, one run each)")
    args = ap.parse_args()
    if args.instructions and shutil.which("valgrind") is None:
        sys.stderr.write("--instructions: valgrind is not installed; the column shows '-'\n")
    sizes = dict(DEFAULT_SIZES)
    for s in args.sizes:
        k, v = s.split("=")
        sizes[k] = [int(x) for x in v.split(",")]
    peers = [p for p in args.peers.split(",") if p]
    missing = [p for p in peers if not available(p)]
    if missing:
        sys.stderr.write(f"left out (not installed): {', '.join(missing)}\n")
    peers = [p for p in peers if p not in missing]
    work = tempfile.mkdtemp(prefix="tackle-scale-")
    generate = os.path.join(ROOT, "bench", "generate.py")

    # Start-up of each peer: a one-unknown system.
    startup = {}
    for p in peers:
        cmd, stdin = peer_command(p, ["x"], [("2*x", "1")], work)
        startup[p], _ = best(cmd, args.timeout, args.repeat, stdin)
    t, _ = best([TACKLE, "--version"], args.timeout, args.repeat)
    print(f"start-up: tackle {show(t, args.timeout)}, " + ", ".join(f"{p} {show(startup[p], args.timeout)}" for p in peers))
    print(f"load average at the start: {os.getloadavg()[0]:.1f}")

    for kind in [k for k in args.kinds.split(",") if k]:
        rows = {}
        for n in sizes[kind]:
            path = os.path.join(work, f"{kind}-{n}.yaml")
            with open(path, "w") as o:
                o.write(subprocess.run([sys.executable, generate, kind, str(n)], capture_output=True, text=True, check=True).stdout)
            row = {}
            row["solve"], _ = best([TACKLE, "solve", path], args.timeout, args.repeat)
            row["peak"] = peak_of([TACKLE, "solve", path], args.timeout) if row["solve"] is not None else None
            row["derive"], _ = best([TACKLE, "derive", path], args.timeout, args.repeat)
            if args.instructions:
                row["instructions"] = instructions([TACKLE, "solve", path], args.timeout)
            if peers:
                unknowns, eqs = equations_of(path)
                row["unknowns"] = len(unknowns)
                for p in peers:
                    cmd, stdin = peer_command(p, unknowns, eqs, work)
                    row[p], _ = best(cmd, args.timeout, args.repeat, stdin)
            rows[n] = row
            print(f"  {kind} n={n} done", file=sys.stderr)
        cols = ["solve", "derive"] + peers
        counted = ["instructions"] if args.instructions else []
        print(f"\n{kind}")
        print("| n | unknowns | tackle solve | peak | " + "".join("solve instructions | " for _ in counted) + "tackle derive | "
              + " | ".join(cols[2:]) + " |")
        print("|---" * (5 + len(counted) + len(peers)) + "|")
        for n in sizes[kind]:
            r = rows[n]
            peak = f"{r['peak'] / 1024:.0f} MB" if r.get("peak") else "-"
            print(f"| {n} | {r.get('unknowns', '-')} | {show(r['solve'], args.timeout)} | {peak} | "
                  + "".join(f"{show_count(r.get(c))} | " for c in counted) + f"{show(r['derive'], args.timeout)} | "
                  + " | ".join(show(r.get(p), args.timeout) for p in peers) + " |")
        print("| growth exponent | | " + " | ".join([exponent(rows, "solve", sizes[kind]), ""] + [exponent(rows, c, sizes[kind]) for c in counted]
                                                    + [exponent(rows, "derive", sizes[kind])]
                                                    + [exponent(rows, p, sizes[kind]) for p in peers]) + " |")
        # Each peer against tackle solve, paired within this run (above 1: tackle is faster;
        # a peer past the limit is at least limit / tackle's time).
        if peers:
            print(f"\n{kind}: peer time / tackle solve time, in this run (load average now {os.getloadavg()[0]:.1f})")
            print("| n | " + " | ".join(peers) + " |")
            print("|---" * (1 + len(peers)) + "|")
            for n in sizes[kind]:
                r = rows[n]
                def ratio(p):
                    if r.get("solve") is None:
                        return "-"
                    if r.get(p) is None:
                        return f"> {args.timeout / r['solve']:.1f}"
                    return f"{r[p] / r['solve']:.1f}"
                print(f"| {n} | " + " | ".join(ratio(p) for p in peers) + " |")
    files = [f for f in args.files.split(",") if f]
    if files:
        print("\nsingle problems")
        print("| file | unknowns | tackle solve | " + ("solve instructions | " if args.instructions else "")
              + "tackle derive | " + " | ".join(peers) + " |")
        print("|---" * (4 + (1 if args.instructions else 0) + len(peers)) + "|")
        for f in files:
            path = f if os.path.isabs(f) else os.path.join(ROOT, f)
            solve_t, _ = best([TACKLE, "solve", path], args.timeout, max(args.repeat, 10))
            derive_t, _ = best([TACKLE, "derive", path], args.timeout, max(args.repeat, 10))
            unknowns, eqs = equations_of(path)
            cells = []
            for p in peers:
                cmd, stdin = peer_command(p, unknowns, eqs, work)
                t, _ = best(cmd, args.timeout, max(args.repeat, 10), stdin)
                cells.append(show(t, args.timeout))
            count = f"{show_count(instructions([TACKLE, 'solve', path], args.timeout))} | " if args.instructions else ""
            print(f"| {os.path.basename(f)} | {len(unknowns)} | {show(solve_t, args.timeout)} | {count}{show(derive_t, args.timeout)} | "
                  + " | ".join(cells) + " |")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
