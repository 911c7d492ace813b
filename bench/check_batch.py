#!/usr/bin/env python3
"""Times `tackle check --batch` on N distinct answers, whole process, and verifies every verdict.

The answers are written in the shapes students write (a closed form with its numerator and
denominator scaled by a random whole number, terms reordered, the fraction split), half of
them right and half wrong (a random coefficient changed, a sign flipped, a parameter swapped),
plus numbers with units. The expected verdict of each is decided here, independently of
tackle: the answer and the hand-derived closed form are evaluated in exact rationals
(Python's fractions) at random points; a number is compared with the value to 1 %.

Half of the lines come from a problem with an angle (the incline: sin, cos, tan, sin(theta +
pi/2) for cos, sin for cos as a mistake), its parameters' points drawn with the angle as t =
tan(theta/2), so that the sine and cosine are exact rationals here too.

With --equations (or --both), the same for N distinct equations a student writes
(`{"equation": ...}` lines): random whole-number combinations of the hand-derived balances and
constraints, their terms spread over both sides, half of them with one coefficient changed,
a term left out or a mass swapped. The expected verdict is decided here too: an equation is
correct when its coefficients (of the unknowns, and the rest) are a combination of the hand
equations', by exact rank in Fractions at two random points.

Prints the whole-process time (best of --repeat runs, with the machine's load average before
each), the time per check, and how many verdicts disagree (there must be none).
With --each, every problem gets N lines of its own (a batch of N per example).
With --module, the same lines are also checked through the Python module (a Problem loaded once,
one call a line) and its time a check printed beside the batch's; with --instructions too, the
instructions a check of both under callgrind (valgrind), which a loaded machine does not move.
Usage: bench/check_batch.py [--build DIR] [-n 10000] [--repeat 5] [--seed 1] [--each] [--jobs N] [--module [--instructions]] [--equations | --both]
"""
import argparse
import math
import json
import os
import random
import re
import resource
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
    # A problem with an angle (its notes): theta = 30 deg; tackle's own points and these are
    # drawn apart. Here theta is t = tan(theta/2) (sin = 2t/(1 + t^2), cos = (1 - t^2)/(1 + t^2):
    # exact rationals), near tan(15 deg).
    "incline-and-hanging-block": {
        "params": {"m_A": 4, "m_B": 6, "g": Fraction(981, 100), "t_theta": Fraction(267949192431, 10**12)},
        "unit": {"ddot(s)": "m/s^2", "T": "N", "N_A": "N"},
        "reference": {
            "ddot(s)": lambda p: p["g"] * (p["m_B"] - p["m_A"] * p["sin(theta)"]) / (p["m_A"] + p["m_B"]),
            "T": lambda p: p["m_A"] * p["m_B"] * p["g"] * (1 + p["sin(theta)"]) / (p["m_A"] + p["m_B"]),
            "N_A": lambda p: p["m_A"] * p["g"] * p["cos(theta)"],
        },
    },
    # Sample 12.8 (its notes): T_HI = m a l/(2 d), l = sqrt(b^2 + d^2 + e^2), a root. Its points
    # are drawn from whole-number quadruples b^2 + d^2 + e^2 = l^2 (scaled together), so that the
    # root is an exact rational here too.
    "sample-12.8-sign-board": {
        "params": {"m": 20, "a": Fraction(6, 10), "g": 10, "b": Fraction(3, 2), "c": Fraction(3, 2), "d": 3, "e": Fraction(1, 2)},
        "unit": {"T_HI": "N"},
        "reference": {"T_HI": lambda p: p["m"] * p["a"] * p["l"] / (2 * p["d"])},
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
    if problem == "incline-and-hanging-block":
        return incline_shape(unknown, rng, right, coef, k)
    if problem == "sample-12.8-sign-board":
        return board_shape(rng, right, coef, k)
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


def root(x):
    """The square root of a Fraction when it is rational, else None (an irrational value, never
    equal to a rational reference)."""
    x = Fraction(x)
    if x < 0:
        return None
    n, d = math.isqrt(x.numerator), math.isqrt(x.denominator)
    return Fraction(n, d) if n * n == x.numerator and d * d == x.denominator else None


def board_shape(rng, right, coef, k):
    """Sample 12.8's T_HI as students write it: the root written out or as l, scaled, split;
    wrong: a coefficient, a term of the root left out, c for d, an extra term."""
    n, two = coef(1), coef(2)
    wrong = None if right else rng.choice(["coefficient", "root", "c", "extra"])
    inside = ["b^2", "d^2", "e^2"]
    rng.shuffle(inside)
    kept = inside[:2] if wrong == "root" else inside
    below = "c" if wrong == "c" else "d"
    extra = rng.randint(1, 5) if wrong == "extra" else 0
    form = rng.randint(0, 3)
    rt = f"sqrt({' + '.join(kept)})"
    if form == 0:
        text = f"{n * k}*m*a*{rt}/({two * k}*{below})"
    elif form == 1 and wrong != "root":
        text = f"{n}*a*m*l/{below}/{two}"
    elif form == 2:
        text = f"{n}*m*a*sqrt(({' + '.join(kept)})/({two * two * k * k}*{below}^2))*{k}"
    else:
        text = f"a*m*{rt}*{n}/({below}*{two})"
    if extra:
        text += f" + {extra}*m*g/{k}"

    def f(p, n=n, two=two, kept=kept, below=below, extra=extra):
        r = root(sum(p[x[0]] ** 2 for x in kept))
        if r is None:
            return None
        return n * p["m"] * p["a"] * r / (two * p[below]) + Fraction(extra, k) * p["m"] * p["g"]

    return text, f


# Whole-number quadruples b^2 + d^2 + e^2 = l^2.
QUADRUPLES = [(1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9), (4, 4, 7, 9), (2, 6, 9, 11), (6, 6, 7, 11),
              (2, 10, 11, 15), (1, 12, 12, 17), (3, 4, 12, 13), (2, 5, 14, 15), (8, 9, 12, 17)]


def incline_shape(unknown, rng, right, coef, k):
    """The incline's answers as students write them: scaled, reordered, sin(theta) written as
    cos(theta - pi/2) or tan(theta)*cos(theta); wrong: a coefficient, a sign, sin for cos."""
    trig = {"sin": ["sin(theta)", "cos(theta - pi/2)", "tan(theta)*cos(theta)"], "cos": ["cos(theta)", "sin(theta + pi/2)"]}
    swap = not right and rng.random() < 0.3
    def fn(name):  # the function written, and the one meant (a swap writes the other)
        other = {"sin": "cos", "cos": "sin"}[name]
        return rng.choice(trig[other if swap else name]), (other if swap else name)
    if unknown == "N_A":
        (text_c, c), n = fn("cos"), coef(1)
        return f"{n * k}*m_A*g*{text_c}/{k}", (lambda p, n=n, c=c: n * p["m_A"] * p["g"] * p[f"{c}(theta)"])
    (text_s, sn), a, b = fn("sin"), coef(1), coef(1)
    sign = 1 if right or rng.random() < 0.6 else -1
    if unknown == "ddot(s)":
        text = f"g*({k}*m_B {'-' if sign > 0 else '+'} {a * k}*m_A*{text_s})/({k}*m_A + {b * k}*m_B)"
        return text, (lambda p, a=a, b=b, sign=sign, sn=sn:
                      p["g"] * (p["m_B"] - sign * a * p["m_A"] * p[f"{sn}(theta)"]) / (p["m_A"] + b * p["m_B"]))
    text = f"{k}*m_A*m_B*g*(1 {'+' if sign > 0 else '-'} {a}*{text_s})/({k}*m_A + {b * k}*m_B)"
    return text, (lambda p, a=a, b=b, sign=sign, sn=sn:
                  p["m_A"] * p["m_B"] * p["g"] * (1 + sign * a * p[f"{sn}(theta)"]) / (p["m_A"] + b * p["m_B"]))


# Each problem's hand-derived equations (the examples' notes), each as {unknown: coefficient,
# "1": the rest} with the coefficients as (text, Python function of the parameters); every
# equation reads sum = 0.
def _c(text, f):
    return (text, f)


EQUATIONS = {
    "sample-12.3-two-mass-pulley": {
        "unknowns": ["T", "ddot(x_A)", "ddot(x_B)"],
        "equations": [
            # LMB A: 2 T - F - m_A a_A = 0; LMB B: -3 T - m_B a_B = 0; length: 3 a_B - 2 a_A = 0
            {"T": _c("2", lambda p: 2), "ddot(x_A)": _c("(-m_A)", lambda p: -p["m_A"]), "1": _c("(-F)", lambda p: -p["F"])},
            {"T": _c("(-3)", lambda p: -3), "ddot(x_B)": _c("(-m_B)", lambda p: -p["m_B"])},
            {"ddot(x_A)": _c("(-2)", lambda p: -2), "ddot(x_B)": _c("3", lambda p: 3)},
        ],
        "swap": ("m_A", "m_B"),
        "classes": [[0, 1], [2]],  # forces; accelerations (only equations of one dimension combine)
    },
    "incline-and-hanging-block": {
        "unknowns": ["T", "N_A", "ddot(s)", "ddot(y_B)"],
        "equations": [
            # Along the incline: T - m_A g sin(theta) - m_A ddot(s) = 0; across it: N_A - m_A g
            # cos(theta) = 0 (tackle balances A along x and y: these are combinations of
            # those with sin and cos for coefficients); B: T - m_B g - m_B ddot(y_B) = 0; the
            # string: ddot(s) + ddot(y_B) = 0.
            {"T": _c("1", lambda p: 1), "ddot(s)": _c("(-m_A)", lambda p: -p["m_A"]),
             "1": _c("(-m_A*g*sin(theta))", lambda p: -p["m_A"] * p["g"] * p["sin(theta)"])},
            {"N_A": _c("1", lambda p: 1), "1": _c("(-m_A*g*cos(theta))", lambda p: -p["m_A"] * p["g"] * p["cos(theta)"])},
            {"T": _c("1", lambda p: 1), "ddot(y_B)": _c("(-m_B)", lambda p: -p["m_B"]), "1": _c("(-m_B*g)", lambda p: -p["m_B"] * p["g"])},
            {"ddot(s)": _c("1", lambda p: 1), "ddot(y_B)": _c("1", lambda p: 1)},
        ],
        "swap": ("sin(theta)", "cos(theta)"),
        "classes": [[0, 1, 2], [3]],  # forces; accelerations
    },
    "sample-12.7-suitcase": {
        "unknowns": ["N_A", "N_B", "a_C"],
        "equations": [
            # x: -mu (N_A + N_B) - m a_C = 0; y: N_A + N_B - m g = 0;
            # about G: (N_B - N_A) l/2 - mu h (N_A + N_B) = 0
            {"N_A": _c("(-mu)", lambda p: -p["mu"]), "N_B": _c("(-mu)", lambda p: -p["mu"]), "a_C": _c("(-m)", lambda p: -p["m"])},
            {"N_A": _c("1", lambda p: 1), "N_B": _c("1", lambda p: 1), "1": _c("(-m*g)", lambda p: -p["m"] * p["g"])},
            {"N_A": _c("(-l/2 - mu*h)", lambda p: -p["l"] / 2 - p["mu"] * p["h"]),
             "N_B": _c("(l/2 - mu*h)", lambda p: p["l"] / 2 - p["mu"] * p["h"])},
        ],
        "swap": ("l", "h"),
        "classes": [[0, 1], [2]],  # forces; moments
    },
}


def _rank(rows):
    """The rank of a list of rows of Fractions (Gaussian elimination, exact)."""
    m = [list(r) for r in rows]
    rank, cols = 0, len(m[0]) if m else 0
    for c in range(cols):
        pivot = next((i for i in range(rank, len(m)) if m[i][c] != 0), None)
        if pivot is None:
            continue
        m[rank], m[pivot] = m[pivot], m[rank]
        for i in range(len(m)):
            if i != rank and m[i][c] != 0:
                f = m[i][c] / m[rank][c]
                m[i] = [a - f * b for a, b in zip(m[i], m[rank])]
        rank += 1
    return rank


def equation_line(problem, rng):
    """A student's equation: (text, expected verdict), the verdict decided by exact rank."""
    spec, params = EQUATIONS[problem], PROBLEMS[problem]["params"]
    keys = spec["unknowns"] + ["1"]
    members = rng.choice(spec["classes"])
    while True:
        cs = [rng.choice([-3, -2, -1, 0, 1, 2, 3]) if i in members else 0 for i in range(len(spec["equations"]))]
        if any(cs):
            break
    # The combination's terms: for each key, the sum of c_i times equation i's coefficient.
    terms = []  # (key, text, function)
    for key in keys:
        parts = [(c, eq[key]) for c, eq in zip(cs, spec["equations"]) if c and key in eq]
        if not parts:
            continue
        text = " + ".join(f"{c}*{t}" for c, (t, _) in parts)
        terms.append([key, f"({text})", lambda p, parts=parts: sum(c * f(p) for c, (_, f) in parts)])
    wrong = rng.random() < 0.5
    if wrong and terms:
        i = rng.randrange(len(terms))
        how = rng.choice(["coefficient", "drop", "swap"])
        key, text, f = terms[i]
        if how == "coefficient":
            k = rng.choice([2, 3, -1])
            terms[i] = [key, f"{k}*{text}", lambda p, f=f, k=k: k * f(p)]
        elif how == "drop" and len(terms) > 1:
            del terms[i]
        else:
            a, b = spec["swap"]
            swapped = text.replace(a, "@").replace(b, a).replace("@", b)
            terms[i] = [key, swapped, lambda p, f=f, a=a, b=b: f({**p, a: p[b], b: p[a]})]
    # A problem with an angle: the whole equation sometimes multiplied by cos(theta) (the same
    # equation, written as a student clearing a denominator would).
    if "t_theta" in params and rng.random() < 0.3:
        terms = [[key, f"cos(theta)*{text}", lambda p, f=f: p["cos(theta)"] * f(p)] for key, text, f in terms]
    # Spread over both sides, in a random order.
    rng.shuffle(terms)
    # A term moved to the right side is written turned: sum(left) = -(the rest).
    left, right = [], []
    for i, (key, text, _) in enumerate(terms):
        word = text if key == "1" else f"{text}*{key}"
        if i > 0 and rng.random() < 0.4:
            right.append(f"-{word}")
        else:
            left.append(word)
    text = " + ".join(left) + " = " + (" + ".join(right) if right else "0")
    expected = "correct"
    vectors = []
    for _ in range(2):
        p = random_point(params, rng)
        rows = [[Fraction(eq[k][1](p)) if k in eq else Fraction(0) for k in keys] for eq in spec["equations"]]
        mine = [Fraction(0)] * len(keys)
        for t in terms:  # what is written: left minus right, and a right term is written turned
            mine[keys.index(t[0])] += Fraction(t[2](p))
        vectors.append(mine)
        if all(x == 0 for x in mine) or _rank(rows + [mine]) != _rank(rows):
            expected = "incorrect"
    return text, expected


def random_point(params, rng):
    p = {k: Fraction(v) * Fraction(rng.randint(500, 2000), 1000) for k, v in params.items()}
    if {"b", "d", "e"} <= p.keys():  # sample 12.8: its root exact
        q = list(rng.choice(QUADRUPLES))
        sides = q[:3]
        rng.shuffle(sides)
        scale = Fraction(rng.randint(1, 40), 10)
        p["b"], p["d"], p["e"], p["l"] = (x * scale for x in sides + [q[3]])
    return with_angles(p)


def with_angles(p):
    """An angle given as t_NAME = tan(NAME/2): its sine and cosine, exact; sample 12.8's l (a
    float at the description's own values, where only numbers with units use it)."""
    if {"b", "d", "e"} <= p.keys() and "l" not in p:
        p["l"] = root(p["b"] ** 2 + p["d"] ** 2 + p["e"] ** 2) or (p["b"] ** 2 + p["d"] ** 2 + p["e"] ** 2) ** 0.5
    for k in [k for k in p if k.startswith("t_")]:
        t, name = p[k], k[2:]
        p[f"sin({name})"] = 2 * t / (1 + t * t)
        p[f"cos({name})"] = (1 - t * t) / (1 + t * t)
    return p


def make_batch(n, rng, equations=False):
    """Lines of (problem, json line, expected verdict)."""
    out = []
    names = list(EQUATIONS) if equations else list(PROBLEMS)
    # Half of the lines from the problems with an angle, half from the others.
    angled = [k for k in names if any(x.startswith("t_") for x in PROBLEMS[k]["params"])]
    plain = [k for k in names if k not in angled]
    for i in range(n):
        if equations:
            group = angled if i % 2 == 0 or not plain else plain
            problem = group[(i // 2) % len(group)]
            text, expected = equation_line(problem, rng)
            out.append((problem, json.dumps({"id": f"e{i}", "equation": text}), expected))
            continue
        problem = names[i % len(names)]
        spec = PROBLEMS[problem]
        unknown = rng.choice(list(spec["reference"]))
        ref = spec["reference"][unknown]
        if rng.random() < 0.2:  # a number with its unit, right or off
            value = float(ref(with_angles({k: Fraction(v) for k, v in spec["params"].items()})))
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
    ap.add_argument("--jobs", type=int, default=1, help="pass --jobs N (grading processes side by side; 1: one)")
    ap.add_argument("--each", action="store_true",
                    help="n lines for each problem (one batch of n per example) rather than n in all")
    ap.add_argument("--module", action="store_true",
                    help="also check the same lines through the Python module (Problem.check / check_equation, one call a "
                         "line, the problem loaded once), in process, and print its time a check beside the batch's")
    ap.add_argument("--instructions", action="store_true",
                    help="with --module: count instructions a check under callgrind too (each problem's first 500 lines; "
                         "the batch's and the module's, each less the same run with no check)")
    ap.add_argument("--write", metavar="DIR", help="write each problem's batch (PROBLEM.jsonl) to DIR and stop (to profile)")
    kind = ap.add_mutually_exclusive_group()
    kind.add_argument("--equations", action="store_true", help="distinct equations instead of answers")
    kind.add_argument("--both", action="store_true", help="answers, then equations, in one run")
    args = ap.parse_args()
    wrong = 0
    for equations in ([False, True] if args.both else [args.equations]):
        wrong += run(args, equations)
    return 1 if wrong else 0


def run(args, equations):
    rng = random.Random(args.seed)
    tackle = os.path.join(args.build, "tackle")
    count = args.n * (len(EQUATIONS if equations else PROBLEMS) if args.each else 1)
    lines = make_batch(count, rng, equations)
    what = "equations" if equations else "answers"
    if args.write:
        os.makedirs(args.write, exist_ok=True)
        for problem in {p for p, _, _ in lines}:
            with open(os.path.join(args.write, f"{problem}.{what}.jsonl"), "w") as f:
                f.write("".join(l + "\n" for p, l, _ in lines if p == problem))
        return 0
    total_time, total_checks, wrong = 0.0, 0, 0
    rows, module_rows, instruction_rows = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for problem in PROBLEMS:
            mine = [(l, e) for p, l, e in lines if p == problem]
            if not mine:
                continue
            path = os.path.join(tmp, problem + ".jsonl")
            with open(path, "w") as f:
                f.write("".join(l + "\n" for l, _ in mine))
            cmd = [tackle, "check", os.path.join(ROOT, "examples", problem + ".yaml"), "--batch", path]
            if args.no_latex:
                cmd.append("--no-latex")
            if args.jobs != 1:
                cmd += ["--jobs", str(args.jobs)]
            best, best_cpu, loads, output = None, None, [], None
            for _ in range(args.repeat):
                loads.append(os.getloadavg()[0])
                start, cpu = time.perf_counter(), children_cpu()
                done = subprocess.run(cmd, stdout=subprocess.PIPE, check=True)
                elapsed, cpu = time.perf_counter() - start, children_cpu() - cpu
                best = elapsed if best is None else min(best, elapsed)
                best_cpu = cpu if best_cpu is None else min(best_cpu, cpu)
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
            if args.module:
                module_rows.append((problem, len(mine), best, best_cpu) + module_time(args, problem, mine))
                wrong += module_rows[-1][-1]
                if args.instructions:
                    instruction_rows.append((problem,) + instructions_a_check(args, problem, mine[:500], tmp))
            total_time += best
            total_checks += len(mine)
    print(f"\n| problem | {what} (right share) | whole process, best of {args.repeat} | per check | load before runs |")
    print("|---|---|---|---|---|")
    for problem, count, share, best, loads in rows:
        print(f"| {problem} | {count} ({share:.0%}) | {best * 1000:.0f} ms | {best / count * 1e6:.1f} us | "
              f"{min(loads):.1f} to {max(loads):.1f} |")
    if module_rows:
        print(f"\n| problem | {what} | batch, whole process, a check: wall (CPU) | module, in process, a check: wall (CPU) "
              f"| module / batch: wall (CPU) |")
        print("|---|---|---|---|---|")
        for problem, count, batch, batch_cpu, module, module_cpu, first, _ in module_rows:
            print(f"| {problem} | {count} | {batch / count * 1e6:.1f} us ({batch_cpu / count * 1e6:.1f} us) | "
                  f"{module / count * 1e6:.1f} us ({module_cpu / count * 1e6:.1f} us; first call {first * 1e6:.0f} us) | "
                  f"{module / batch:.2f} ({module_cpu / batch_cpu:.2f}) |")
        print(f"(best of {args.repeat} each; CPU: user and system time, the batch's of its process, the module's of this one)")
    if instruction_rows:
        print(f"\n| problem | {what} | batch: instructions a check | module: instructions a check | module / batch |")
        print("|---|---|---|---|---|")
        for problem, count, batch, module in instruction_rows:
            print(f"| {problem} | {count} | {batch / 1000:.0f}k | {module / 1000:.0f}k | {module / batch:.2f} |")
        print("(callgrind; each run less the same run with no check: the batch with an empty file, the module with its "
              "lines read and not checked)")
    print(f"\n{total_checks} distinct {what}: {total_time * 1000:.0f} ms whole process in all "
          f"({total_time / total_checks * 1e6:.1f} us a check); verdicts that disagree with the "
          f"independent evaluation: {wrong}")
    return wrong


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


MODULE_RUN = """
import json, sys
sys.path.insert(0, sys.argv[1])
import tackle
p = tackle.Problem(sys.argv[2])
lines = [json.loads(l) for l in open(sys.argv[3])]
if sys.argv[4] == "check":
    for d in lines:
        p.check_equation(d["equation"]) if "equation" in d else p.check(d["unknown"], d["answer"])
"""


def callgrind(cmd):
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + cmd,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, check=True).stderr
    return int(re.search(r"Collected : (\d+)", out).group(1))


def instructions_a_check(args, problem, lines, tmp):
    """(lines, the batch's instructions a check, the module's), each less its run with no check."""
    path = os.path.join(tmp, problem + ".head.jsonl")
    with open(path, "w") as f:
        f.write("".join(l + "\n" for l, _ in lines))
    empty = os.path.join(tmp, "empty.jsonl")
    open(empty, "w").close()
    yaml = os.path.join(ROOT, "examples", problem + ".yaml")
    batch = [os.path.join(args.build, "tackle"), "check", yaml, "--batch"]
    module = [sys.executable, "-c", MODULE_RUN, os.path.join(args.build, "python"), yaml, path]
    n = len(lines)
    return (n, (callgrind(batch + [path]) - callgrind(batch + [empty])) / n,
            (callgrind(module + ["check"]) - callgrind(module + ["read"])) / n)


def module_time(args, problem, lines):
    """The lines checked through the Python module, one call each, the problem loaded once
    (outside the time): (best of args.repeat in seconds, wall and CPU, the first call's,
    verdicts wrong)."""
    sys.path.insert(0, os.path.join(args.build, "python"))
    import tackle  # noqa: E402
    calls = []
    for line, expected in lines:
        d = json.loads(line)
        calls.append(((d["equation"],) if "equation" in d else (d["unknown"], d["answer"]), expected))
    best, best_cpu, first_call, wrong = None, None, None, 0
    for _ in range(args.repeat):
        p = tackle.Problem(os.path.join(ROOT, "examples", problem + ".yaml"))
        check = p.check_equation if "equation" in json.loads(lines[0][0]) else p.check
        got = []
        start, cpu = time.perf_counter(), time.process_time()
        for i, (call, _) in enumerate(calls):
            got.append(check(*call)["verdict"])
            if i == 0 and first_call is None:
                first_call = time.perf_counter() - start
        elapsed, cpu = time.perf_counter() - start, time.process_time() - cpu
        best = elapsed if best is None else min(best, elapsed)
        best_cpu = cpu if best_cpu is None else min(best_cpu, cpu)
        bad = [(c, e, g) for (c, e), g in zip(calls, got) if e != g]
        for b in bad[:5]:
            print("MODULE DISAGREES:", b, file=sys.stderr)
        wrong = max(wrong, len(bad))
    return best, best_cpu, first_call, wrong


if __name__ == "__main__":
    sys.exit(main())
