#!/usr/bin/env python3
"""Writes a chain of n links pinned end to end (issue 42, item 7):

    python3 bench/links.py N [--kind bobs|rods] [--base fixed|cart] [--until S] > chain.yaml

Link i (i = 1 ... n) turns through theta_i, counterclockwise from straight down. Its upper
end is the lower end of link i - 1 (the first one's is the pin O, or the pin P on a cart of
mass M at x that rolls on a smooth floor). `bobs`: a particle of mass m at the lower end of a
massless rod of length l; `rods`: a uniform rod of mass m and length l (inertia m l^2/12).
Each link's center of mass is written in the angles of the links above it (and x on a cart),
so the pins add no constraint: the chain has n degrees of freedom (n + 1 on a cart).
"""
import argparse


def cm(i, kind, base):
    """Link i's center of mass, as [x, y] in the description's text."""
    x = ["x"] if base == "cart" else []
    y = []
    for k in range(1, i):
        x.append(f"l*sin(theta_{k})")
        y.append(f"l*cos(theta_{k})")
    f = "l/2*" if kind == "rods" else "l*"
    x.append(f"{f}sin(theta_{i})")
    y.append(f"{f}cos(theta_{i})")
    return f'["{" + ".join(x)}", "-{" - ".join(y)}"]' if len(y) == 1 else f'["{" + ".join(x)}", "-({" + ".join(y)})"]'


def description(n, kind="bobs", base="fixed", until=10.0):
    shape = ", shape: {rod: l}" if kind == "rods" else ""
    lower = '"-l/2"' if kind == "rods" else "0"
    out = [f'title: "A chain of {n} {"rods" if kind == "rods" else "bobs"} pinned end to end'
           + (' on a cart"' if base == "cart" else '"'),
           "axes: [x, y]", "parameters:", "  m: {value: 1, unit: kg}", "  l: {value: 1, unit: m}",
           "  g: {value: 9.81, unit: m/s^2}"]
    if base == "cart":
        out.append("  M: {value: 2, unit: kg}")
    out += ["gravity: [0, -g]", "bodies:"]
    if base == "cart":
        out.append("  cart: {mass: M, position: x, center_of_mass: [x, 0]}")
    out += [f"  link_{i}: {{mass: m, angle: theta_{i}, center_of_mass: {cm(i, kind, base)}{shape}}}" for i in range(1, n + 1)]
    out.append("points:")
    out.append("  P: {on: cart}" if base == "cart" else "  P: [0, 0]")
    out += [f"  J_{i}: {{on: link_{i - 1}, offset: [0, {lower}]}}" for i in range(2, n + 1)]
    out.append("connections:")
    if base == "cart":
        out += ["  - {type: roller, body: cart, at: cart, normal: [0, 1]}",
                "  - {type: pin_joint, body: cart, other: link_1, at: P}"]
    else:
        out.append("  - {type: pin, body: link_1, at: P}")
    out += [f"  - {{type: pin_joint, body: link_{i - 1}, other: link_{i}, at: J_{i}}}" for i in range(2, n + 1)]
    start = [f"theta_{i}: {0.5 if i == 1 else 0}, dot(theta_{i}): 0" for i in range(1, n + 1)]
    if base == "cart":
        start = ["x: 0, dot(x): 0"] + start
    out += ["motion:", f"  initial: {{{', '.join(start)}}}", f"  until: {until:g}"]
    return "\n".join(out) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("n", type=int)
    p.add_argument("--kind", choices=["bobs", "rods"], default="bobs")
    p.add_argument("--base", choices=["fixed", "cart"], default="fixed")
    p.add_argument("--until", type=float, default=10.0)
    a = p.parse_args()
    print(description(a.n, a.kind, a.base, a.until), end="")


if __name__ == "__main__":
    main()
