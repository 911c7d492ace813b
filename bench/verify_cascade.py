#!/usr/bin/env python3
"""Checks tackle's closed forms for a compound Atwood cascade at an exact random point:

  python3 bench/verify_cascade.py [N ...]        (default: 8 16 32 64)

Not a timing. For each N it writes the cascade (bench/generate.py cascade N), runs
`tackle derive --format json` and draws a random point of exact rationals for g and the
masses. At that point:

1. the equations tackle writes are solved again here, in exact rationals (Python's
   fractions, Gauss-Jordan elimination with no symbol in sight), and every closed form
   tackle prints (each unknown's, and each validity condition's simplified side) must give
   exactly the value found;
2. the tensions and accelerations must equal the ones derived by hand, from the physics
   rather than from tackle's equations: a massless pulley P_(k+1) gives T_k = 2 T_(k+1);
   with w_k = 2^(N-k) (w_(N+1) = 1) the strings' lengths give sum w_k ddot(y_k) = 0, and
   LMB of each block, m_k ddot(y_k) = w_k T_N - m_k g, gives
   T_N = g sum w_k / sum (w_k^2 / m_k), T_k = 2^(N-k) T_N, ddot(y_k) = w_k T_N / m_k - g.

Prints one line per N; exits 1 at the first value that differs.
"""
import json
import os
import random
import re
import subprocess
import sys
from fractions import Fraction

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("TACKLE_BUILD_DIR", os.path.join(ROOT, "build"))
TACKLE = os.path.join(BUILD, "tackle")

NAME = re.compile(r"\b(ddot|dot)\(([A-Za-z_][A-Za-z_0-9]*)\)")
NUMBER = re.compile(r"(?<![A-Za-z_0-9.])(\d+(?:\.\d+)?)(?![A-Za-z_0-9.])")


def python_expression(text):
    """tackle's plain text as a Python expression over Fractions: ddot(x) -> ddot_x, ^ -> **,
    every number a Fraction (so that 1/2 is not a float)."""
    text = NAME.sub(lambda m: f"{m.group(1)}_{m.group(2)}", text)
    text = NUMBER.sub(lambda m: f"F('{m.group(1)}')", text)
    return text.replace("^", "**")


def value(text, point):
    return eval(python_expression(text), {"F": Fraction, "__builtins__": {}}, point)


def solve_exactly(equations, unknowns, point):
    """The unknowns' values at `point` from the equations (linear in the unknowns): each
    residual lhs - rhs evaluated at the unknowns all 0 and at each one 1 gives its row."""
    rows = []
    for e in equations:
        residual = f"({e['lhs']}) - ({e['rhs']})"
        code = compile(python_expression(residual), "<equation>", "eval")
        at = dict(point)
        for u in unknowns:
            at[u] = Fraction(0)
        r0 = eval(code, {"F": Fraction, "__builtins__": {}}, at)
        row = []
        for u in unknowns:
            at[u] = Fraction(1)
            row.append(eval(code, {"F": Fraction, "__builtins__": {}}, at) - r0)
            at[u] = Fraction(0)
        rows.append(row + [-r0])
    n = len(unknowns)
    pivot_row = 0
    where = [None] * n
    for c in range(n):
        p = next((r for r in range(pivot_row, len(rows)) if rows[r][c] != 0), None)
        if p is None:
            raise SystemExit(f"the equations leave {unknowns[c]} undetermined at the point")
        rows[pivot_row], rows[p] = rows[p], rows[pivot_row]
        pr = rows[pivot_row]
        inv = 1 / pr[c]
        rows[pivot_row] = pr = [x * inv for x in pr]
        for r in range(len(rows)):
            if r != pivot_row and rows[r][c] != 0:
                f = rows[r][c]
                rows[r] = [x - f * y for x, y in zip(rows[r], pr)]
        where[c] = pivot_row
        pivot_row += 1
    for r in range(pivot_row, len(rows)):
        if rows[r][n] != 0:
            raise SystemExit("the equations are inconsistent at the point")
    return {u: rows[where[c]][n] for c, u in enumerate(unknowns)}


def by_hand(n, point):
    w = [2 ** (n - k) for k in range(1, n + 1)] + [1]
    m = [point[f"m_{k}"] for k in range(1, n + 2)]
    g = point["g"]
    t_n = g * sum(w) / sum(Fraction(wk * wk) / mk for wk, mk in zip(w, m))
    out = {f"T_{k}": 2 ** (n - k) * t_n for k in range(1, n + 1)}
    out.update({f"ddot_y_{k}": w[k - 1] * t_n / m[k - 1] - g for k in range(1, n + 2)})
    return out


def check(n, rng):
    path = f"/tmp/tackle-verify-cascade-{os.getpid()}-{n}.yaml"
    with open(path, "w") as o:
        o.write(subprocess.run([sys.executable, os.path.join(ROOT, "bench", "generate.py"), "cascade", str(n)],
                               capture_output=True, text=True, check=True).stdout)
    try:
        d = json.loads(subprocess.run([TACKLE, "derive", "--format", "json", path], capture_output=True, text=True,
                                      check=True).stdout)
    finally:
        os.remove(path)
    point = {"g": Fraction(rng.randint(1, 10 ** 6), rng.randint(1, 10 ** 6))}
    for k in range(1, n + 2):
        point[f"m_{k}"] = Fraction(rng.randint(1, 10 ** 6), rng.randint(1, 10 ** 6))
    unknowns = [NAME.sub(lambda m: f"{m.group(1)}_{m.group(2)}", u) for u in d["solved_for"]]
    equations = [e for e in d["equations"] if e.get("kind") != "definition"]
    solved = solve_exactly(equations, unknowns, point)
    hand = by_hand(n, point)
    checked = 0
    for u in d["unknowns"]:
        name = NAME.sub(lambda m: f"{m.group(1)}_{m.group(2)}", u["name"])
        got = value(u["closed_form"], point)
        if got != solved[name]:
            raise SystemExit(f"cascade {n}: {u['name']} = {u['closed_form'][:200]}... is {got}, the equations give {solved[name]}")
        if name in hand and got != hand[name]:
            raise SystemExit(f"cascade {n}: {u['name']} is {got}, by hand {hand[name]}")
        checked += 1
    for c in d["conditions"]:
        # "T_k >= 0" simplified to "<closed form> >= 0": both sides at the point.
        lhs, op, rhs = re.match(r"(.*) (>=|<=|>|<|=) (.*)$", c["simplified"]).groups()
        ilhs, iop, irhs = re.match(r"(.*) (>=|<=|>|<|=) (.*)$", c["inequality"]).groups()
        if value(lhs, point) - value(rhs, point) != value(ilhs, {**point, **solved}) - value(irhs, {**point, **solved}):
            raise SystemExit(f"cascade {n}: condition {c['inequality']} simplified to {c['simplified'][:200]}... differs")
        checked += 1
    missing = [k for k in hand if k not in solved]
    if missing:
        raise SystemExit(f"cascade {n}: tackle did not solve for {missing}")
    print(f"cascade {n}: {checked} closed forms (unknowns and conditions) exact at a random rational point; "
          f"equations solved again in Python: equal; the hand-derived tensions and accelerations: equal")


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [8, 16, 32, 64]
    rng = random.Random(20261127)
    for n in sizes:
        check(n, rng)


if __name__ == "__main__":
    main()
