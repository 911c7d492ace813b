#!/usr/bin/env python3
"""A chain of n pendulums coupled by springs (bench/generate.py pendulums n), derived by tackle
and by SymPy's KanesMethod in one run: the equations of motion, linearised about hanging
straight down, and the frequencies of small oscillations, checked against the closed form
lambda_j^2 = g/l + (4 k a^2/(m l^2)) sin^2(j pi/(2 n)).

    python3 bench/pendulums_vs_sympy.py [N ...] [--timeout S]   (default: 8 16 32 64, 600 s)

Whole process each (start-up included), best of one run per size; the machine's load is
printed with the table. tackle: `tackle derive --format json` (its motion stage linearises);
SymPy: KanesMethod's mass matrix and forcing, the forcing's Jacobian at rest (the linearised
equations; that time is also shown alone), then M^-1 K and its eigenvalues with mpmath
(numpy is not installed)."""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TACKLE = os.environ.get("TACKLE", os.path.join(HERE, "..", "build", "tackle"))
VALUES = {"m": 1.0, "l": 1.0, "a": 0.5, "d": 0.4, "k": 10.0, "g": 9.81}

SYMPY_SCRIPT = r'''
import sys, math
import time
start = time.perf_counter()
import sympy as sp
from sympy.physics import mechanics as me
import mpmath
n = int(sys.argv[1])
m, l, a, d, k, g = sp.symbols("m l a d k g", positive=True)
q = me.dynamicsymbols(f"theta1:{n + 1}")
u = me.dynamicsymbols(f"u1:{n + 1}")
N = me.ReferenceFrame("N")
O = me.Point("O"); O.set_vel(N, 0)
frames, bobs, springs_at = [], [], []
for i in range(n):
    A = N.orientnew(f"A{i}", "Axis", [q[i], N.z])
    A.set_ang_vel(N, u[i] * N.z)
    pin = O.locatenew(f"O{i}", i * d * N.x); pin.set_vel(N, 0)
    bob = pin.locatenew(f"B{i}", -l * A.y); bob.v2pt_theory(pin, N, A)
    kp = pin.locatenew(f"K{i}", -a * A.y); kp.v2pt_theory(pin, N, A)
    frames.append(A); bobs.append(bob); springs_at.append(kp)
particles = [me.Particle(f"P{i}", bobs[i], m) for i in range(n)]
loads = [(bobs[i], -m * g * N.y) for i in range(n)]
for i in range(n - 1):
    r = springs_at[i + 1].pos_from(springs_at[i])
    L = sp.sqrt(r.dot(r))
    f = k * (L - d) * r / L          # pulls K_i towards K_(i+1)
    loads.append((springs_at[i], f))
    loads.append((springs_at[i + 1], -f))
kd = [q[i].diff() - u[i] for i in range(n)]
KM = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
KM.kanes_equations(particles, loads)
M = KM.mass_matrix
F = KM.forcing
rest = {**{qi: 0 for qi in q}, **{ui: 0 for ui in u}}
K = -F.jacobian(q).subs(rest)
derived = time.perf_counter() - start
vals = {m: 1.0, l: 1.0, a: 0.5, d: 0.4, k: 10.0, g: 9.81}
Mn = mpmath.matrix([[float(x) for x in row] for row in M.subs(rest).subs(vals).tolist()])
Kn = mpmath.matrix([[float(x) for x in row] for row in K.subs(vals).tolist()])
ev = mpmath.eig(mpmath.inverse(Mn) * Kn, left=False, right=False)
print(" ".join(repr(math.sqrt(float(mpmath.re(x)))) for x in sorted(ev, key=lambda z: float(mpmath.re(z)))))
print(f"{derived:.3f}", file=sys.stderr)
'''


def expected(n):
    v = VALUES
    return sorted(math.sqrt(v["g"] / v["l"] + 4 * v["k"] * v["a"] ** 2 / (v["m"] * v["l"] ** 2) * math.sin(j * math.pi / (2 * n)) ** 2)
                  for j in range(n))


def find(o, key):
    if isinstance(o, dict):
        if key in o and isinstance(o[key], list) and o[key] and isinstance(o[key][0], float):
            return o[key]
        for v in o.values():
            r = find(v, key)
            if r is not None:
                return r
    if isinstance(o, list):
        for v in o:
            r = find(v, key)
            if r is not None:
                return r
    return None


def timed(cmd, timeout):
    start = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, None
    return time.perf_counter() - start, p


def agree(got, want):
    return got is not None and len(got) == len(want) and all(abs(x - y) <= 1e-8 * y for x, y in zip(got, want))


def main():
    args = [x for x in sys.argv[1:] if not x.startswith("--")]
    timeout = 600.0
    if "--timeout" in sys.argv:
        timeout = float(sys.argv[sys.argv.index("--timeout") + 1])
        args = [x for x in args if x != sys.argv[sys.argv.index("--timeout") + 1]]
    sizes = [int(x) for x in args] or [8, 16, 32, 64]
    print(f"load average before: {os.getloadavg()[0]:.2f} (2 cores); whole process, one run each")
    print(f"{'n':>4} {'tackle [s]':>11} {'SymPy KanesMethod [s]':>22} {'(to linearised)':>16} {'ratio':>8}  frequencies")
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            desc = os.path.join(tmp, f"p{n}.yaml")
            with open(desc, "w") as f:
                f.write(subprocess.run([sys.executable, os.path.join(HERE, "generate.py"), "pendulums", str(n)],
                                       capture_output=True, text=True, check=True).stdout)
            want = expected(n)
            tt, tp = timed([TACKLE, "derive", desc, "--format", "json"], timeout)
            tackle_ok = tp is not None and tp.returncode == 0 and agree(find(json.loads(tp.stdout), "frequencies"), want)
            script = os.path.join(tmp, "kane.py")
            with open(script, "w") as f:
                f.write(SYMPY_SCRIPT)
            st, sp_ = timed([sys.executable, script, str(n)], timeout)
            sympy_ok = sp_ is not None and sp_.returncode == 0 and agree([float(x) for x in sp_.stdout.split()], want)
            linearised = sp_.stderr.strip().splitlines()[-1] if sp_ is not None and sp_.returncode == 0 else "-"
            show = lambda t, ok: (f"{t:.2f}" if t is not None else f"> {timeout:.0f}") + ("" if ok or t is None else " (wrong)")
            ratio = f"{st / tt:.1f}x" if tt and st else "-"
            verdict = "tackle " + ("agrees" if tackle_ok else "DISAGREES") + ", SymPy " + (
                "agrees" if sympy_ok else ("timed out" if st is None else "DISAGREES"))
            print(f"{n:>4} {show(tt, tackle_ok):>11} {show(st, sympy_ok):>22} {linearised:>16} {ratio:>8}  {verdict} with the closed form",
                  flush=True)
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
