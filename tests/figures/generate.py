#!/usr/bin/env python3
"""Deterministic generator of 2-D mechanism descriptions for the legibility measure.

    python3 tests/figures/generate.py OUTDIR [--count N] [--seed S] [--check TACKLE]

Writes OUTDIR/gen-NN-<family>.yaml, N descriptions (default 40: each of the 20 families twice) from a seeded random
generator (default seed 44): the same seed writes the same files. Every form is one the
description language documents (docs/reference.md, docs/cookbook.md, examples/): blocks on
inclines and floors (smooth, rough, with springs and dampers), strings over pulleys to hanging
blocks, stacked blocks with friction between them, pin-joined blocks, and bodies that turn
(pendulums, bars on pins, rolling disks and wheels, a disk spun up by a falling block, a
ladder). With --check, each file is derived by the tackle binary given (`derive FILE`,
serially); a file it refuses is reported and the exit status is 1 (the generator is to be
fixed, never tackle).

Python 3 standard library only.
"""
import argparse
import math
import os
import random
import subprocess
import sys


def num(v, digits=3):
    s = f"{v:.{digits}f}".rstrip("0").rstrip(".")
    return s if s not in ("-0", "") else "0"


class Writer:
    """Builds one description's YAML text (written by hand: PyYAML would read `on:` as true)."""

    def __init__(self, title):
        self.lines = [f'title: "{title}"', "source: tests/figures/generate.py (issue 44's legibility set)",
                      "axes: [x, y]"]

    def add(self, text):
        self.lines.extend(text.rstrip("\n").split("\n"))

    def text(self):
        return "\n".join(self.lines) + "\n"


def params(pairs):
    out = ["parameters:"]
    for name, value, unit in pairs:
        if unit:
            out.append(f"  {name}: {{value: {value}, unit: {unit}}}")
        else:
            out.append(f"  {name}: {{value: {value}}}")
    out.append("  g: {value: 9.81, unit: m/s^2}")
    out.append("gravity: [0, -g]")
    return "\n".join(out)



def contact(body, rough, normal, sliding):
    """A body on a surface: rough (sliding with mu, `sliding` its assumed direction) or smooth."""
    if rough:
        return f"  - {{type: sliding, body: {body}, at: {body}, normal: {normal}, sliding: {sliding}, mu: mu}}"
    return f"  - {{type: roller, body: {body}, at: {body}, normal: {normal}}}"

def mass(rng):
    return rng.choice([1, 1.5, 2, 3, 4, 5, 6, 8, 10])


def pick_names(rng, n):
    sets = [["A", "B", "C"], ["block", "weight", "crate"], ["U", "V", "W"], ["A", "B", "D"],
            ["box", "load", "cart"], ["m1", "m2", "m3"]]
    return rng.choice(sets)[:n]


# ---- families -------------------------------------------------------------------------

def incline_block(rng, i):
    """A block alone on an incline: smooth (roller) or rough (sliding), maybe pushed up it."""
    b = pick_names(rng, 1)[0]
    th = rng.choice([15, 20, 25, 30, 35, 40, 50])
    rough = rng.random() < 0.6
    push = rng.random() < 0.5
    w = Writer(f"A block on a {'rough' if rough else 'smooth'} {th} deg incline")
    p = [("m", mass(rng), "kg"), ("theta", th, "deg")]
    if rough:
        p.append(("mu", rng.choice([0.1, 0.2, 0.3]), None))
    if push:
        p.append(("F", rng.choice([5, 10, 20, 40]), "N"))
    w.add(params(p))
    w.add(f"""bodies:
  {b}: {{mass: m, position: s, center_of_mass: ["s*cos(theta)", "s*sin(theta)"]}}
connections:""")
    w.add(contact(b, rough, '["-sin(theta)", "cos(theta)"]', '["-cos(theta)", "-sin(theta)"]'))
    if push:
        w.add(f'  - {{type: force, on: {b}, at: {b}, force: ["F*cos(theta)", "F*sin(theta)"]}}')
    w.add(f"layout: {{s: {rng.choice([0.5, 1, 1.5, 2])}}}")
    w.add(f"find: [ddot(s), N_{b}]")
    return w.text()


def incline_spring(rng, i):
    """A block on a rough incline held by a spring and a damper to a fixed point up the slope."""
    b = pick_names(rng, 1)[0]
    th = rng.choice([20, 30, 40])
    damper = rng.random() < 0.5
    w = Writer(f"A block on a {th} deg incline on a spring{' and a damper' if damper else ''}")
    p = [("m", mass(rng), "kg"), ("theta", th, "deg"), ("mu", rng.choice([0.1, 0.2]), None),
         ("k", rng.choice([50, 100, 200]), "N/m"), ("l_0", 0.5, "m"), ("D", rng.choice([1.5, 2, 2.5]), "m")]
    if damper:
        p.append(("c", rng.choice([5, 10]), "N*s/m"))
    w.add(params(p))
    w.add(f"""bodies:
  {b}: {{mass: m, position: s, center_of_mass: ["s*cos(theta)", "s*sin(theta)"]}}
points:
  Q: ["D*cos(theta)", "D*sin(theta)"]
connections:
  - {{type: sliding, body: {b}, at: {b}, normal: ["-sin(theta)", "cos(theta)"], sliding: ["-cos(theta)", "-sin(theta)"], mu: mu}}
  - {{type: spring, name: sp, path: [{b}, Q], k: k, rest_length: l_0}}""")
    if damper:
        w.add(f"  - {{type: damper, name: dp, path: [{b}, Q], c: c}}")
    w.add(f"layout: {{s: {rng.choice([0.6, 0.8, 1])}}}")
    w.add("given: [s, dot(s)]")
    w.add(f"find: [ddot(s), N_{b}]")
    return w.text()


def incline_pulley(rng, i):
    """A block on an incline tied over a pulley at its top to a hanging block."""
    a, b = pick_names(rng, 2)
    th = rng.choice([20, 30, 35, 45, 55])
    rough = rng.random() < 0.4
    w = Writer(f"A block on a {th} deg incline over a pulley to a hanging block")
    p = [("m_A", mass(rng), "kg"), ("m_B", mass(rng), "kg"), ("theta", th, "deg"),
         ("L", rng.choice([1.5, 2, 3]), "m")]
    if rough:
        p.append(("mu", rng.choice([0.1, 0.2]), None))
    w.add(params(p))
    w.add(f"""bodies:
  {a}: {{mass: m_A, position: s, center_of_mass: ["s*cos(theta)", "s*sin(theta)"]}}
  {b}: {{mass: m_B, position: y_B, center_of_mass: ["L*cos(theta)", y_B]}}
points:
  P: ["L*cos(theta)", "L*sin(theta)"]
connections:""")
    w.add(contact(a, rough, '["-sin(theta)", "cos(theta)"]', '["cos(theta)", "sin(theta)"]'))
    w.add(f"""  - {{type: pulley, at: P}}
strings:
  - {{name: s, path: [{a}, P, {b}], tension: T}}
layout: {{s: {rng.choice([0.5, 1])}, y_B: {rng.choice([-0.5, 0, 0.3])}}}
find: [ddot(s), T, N_{a}]""")
    return w.text()


def table_pulley(rng, i):
    """A block on a floor (table) tied over a pulley at its edge to a hanging block."""
    a, b = pick_names(rng, 2)
    rough = rng.random() < 0.5
    force = rng.random() < 0.3
    w = Writer("A block on a table over a pulley at its edge to a hanging block")
    p = [("m_A", mass(rng), "kg"), ("m_B", mass(rng), "kg"), ("L", rng.choice([1, 1.5, 2]), "m"),
         ("h", rng.choice([0.2, 0.3]), "m")]
    if rough:
        p.append(("mu", rng.choice([0.1, 0.2]), None))
    if force:
        p.append(("F", rng.choice([5, 10]), "N"))
    w.add(params(p))
    w.add(f"""bodies:
  {a}: {{mass: m_A, position: x_A, center_of_mass: [x_A, h]}}
  {b}: {{mass: m_B, position: y_B, center_of_mass: [L, y_B]}}
points:
  P: [L, h]
connections:""")
    w.add(contact(a, rough, "[0, 1]", "[1, 0]"))
    w.add("  - {type: pulley, at: P}")
    if force:
        w.add(f"  - {{type: force, on: {a}, at: {a}, force: [\"-F\", 0]}}")
    w.add(f"""strings:
  - {{name: s, path: [{a}, P, {b}], tension: T}}
layout: {{x_A: {rng.choice([0, 0.3])}, y_B: {rng.choice([-1, -0.5])}}}
find: [ddot(x_A), T, N_{a}]""")
    return w.text()


def atwood(rng, i):
    """Two blocks hanging from a string over a fixed pulley (in the plane)."""
    a, b = pick_names(rng, 2)
    w = Writer("An Atwood machine in the plane")
    p = [("m_A", mass(rng), "kg"), ("m_B", mass(rng), "kg"), ("d", rng.choice([0.3, 0.5, 0.8]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  {a}: {{mass: m_A, position: y_A, center_of_mass: ["-d", y_A]}}
  {b}: {{mass: m_B, position: y_B, center_of_mass: [d, y_B]}}
points:
  L: ["-d", 0]
  R: [d, 0]
connections:
  - {{type: pulley, at: L}}
  - {{type: pulley, at: R}}
strings:
  - {{name: s, path: [{a}, L, R, {b}], tension: T}}
layout: {{y_A: {rng.choice([-1, -1.5])}, y_B: {rng.choice([-2, -1.2])}}}
find: [ddot(y_A), T]""")
    return w.text()


def floor_train(rng, i):
    """Two or three blocks on a floor tied by strings, pulled by a force."""
    n = rng.choice([2, 3])
    names = pick_names(rng, n)
    rough = rng.random() < 0.5
    w = Writer(f"{n} blocks on a {'rough' if rough else 'smooth'} floor tied by strings, pulled")
    p = [(f"m_{k + 1}", mass(rng), "kg") for k in range(n)] + [("F", rng.choice([10, 20, 30]), "N"),
                                                                ("h", 0.2, "m")]
    if rough:
        p.append(("mu", rng.choice([0.1, 0.2]), None))
    w.add(params(p))
    w.add("bodies:")
    for k, b in enumerate(names):
        w.add(f"  {b}: {{mass: m_{k + 1}, position: x_{k + 1}, center_of_mass: [x_{k + 1}, h]}}")
    w.add("connections:")
    for b in names:
        w.add(contact(b, rough, "[0, 1]", "[1, 0]"))
    w.add(f"  - {{type: force, on: {names[-1]}, at: {names[-1]}, force: [F, 0]}}")
    w.add("strings:")
    for k in range(n - 1):
        w.add(f"  - {{name: s_{k + 1}, path: [{names[k]}, {names[k + 1]}], tension: T_{k + 1}}}")
    lay = ", ".join(f"x_{k + 1}: {num(1.2 * k)}" for k in range(n))
    w.add(f"layout: {{{lay}}}")
    w.add("find: [ddot(x_1), " + ", ".join(f"T_{k + 1}" for k in range(n - 1)) + "]")
    return w.text()


def stacked(rng, i):
    """Two stacked blocks with friction between them on a smooth floor, one of them pulled."""
    a, b = pick_names(rng, 2)
    on_lower = rng.random() < 0.6
    w = Writer(f"Two stacked blocks, the {'lower' if on_lower else 'upper'} one pulled")
    p = [("m_A", mass(rng), "kg"), ("m_B", mass(rng), "kg"), ("F", rng.choice([5, 10, 20, 40]), "N"),
         ("mu_s", 0.3, None), ("mu_k", 0.25, None), ("h", rng.choice([0.2, 0.3]), "m")]
    w.add(params(p))
    target = b if on_lower else a
    w.add(f"""bodies:
  {a}: {{mass: m_A, position: x_A, center_of_mass: [x_A, 3*h/2]}}
  {b}: {{mass: m_B, position: x_B, center_of_mass: [x_B, h/2]}}
loads:
  - {{on: {target}, at: {target}, force: [F, 0]}}
connections:
  - {{type: friction_between, body: {a}, other: {b}, at: {a}, normal: [0, 1], tangent: [1, 0], mu_s: mu_s, mu_k: mu_k}}
  - {{type: roller, body: {b}, at: {b}, normal: [0, 1]}}
layout: {{x_A: 0, x_B: 0}}
find: [ddot(x_A), ddot(x_B), N_{a}, N_{b}]""")
    return w.text()


def pinned_blocks(rng, i):
    """Two blocks on a floor joined by a pin, one pushed."""
    a, b = pick_names(rng, 2)
    w = Writer("Two blocks on a floor joined by a pin")
    p = [("m_A", mass(rng), "kg"), ("m_B", mass(rng), "kg"), ("F", rng.choice([4, 8, 12]), "N"),
         ("b", rng.choice([0.6, 1]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  {a}: {{mass: m_A, position: x_A, center_of_mass: [x_A, 0]}}
  {b}: {{mass: m_B, position: x_B, center_of_mass: [x_B, 0]}}
points:
  H: {{on: {a}, offset: ["-b", 0]}}
connections:
  - {{type: roller, body: {a}, at: {a}, normal: [0, 1]}}
  - {{type: roller, body: {b}, at: {b}, normal: [0, 1]}}
  - {{type: pin_joint, body: {a}, other: {b}, at: H}}
  - {{type: force, on: {a}, at: {a}, force: [F, 0]}}
layout: {{x_A: {num(2 * 1)}, x_B: 0}}
find: [ddot(x_A), H_x, H_y]""")
    return w.text()


def pendulum(rng, i):
    """A bob on a string from a fixed point, at an angle, moving."""
    bob = rng.choice(["bob", "B", "ball"])
    th = rng.choice([10, 20, 30, 45, 60, -30, -15])
    w = Writer(f"A pendulum at {th} deg")
    p = [("m", mass(rng), "kg"), ("l", rng.choice([0.5, 1, 1.5]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  {bob}: {{mass: m, angle: theta, center_of_mass: ["l*sin(theta)", "-l*cos(theta)"]}}
points:
  O: [0, 0]
strings:
  - {{name: s, path: [O, {bob}], tension: T}}
given: {{theta: {{value: {th}, unit: deg}}, dot(theta): {{value: {rng.choice([0, 1, 2])}, unit: rad/s}}}}
find: [ddot(theta), T]""")
    return w.text()


def bar_on_pin(rng, i):
    """A bar pinned at one end, at an angle (released)."""
    bar = rng.choice(["bar", "rod", "beam"])
    th = rng.choice([0, 15, 30, -20, -45])
    w = Writer(f"A bar pinned at its end, at {th} deg")
    p = [("m", mass(rng), "kg"), ("L", rng.choice([0.8, 1, 1.5]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  {bar}: {{mass: m, angle: theta, center_of_mass: ["L/2*cos(theta)", "L/2*sin(theta)"], shape: {{rod: L}}}}
points:
  O: [0, 0]
connections:
  - {{type: pin, body: {bar}, at: O}}
given: {{theta: {{value: {th}, unit: deg}}, dot(theta): {rng.choice([0, 1])}}}
find: [ddot(theta), O_x, O_y]""")
    return w.text()


def physical_pendulum(rng, i):
    """A disk pinned at a point of its rim (a physical pendulum)."""
    w = Writer("A disk pinned at its rim")
    th = rng.choice([0, 20, 40])
    p = [("m", mass(rng), "kg"), ("R", rng.choice([0.2, 0.3, 0.5]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  disk: {{mass: m, angle: theta, center_of_mass: ["R*sin(theta)", "-R*cos(theta)"], shape: {{disk: R}}}}
points:
  O: [0, 0]
connections:
  - {{type: pin, body: disk, at: O}}
given: {{theta: {{value: {th}, unit: deg}}, dot(theta): {{value: {rng.choice([0, 2, 3])}, unit: rad/s}}}}
find: [ddot(theta), O_x, O_y]""")
    return w.text()


def rolling_incline(rng, i):
    """A disk or a ring rolling down an incline without slipping."""
    shape = rng.choice(["disk", "ring"])
    th = rng.choice([15, 20, 30, 40])
    w = Writer(f"A {shape} rolling down a {th} deg incline")
    p = [("m", mass(rng), "kg"), ("r", rng.choice([0.1, 0.2, 0.3]), "m"), ("theta", th, "deg"),
         ("mu", rng.choice([0.3, 0.5]), None)]
    w.add(params(p))
    w.add(f"""bodies:
  wheel:
    mass: m
    position: s
    angle: phi
    center_of_mass: ["s*cos(theta) + r*sin(theta)", "-s*sin(theta) + r*cos(theta)"]
    shape: {{{shape}: r}}
points:
  C: {{on: wheel, offset: ["-r*sin(theta)", "-r*cos(theta)"], turns: false}}
connections:
  - {{type: rolling, body: wheel, at: C, normal: ["sin(theta)", "cos(theta)"], tangent: ["-cos(theta)", "sin(theta)"], mu: mu}}
find: [ddot(s), F_C, N_C]""")
    return w.text()


def rolling_floor(rng, i):
    """A wheel on a floor driven by a couple, or pulled at its center by a force."""
    couple = rng.random() < 0.5
    w = Writer(f"A wheel rolling on a floor, {'driven by a couple' if couple else 'pulled at its center'}")
    p = [("m", mass(rng), "kg"), ("R", rng.choice([0.2, 0.25, 0.4]), "m"), ("mu", 0.5, None)]
    p.append(("M_0", rng.choice([2, 6]), "N*m") if couple else ("P", rng.choice([5, 10, 20]), "N"))
    w.add(params(p))
    w.add(f"""bodies:
  wheel: {{mass: m, position: x, angle: phi, center_of_mass: [x, R], shape: {{disk: R}}}}
points:
  C: {{on: wheel, offset: [0, "-R"], turns: false}}
connections:""")
    if couple:
        w.add("  - {type: couple, on: wheel, moment: \"-M_0\"}")
    else:
        w.add("  - {type: force, on: wheel, at: wheel, force: [P, 0]}")
    w.add("""  - {type: rolling, body: wheel, at: C, normal: [0, 1], tangent: [1, 0], mu: mu}
find: [ddot(x), F_C, N_C]""")
    return w.text()


def disk_and_block(rng, i):
    """A pinned disk spun up by a block hanging from a string wound on it."""
    b = rng.choice(["block", "A", "weight"])
    w = Writer("A pinned disk spun up by a falling block")
    p = [("m", mass(rng), "kg"), ("M", mass(rng), "kg"), ("R", rng.choice([0.2, 0.3, 0.5]), "m")]
    w.add(params(p))
    side = rng.choice(["R", "-R"])
    w.add(f"""bodies:
  disk: {{mass: M, angle: phi, center_of_mass: [0, 0], shape: {{disk: R}}}}
  {b}: {{mass: m, position: y, center_of_mass: ["{side}", y]}}
points:
  O: [0, 0]
  E: {{on: disk, offset: ["{side}", 0], turns: false}}
strings:
  - {{name: s, path: [{b}, E], tension: T}}
connections:
  - {{type: pin, body: disk, at: O}}
layout: {{y: {rng.choice([-1, -1.5, -0.6])}}}
find: [ddot(y), T, O_x, O_y]""")
    return w.text()


def massive_atwood(rng, i):
    """Two blocks over a pulley with mass (two strings, one per side)."""
    w = Writer("An Atwood machine over a pulley with mass")
    p = [("m_1", mass(rng), "kg"), ("m_2", mass(rng), "kg"), ("M", mass(rng), "kg"),
         ("R", rng.choice([0.1, 0.2, 0.3]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  P: {{mass: M, angle: phi, center_of_mass: [0, 0], shape: {{disk: R}}}}
  block_1: {{mass: m_1, position: y_1, center_of_mass: ["-R", y_1]}}
  block_2: {{mass: m_2, position: y_2, center_of_mass: [R, y_2]}}
points:
  O: [0, 0]
  L: {{on: P, offset: ["-R", 0], turns: false}}
  E: {{on: P, offset: [R, 0], turns: false}}
strings:
  - {{name: s_1, path: [block_1, L], tension: T_1}}
  - {{name: s_2, path: [block_2, E], tension: T_2}}
connections:
  - {{type: pin, body: P, at: O}}
layout: {{y_1: {rng.choice([-1, -1.5])}, y_2: {rng.choice([-1, -2])}}}
find: [ddot(y_1), T_1, T_2]""")
    return w.text()


def table_massive_pulley(rng, i):
    """A block on a table over a pulley with mass at its edge to a hanging block."""
    w = Writer("A block on a table over a pulley with mass to a hanging block")
    p = [("m_1", mass(rng), "kg"), ("m_2", mass(rng), "kg"), ("M", mass(rng), "kg"),
         ("R", rng.choice([0.1, 0.2]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  block_1: {{mass: m_1, position: x, center_of_mass: [x, R]}}
  block_2: {{mass: m_2, position: y_2, center_of_mass: [R, y_2]}}
  P: {{mass: M, angle: phi, center_of_mass: [0, 0], shape: {{disk: R}}}}
points:
  O: [0, 0]
  T: {{on: P, offset: [0, R], turns: false}}
  E: {{on: P, offset: [R, 0], turns: false}}
strings:
  - {{name: s_1, path: [block_1, T], tension: T_1}}
  - {{name: s_2, path: [block_2, E], tension: T_2}}
connections:
  - {{type: pin, body: P, at: O}}
  - {{type: roller, body: block_1, at: block_1, normal: [0, 1]}}
layout: {{x: {rng.choice([-1, -1.5])}, y_2: {rng.choice([-1, -0.7])}}}
find: [ddot(x), T_1, T_2]""")
    return w.text()


def ladder(rng, i):
    """A ladder against a smooth wall on a smooth floor, released."""
    th = rng.choice([50, 60, 70])
    w = Writer(f"A ladder at {th} deg on a smooth floor and wall")
    p = [("m", mass(rng), "kg"), ("L", rng.choice([2, 3, 4]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  ladder: {{mass: m, angle: theta, center_of_mass: ["-L*cos(theta)/2", "L*sin(theta)/2"], shape: {{rod: L}}}}
points:
  A: {{on: ladder, offset: ["-L/2", 0]}}
  B: {{on: ladder, offset: ["L/2", 0]}}
connections:
  - {{type: roller, body: ladder, at: A, normal: [0, 1]}}
  - {{type: roller, body: ladder, at: B, normal: [-1, 0]}}
given: {{theta: {{value: {th}, unit: deg}}, dot(theta): 0}}
find: [ddot(theta), N_A, N_B]""")
    return w.text()


def pendulum_on_cart(rng, i):
    """A pendulum hanging from a cart on a floor."""
    w = Writer("A pendulum hanging from a cart")
    p = [("M", mass(rng), "kg"), ("m", mass(rng), "kg"), ("l", rng.choice([0.5, 1]), "m")]
    w.add(params(p))
    w.add(f"""bodies:
  cart: {{mass: M, position: x, center_of_mass: [x, 0], draw: {{shape: rectangle, size: ["0.8*l", "0.4*l"]}}}}
  bob: {{mass: m, angle: theta, center_of_mass: ["x + l*sin(theta)", "-l*cos(theta)"]}}
points:
  P: {{on: cart}}
connections:
  - {{type: roller, body: cart, at: cart, normal: [0, 1]}}
  - {{type: pin_joint, body: cart, other: bob, at: P}}
given: {{theta: {rng.choice([0.3, 0.5, -0.4])}, dot(theta): {{value: 1, unit: rad/s}}, dot(x): 0}}
find: [ddot(x), ddot(theta), P_x, P_y]""")
    return w.text()


def double_pendulum(rng, i):
    """Two bobs in a chain: a double pendulum."""
    w = Writer("A double pendulum")
    p = [("m", mass(rng), "kg"), ("l", rng.choice([0.5, 1]), "m")]
    w.add(params(p))
    t1, t2 = rng.choice([0.3, 0.5, -0.4]), rng.choice([-0.3, 0.2, 0.6])
    w.add(f"""bodies:
  bob_1: {{mass: m, angle: theta_1, center_of_mass: ["l*sin(theta_1)", "-l*cos(theta_1)"]}}
  bob_2: {{mass: m, angle: theta_2, center_of_mass: ["l*sin(theta_1) + l*sin(theta_2)", "-l*cos(theta_1) - l*cos(theta_2)"]}}
points:
  P: [0, 0]
  J: {{on: bob_1, offset: [0, 0]}}
connections:
  - {{type: pin, body: bob_1, at: P}}
  - {{type: pin_joint, body: bob_1, other: bob_2, at: J}}
given: {{theta_1: {t1}, theta_2: {t2}, dot(theta_1): 0, dot(theta_2): 0}}
find: [ddot(theta_1), ddot(theta_2)]""")
    return w.text()


def suitcase(rng, i):
    """A box on two feet sliding on a floor (sample 12.7's suitcase), with friction at both."""
    w = Writer("A box on two feet sliding on a rough floor")
    p = [("m", mass(rng), "kg"), ("mu", rng.choice([0.2, 0.3]), None), ("l", rng.choice([0.6, 1]), "m"),
         ("h", rng.choice([0.3, 0.4, 0.6]), "m")]
    w.add(params(p))
    w.add("""points:
  A: [0, 0]
  B: [l, 0]
bodies:
  box: {mass: m, center_of_mass: ["l/2", h], acceleration: {along: [1, 0], name: a_C}}
connections:
  - {type: sliding, body: box, at: A, normal: [0, 1], sliding: [1, 0], mu: mu}
  - {type: sliding, body: box, at: B, normal: [0, 1], sliding: [1, 0], mu: mu}
find: [a_C, N_A, N_B]""")
    return w.text()


FAMILIES = [incline_block, incline_pulley, table_pulley, stacked, pendulum, bar_on_pin, rolling_incline,
            disk_and_block, floor_train, atwood, rolling_floor, massive_atwood, incline_spring,
            physical_pendulum, pinned_blocks, table_massive_pulley, ladder, pendulum_on_cart,
            double_pendulum, suitcase]


def generate(count, seed):
    rng = random.Random(seed)
    out = []
    for i in range(count):
        family = FAMILIES[i % len(FAMILIES)]
        out.append((f"gen-{i + 1:02d}-{family.__name__.replace('_', '-')}.yaml", family(rng, i)))
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--count", type=int, default=40)
    ap.add_argument("--seed", type=int, default=44)
    ap.add_argument("--check", metavar="TACKLE", help="derive each file with this binary; report refusals")
    a = ap.parse_args(argv)
    os.makedirs(a.outdir, exist_ok=True)
    failed = 0
    for name, text in generate(a.count, a.seed):
        path = os.path.join(a.outdir, name)
        with open(path, "w") as f:
            f.write(text)
        if a.check:
            r = subprocess.run([a.check, "derive", path], capture_output=True, text=True, timeout=300)
            if r.returncode != 0:
                failed += 1
                print(f"{path}: tackle derive exit {r.returncode}: {r.stderr.strip()[:400]}", file=sys.stderr)
    print(f"wrote {a.count} descriptions to {a.outdir}" + (f"; {failed} refused" if a.check else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
