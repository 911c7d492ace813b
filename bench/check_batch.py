#!/usr/bin/env python3
"""Times `tackle check --batch` on N distinct answers, whole process, and verifies every verdict.

The answers are written in the shapes students write (a closed form with its numerator and
denominator scaled by a random whole number, terms reordered, the fraction split), half of
them right and half wrong (a random coefficient changed, a sign flipped, a parameter swapped),
plus numbers with units. The expected verdict of each is decided here, independently of
tackle: the answer and the hand-derived closed form are evaluated in exact rationals
(Python's fractions) at random points; a number is compared with the value to 1 %.

Prints the whole-process time (best of --repeat runs, with the machine's load average before
each), the time per check, and how many verdicts disagree (there must be none).
Usage: bench/check_batch.py [--build DIR] [-n 10000] [--repeat 5] [--seed 1]
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Each problem: its file, its parameters' values (SI), and its unknowns' hand-derived closed
# forms as Python functions of the parameters (from the examples' notes, not from tackle).
PROBLEMS = {
    "sample-12.3-two-mass-pulley": {
        "params": {"F": 130, "m_A": 40, "m_B": 40},
        "unit": {"T": "N", "ddot(x_A)": "m/s^2", "ddot(x_B)": "m/s^2"},
        "reference": {
            "T": lambda p: 2 * p["m_B"] * p["F"] / (9 * p["m_A"] + 4 * p["m_B"]),
            "ddot(x_A)": lambda p: -9 * p["F"] / (9 * p["m_A"] + 4 * p["m_B"]),
            "ddot(x_B)": lambda p: -6 * p["F"] / (9 * p["m_A"] + 4 * p["m_B"]),
        },
    },
    "sample-12.7-suitcase": {
        "params": {"m": 10, "g": Fraction(981, 100), "mu": Fraction(3, 10), "l": Fraction(6, 10), "h": Fraction(4, 10)},
        "unit": {"N_A": "N", "N_B": "N", "a_C": "m/s^2"},
        "reference": {
            "N_A": lambda p: p["m"] * p["g"] * (Fraction(1, 2) - p["mu"] * p["h"] / p["l"]),
            "N_B": lambda p: p["m"] * p["g"] * (Fraction(1, 2) + p["mu"] * p["h"] / p["l"]),
            "a_C": lambda p: -p["mu"] * p["g"],
        },
    },
}


def shapes(problem, unknown, rng):
    """An answer in a student's shape: (text, a Python function of the parameters)."""
    k = rng.randint(2, 9)
    right = rng.random() < 0.5
    c = (lambda: rng.randint(1, 9)) if not right else None

    def coef(exact):
        # The right coefficient, or (for a wrong answer) a random one that may still be right
        # by chance: the verdict is decided by evaluation, not by how the answer was made.
        return exact if right else c()

    if problem == "sample-12.3-two-mass-pulley":
        num = {"T": ("m_B*F", 2), "ddot(x_A)": ("F", -9), "ddot(x_B)": ("F", -6)}[unknown]
        a, b, n = coef(9), coef(4), coef(num[1])
        if not right and rng.random() < 0.3:
            n = -num[1]  # the sign
        form = rng.randint(0, 2)
        if form == 0:
            text = f"{n * k}*{num[0]}/({a * k}*m_A + {b * k}*m_B)"
        elif form == 1:
            text = f"{num[0]}*{n * k}/({b * k}*m_B + m_A*{a * k})"
        else:
            text = f"({n}/{k})*{num[0]}/({a}*m_A/{k} + {b}*m_B/{k})"
        swap = not right and rng.random() < 0.2
        if swap:
            text = text.replace("m_A", "TMP").replace("m_B", "m_A").replace("TMP", "m_B")
        nm = num[0]

        def f(p, a=a, b=b, n=n, swap=swap, nm=nm):
            ma, mb = (p["m_B"], p["m_A"]) if swap else (p["m_A"], p["m_B"])
            top = p["F"] * (mb if nm == "m_B*F" else 1)
            return Fraction(n) * top / (a * ma + b * mb)

        return text, f
    # The suitcase.
    sign = {"N_A": -1, "N_B": 1}.get(unknown)
    if sign is None:  # a_C = -mu g
        n = coef(-1) * k
        text = f"{n}*mu*g/{k}" if rng.random() < 0.5 else f"-g*mu*{-n}/{k}"
        return text, (lambda p, n=n: Fraction(n) * p["mu"] * p["g"] / k)  # -g*mu*(-n)/k is n mu g/k too
    two, s = coef(2), sign if right or rng.random() < 0.7 else -sign
    form = rng.randint(0, 1)
    if form == 0:
        text = f"m*g*({k}*l {'+' if s > 0 else '-'} {two * k}*mu*h)/({2 * k}*l)"

        def f(p, two=two, s=s):
            return p["m"] * p["g"] * (k * p["l"] + s * two * k * p["mu"] * p["h"]) / (2 * k * p["l"])
    else:
        text = f"m*g/2 {'+' if s > 0 else '-'} {two}*m*g*mu*h/(2*l)"

        def f(p, two=two, s=s):
            return p["m"] * p["g"] / 2 + s * two * p["m"] * p["g"] * p["mu"] * p["h"] / (2 * p["l"])
    return text, f


def random_point(params, rng):
    return {k: Fraction(v) * Fraction(rng.randint(500, 2000), 1000) for k, v in params.items()}


def make_batch(n, rng):
    """Lines of (problem, json line, expected verdict)."""
    out = []
    names = list(PROBLEMS)
    for i in range(n):
        problem = names[i % len(names)]
        spec = PROBLEMS[problem]
        unknown = rng.choice(list(spec["reference"]))
        ref = spec["reference"][unknown]
        if rng.random() < 0.2:  # a number with its unit, right or off
            value = float(ref({k: Fraction(v) for k, v in spec["params"].items()}))
            given = value * (1 + rng.choice([0, 0, 0.002, 0.05, -0.3]))
            text = f"{given:.6g} {spec['unit'][unknown]}"
            expected = abs(given - value) <= 0.01 * abs(value)
        else:
            text, f = shapes(problem, unknown, rng)
            points = [random_point(spec["params"], rng) for _ in range(3)]
            expected = all(f(p) == ref(p) for p in points)
        line = json.dumps({"id": f"s{i}", "unknown": unknown, "answer": text})
        out.append((problem, line, "correct" if expected else "incorrect"))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("-n", type=int, default=10000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--no-latex", action="store_true", help="pass --no-latex (no LaTeX echo of each answer)")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    tackle = os.path.join(args.build, "tackle")
    lines = make_batch(args.n, rng)
    total_time, total_checks, wrong = 0.0, 0, 0
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for problem in PROBLEMS:
            mine = [(l, e) for p, l, e in lines if p == problem]
            path = os.path.join(tmp, problem + ".jsonl")
            with open(path, "w") as f:
                f.write("".join(l + "\n" for l, _ in mine))
            cmd = [tackle, "check", os.path.join(ROOT, "examples", problem + ".yaml"), "--batch", path]
            if args.no_latex:
                cmd.append("--no-latex")
            best, loads, output = None, [], None
            for _ in range(args.repeat):
                loads.append(os.getloadavg()[0])
                start = time.perf_counter()
                done = subprocess.run(cmd, stdout=subprocess.PIPE, check=True)
                elapsed = time.perf_counter() - start
                best = elapsed if best is None else min(best, elapsed)
                output = done.stdout
            got = [json.loads(x)["verdict"] for x in output.decode().splitlines()]
            bad = [(l, e, g) for (l, e), g in zip(mine, got) if e != g]
            if len(got) != len(mine):
                bad.append(("(line count)", len(mine), len(got)))
            for b in bad[:5]:
                print("DISAGREES:", b, file=sys.stderr)
            wrong += len(bad)
            right_share = sum(e == "correct" for _, e in mine) / max(1, len(mine))
            rows.append((problem, len(mine), right_share, best, loads))
            total_time += best
            total_checks += len(mine)
    print(f"| problem | answers (right share) | whole process, best of {args.repeat} | per check | load before runs |")
    print("|---|---|---|---|---|")
    for problem, count, share, best, loads in rows:
        print(f"| {problem} | {count} ({share:.0%}) | {best * 1000:.0f} ms | {best / count * 1e6:.1f} us | "
              f"{min(loads):.1f} to {max(loads):.1f} |")
    print(f"\n{total_checks} distinct answers: {total_time * 1000:.0f} ms whole process in all "
          f"({total_time / total_checks * 1e6:.1f} us a check); verdicts that disagree with the "
          f"independent evaluation: {wrong}")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
