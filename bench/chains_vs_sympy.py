#!/usr/bin/env python3
"""A chain of n bobs pinned end to end (bench/links.py n, issue 42 item 7), by tackle and by
SymPy's KanesMethod in one run: the equations of motion M(q) q'' = F(q, q'), the linearised
matrices about hanging straight down, and the frequencies of small oscillations; then, at one
n, `tackle simulate` of 10 s against SciPy's solve_ivp integrating SymPy's lambdified
right-hand side.

    python3 bench/chains_vs_sympy.py [N ...] [--timeout S] [--simulate N] [--until S]
    (default: 2 4 8 16, 600 s, simulate at n = 8 for 10 s)

tackle: `tackle derive --format json`, whole process (start-up, reading, the balances, the
equations of motion, their linearisation and frequencies, and the rest of the derivation:
the power check, the report). SymPy: a fresh process each n; the times printed are from its
start (the import of sympy included) to KanesMethod's mass matrix and forcing (the equations
of motion), then to M0 = M(0) and K0 = -dF/dq at rest (the linearised matrices), and the
whole process. Agreement: tackle's M and F (parsed from its JSON) and SymPy's, evaluated at a
random state (every entry, relative 1e-9), and the frequencies (sqrt of the eigenvalues of
M0^-1 K0, relative 1e-8).

Simulation: both with Dormand-Prince 5(4) at relative and absolute tolerance 1e-10 (tackle's
default; SciPy's RK45), from theta_1 = 0.5 at rest; SymPy's M and F lambdified with numpy and
q'' = solve(M, F) at each step. The SciPy time is shown as derivation + lambdify +
integration. The two runs are compared at t = 1, 2, ..., 10 s (the chain is chaotic: the
difference grows from the tolerances; tackle's CSV has six significant digits)."""
import csv
import json
import os
import random
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TACKLE = os.environ.get("TACKLE", os.path.join(HERE, "..", "build", "tackle"))
VALUES = {"m": 1.0, "l": 1.0, "g": 9.81}

# The chain in SymPy: link i turns through theta_i counterclockwise from straight down, its
# bob at -l A_i.y from the bob above (the pin O for the first).
MODEL = r'''
import sys, time, json, math
start = time.perf_counter()
import sympy as sp
from sympy.physics import mechanics as me
n = int(sys.argv[1])
m, l, g = sp.symbols("m l g", positive=True)
q = me.dynamicsymbols(f"theta_1:{n + 1}")
u = me.dynamicsymbols(f"u_1:{n + 1}")
N = me.ReferenceFrame("N")
P = me.Point("O"); P.set_vel(N, 0)
particles, loads = [], []
for i in range(n):
    A = N.orientnew(f"A{i}", "Axis", [q[i], N.z])
    A.set_ang_vel(N, u[i] * N.z)
    B = P.locatenew(f"B{i}", -l * A.y)
    B.v2pt_theory(P, N, A)
    particles.append(me.Particle(f"P{i}", B, m))
    loads.append((B, -m * g * N.y))
    P = B
KM = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[q[i].diff() - u[i] for i in range(n)])
KM.kanes_equations(particles, loads)
M = KM.mass_matrix
F = KM.forcing
eom = time.perf_counter() - start
rest = {**{x: 0 for x in q}, **{x: 0 for x in u}}
M0 = M.subs(rest)
K0 = -F.jacobian(q).subs(rest)
C0 = -F.jacobian(u).subs(rest)
linearised = time.perf_counter() - start
'''

CHECK = MODEL + r'''
import mpmath
vals = {m: 1.0, l: 1.0, g: 9.81}
state = json.loads(sys.argv[2])
at = {**{q[i]: state["q"][i] for i in range(n)}, **{u[i]: state["u"][i] for i in range(n)}, **vals}
Mn = [[float(x.evalf(subs=at)) for x in row] for row in M.tolist()]
Fn = [float(x.evalf(subs=at)) for x in F]
ev = mpmath.eig(mpmath.inverse(mpmath.matrix([[float(x.subs(vals)) for x in r] for r in M0.tolist()]))
                * mpmath.matrix([[float(x.subs(vals)) for x in r] for r in K0.tolist()]), left=False, right=False)
freq = sorted(math.sqrt(float(mpmath.re(x))) for x in ev)
print(json.dumps({"eom": eom, "linearised": linearised, "M": Mn, "F": Fn, "frequencies": freq}))
'''

SIMULATE = MODEL + r'''
import numpy as np
from scipy.integrate import solve_ivp
until = float(sys.argv[2])
t0 = time.perf_counter()
vals = {m: 1.0, l: 1.0, g: 9.81}
Mf = sp.lambdify([q, u], M.subs(vals), "numpy")
Ff = sp.lambdify([q, u], F.subs(vals), "numpy")
def rhs(t, y):
    qq, uu = y[:n], y[n:]
    return np.concatenate([uu, np.linalg.solve(np.asarray(Mf(qq, uu), dtype=float), np.asarray(Ff(qq, uu), dtype=float).ravel())])
t1 = time.perf_counter()
y0 = np.zeros(2 * n); y0[0] = 0.5
times = [float(k) for k in range(1, int(until) + 1)]
sol = solve_ivp(rhs, (0.0, until), y0, method="RK45", rtol=1e-10, atol=1e-10, t_eval=times)
t2 = time.perf_counter()
print(json.dumps({"eom": eom, "lambdify": t1 - t0, "integrate": t2 - t1, "steps": int(sol.t.size), "nfev": int(sol.nfev),
                  "ok": bool(sol.success), "t": sol.t.tolist(), "q": sol.y[:n].T.tolist()}))
'''


def chain(n, tmp, until=10.0):
    path = os.path.join(tmp, f"chain{n}.yaml")
    with open(path, "w") as f:
        f.write(subprocess.run([sys.executable, os.path.join(HERE, "links.py"), str(n), "--until", f"{until:g}"],
                               capture_output=True, text=True, check=True).stdout)
    return path


def timed(cmd, timeout):
    start = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, None
    return time.perf_counter() - start, p


def tackle_numbers(motion, n, state):
    """tackle's M and F at the state, its text read by SymPy (outside any timing)."""
    import sympy as sp
    names = {"m": VALUES["m"], "l": VALUES["l"], "g": VALUES["g"]}
    for i in range(n):
        names[f"theta_{i + 1}"] = state["q"][i]
        names[f"dtheta_{i + 1}"] = state["u"][i]

    def value(text):
        text = text.replace("^", "**")
        for i in reversed(range(n)):  # dot(theta_10) before dot(theta_1)
            text = text.replace(f"dot(theta_{i + 1})", f"dtheta_{i + 1}")
        return float(sp.sympify(text, locals={k: sp.Symbol(k) for k in names}).evalf(subs={sp.Symbol(k): v for k, v in names.items()}))

    return [[value(x) for x in row] for row in motion["mass"]], [value(x) for x in motion["forcing"]]


def close(a, b, rel):
    return abs(a - b) <= rel * max(1.0, abs(a), abs(b))


def main():
    argv = sys.argv[1:]
    opt = lambda name, default: type(default)(argv[argv.index(name) + 1]) if name in argv else default
    timeout, sim_n, until = opt("--timeout", 600.0), opt("--simulate", 8), opt("--until", 10.0)
    skip = {i + 1 for i, x in enumerate(argv) if x.startswith("--")}
    sizes = [int(x) for i, x in enumerate(argv) if not x.startswith("--") and i not in skip] or [2, 4, 8, 16]
    rng = random.Random(42)
    print(f"load average before: {os.getloadavg()[0]:.2f} (2 cores); whole process, one run each; "
          f"SymPy capped at {timeout:.0f} s")
    print(f"{'n':>3} {'tackle [s]':>10} {'SymPy to EOM [s]':>17} {'to linearised [s]':>18} {'whole [s]':>10} "
          f"{'ratio (linearised)':>19}  agreement")
    with tempfile.TemporaryDirectory() as tmp:
        check = os.path.join(tmp, "check.py")
        with open(check, "w") as f:
            f.write(CHECK)
        for n in sizes:
            desc = chain(n, tmp)
            state = {"q": [rng.uniform(-1, 1) for _ in range(n)], "u": [rng.uniform(-1, 1) for _ in range(n)]}
            tt, tp = timed([TACKLE, "derive", desc, "--format", "json"], timeout)
            motion = json.loads(tp.stdout)["motion"] if tp is not None and tp.returncode == 0 else None
            st, sp_ = timed([sys.executable, check, str(n), json.dumps(state)], timeout)
            s = json.loads(sp_.stdout) if sp_ is not None and sp_.returncode == 0 else None
            verdict = "-"
            if motion and s:
                Mt, Ft = tackle_numbers(motion, n, state)
                m_ok = all(close(Mt[i][j], s["M"][i][j], 1e-9) for i in range(n) for j in range(n))
                f_ok = all(close(Ft[i], s["F"][i], 1e-9) for i in range(n))
                fr = motion["linearised"]["frequencies"]
                w_ok = len(fr) == n and all(close(a, b, 1e-8) for a, b in zip(fr, s["frequencies"]))
                verdict = (f"M {'agrees' if m_ok else 'DISAGREES'}, F {'agrees' if f_ok else 'DISAGREES'}, "
                           f"frequencies {'agree' if w_ok else 'DISAGREE'} (lowest {fr[0]:.6f} rad/s)")
            elif motion is None:
                verdict = "tackle failed" if tt is not None else "tackle timed out"
            else:
                verdict = "SymPy timed out" if st is None else "SymPy failed: " + sp_.stderr.strip().splitlines()[-1]
            show = lambda t: f"{t:.2f}" if t is not None else f"> {timeout:.0f}"
            ratio = f"{s['linearised'] / tt:.1f}x" if s and tt else (f"> {timeout / tt:.0f}x" if tt and st is None else "-")
            print(f"{n:>3} {show(tt):>10} {show(s['eom'] if s else None):>17} {show(s['linearised'] if s else None):>18} "
                  f"{show(st):>10} {ratio:>19}  {verdict}", flush=True)

        if sim_n:
            desc = chain(sim_n, tmp, until)
            out = os.path.join(tmp, "sim.csv")
            plot = ",".join(f"theta_{i + 1}" for i in range(sim_n))
            samples = int(until) + 1
            tt, tp = timed([TACKLE, "simulate", desc, "--until", f"{until:g}", "--plot", plot, "--samples", str(samples),
                            "--csv", out], timeout)
            sim = os.path.join(tmp, "sim.py")
            with open(sim, "w") as f:
                f.write(SIMULATE)
            st, sp_ = timed([sys.executable, sim, str(sim_n), f"{until:g}"], timeout)
            if tp is None or tp.returncode != 0:
                print(f"tackle simulate failed: {tp.stderr if tp else 'timed out'}")
                return
            with open(out) as f:
                rows = [r for r in csv.reader(f)]
            header, rows = rows[0], [[float(x) for x in r[:-1]] for r in rows[1:]]  # the last column: valid
            print(f"\nsimulate n = {sim_n}, {until:g} s: tackle {tt:.2f} s whole process (derivation and integration)", end="")
            if sp_ is None or sp_.returncode != 0:
                print(f"; SciPy {'timed out' if sp_ is None else 'failed: ' + sp_.stderr.strip()[-300:]}")
                return
            s = json.loads(sp_.stdout)
            print(f"; SymPy + SciPy {st:.2f} s whole process (KanesMethod {s['eom']:.2f} s, lambdify {s['lambdify']:.2f} s, "
                  f"solve_ivp {s['integrate']:.2f} s, {s['nfev']} right-hand sides); ratio {st / tt:.1f}x "
                  f"(integration alone against tackle's whole run: {s['integrate'] / tt:.1f}x)")
            cols = [header.index(f"theta_{i + 1}") for i in range(sim_n)]
            for k, t in enumerate(s["t"]):
                row = next(r for r in rows if abs(r[0] - t) < 1e-9)
                diff = max(abs(row[c] - s["q"][k][i]) for i, c in enumerate(cols))
                print(f"  t = {t:4.1f} s: theta_1 tackle {row[cols[0]]: .9f}, SciPy {s['q'][k][0]: .9f}; "
                      f"largest difference over the {sim_n} angles {diff:.2e} rad")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
