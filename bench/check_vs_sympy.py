#!/usr/bin/env python3
"""Times tackle's answer checks against SymPy and Maxima on the same decisions, in one run.

tackle: build/bench/tackle_bench's check/* benchmarks (Google Benchmark, median of
repetitions). SymPy: parse_expr + equals against the same closed form, per answer, median
of repetitions. Maxima (when installed): parse_string + is(radcan(given - reference) = 0),
timed inside one Maxima process with elapsed_real_time over 5000 checks per answer (its
start-up is not counted). Prints a table and the ratios.
Usage: bench/check_vs_sympy.py [BUILD_DIR]
"""
import json
import statistics
import subprocess
import sys
import time

# Keep equal to the cases in bench/check_bench.cpp.
CASES = [
    ("T_HI", "m*a*l/(2*d)", True),
    ("T_HI", "a*m*sqrt(d^2+b^2+e^2)/d/2", True),
    ("T_HI", "m*a*sqrt(b^2+d^2+e^2)/d", False),
    ("T_HI", "-m*a*l/(2*d)", False),
    ("N_A", "m*g*(1/2 - mu*h/l)", True),
    ("N_A", "m*g*(l - 2*mu*h)/(2*l)", True),
    ("N_A", "m*g*(l - 2*mu*h)/l", False),
    ("N_A", "m*g/2", False),
]
REFERENCE = {"T_HI": "m*a*sqrt(b^2 + d^2 + e^2)/(2*d)", "N_A": "m*g*(1/2 - mu*h/l)"}


def sympy_times(repeats=7, loops=20):
    import sympy
    from sympy.parsing.sympy_parser import parse_expr, standard_transformations, convert_xor

    names = {n: sympy.Symbol(n, positive=True) for n in ["m", "a", "b", "d", "e", "g", "mu", "h", "l"]}
    sign_l = names["l"]
    transformations = standard_transformations + (convert_xor,)
    results = []
    for unknown, answer, expect in CASES:
        local = dict(names)
        if unknown == "T_HI":  # the sign-board's l is the rod's length
            local = {k: v for k, v in names.items() if k != "l"}
            local["l"] = sympy.sqrt(names["b"] ** 2 + names["d"] ** 2 + names["e"] ** 2)
        reference = parse_expr(REFERENCE[unknown], local_dict=local, transformations=transformations)
        per_check = []
        for _ in range(repeats):
            start = time.perf_counter()
            for _ in range(loops):
                given = parse_expr(answer, local_dict=local, transformations=transformations)
                verdict = given.equals(reference)
            per_check.append((time.perf_counter() - start) / loops)
        if bool(verdict) != expect:
            print(f"warning: SymPy decided {verdict} for {answer}", file=sys.stderr)
        results.append(statistics.median(per_check) * 1e6)
    return results


def maxima_times(loops=5000):
    import shutil
    if shutil.which("maxima") is None:
        return None
    program = ["display2d:false$", "load(stringproc)$", "assume(m>0, a>0, b>0, d>0, e>0, g>0, mu>0, h>0, l>0)$",
               "ref(u) := if u = \"T_HI\" then m*a*sqrt(b^2 + d^2 + e^2)/(2*d) else m*g*(1/2 - mu*h/l)$",
               "time1(u, s, n) := block([t0, v, r], r: ref(u), t0: elapsed_real_time(), for i:1 thru n do "
               "(v: parse_string(s), if u = \"T_HI\" then v: subst(l = sqrt(b^2 + d^2 + e^2), v), "
               "v: is(radcan(v - r) = 0)), [v, (elapsed_real_time() - t0)/n])$"]
    for unknown, answer, _ in CASES:
        program.append(f'print("CASE", time1("{unknown}", "{answer}", {loops}))$')
    out = subprocess.run(["maxima", "--very-quiet", "--batch-string=" + "\n".join(program)],
                         capture_output=True, text=True, check=True).stdout
    results = []
    for (unknown, answer, expect), line in zip(CASES, [l for l in out.splitlines() if l.startswith("CASE ")]):
        verdict, seconds = line[len("CASE "):].strip("[] ").split(",")
        if (verdict.strip() == "true") != expect:
            print(f"warning: Maxima decided {verdict.strip()} for {answer}", file=sys.stderr)
        results.append(float(seconds) * 1e6)
    return results if len(results) == len(CASES) else None


def tackle_times(build):
    out = subprocess.run(
        [f"{build}/bench/tackle_bench", "--benchmark_filter=^check", "--benchmark_repetitions=5",
         "--benchmark_report_aggregates_only=true", "--benchmark_format=json", "--benchmark_min_time=0.2"],
        capture_output=True, text=True, check=True).stdout
    medians = {b["run_name"]: b["real_time"] for b in json.loads(out)["benchmarks"] if b.get("aggregate_name") == "median"}
    return ([medians[f"check/{u}/{a}"] for u, a, _ in CASES], [medians[f"check-no-latex/{u}/{a}"] for u, a, _ in CASES],
            medians.get("check/batch"))


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    ours, plain, batch = tackle_times(build)
    theirs = sympy_times()
    maxima = maxima_times() or [float("nan")] * len(CASES)
    print(f"{'answer':40} {'tackle us':>10} {'no LaTeX':>10} {'SymPy us':>10} {'ratio':>8} {'Maxima us':>10} {'ratio':>8}")
    for (unknown, answer, _), t, p, s, x in zip(CASES, ours, plain, theirs, maxima):
        print(f"{unknown + ': ' + answer:40} {t:10.1f} {p:10.1f} {s:10.1f} {s / t:8.0f} {x:10.1f} {x / t:8.1f}")
    mt, mp, ms, mx = (statistics.median(ours), statistics.median(plain), statistics.median(theirs),
                      statistics.median(maxima))
    print(f"{'median per check':40} {mt:10.1f} {mp:10.1f} {ms:10.1f} {ms / mt:8.0f} {mx:10.1f} {mx / mt:8.1f}")
    if batch:
        print(f"batch of {len(CASES)}: {batch / len(CASES):.1f} us per check")


if __name__ == "__main__":
    main()
