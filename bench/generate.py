#!/usr/bin/env python3
"""Writes the scale benchmarks' descriptions: python3 bench/generate.py KIND N > file.yaml

KIND is one of
  chain    n blocks on a smooth floor joined by n - 1 strings, pulled at the front by F
           (every acceleration is F/(m_1 + ... + m_n); the k-th string's tension is
           (m_1 + ... + m_k) F/(m_1 + ... + m_n))
  cascade  a compound Atwood machine of n levels: pulley P_1 hangs from the ceiling; the
           string over P_k carries block B_k on one side and pulley P_(k+1) on the other;
           the last string carries blocks B_n and B_(n+1)
  tackle   a block-and-tackle with n strands: a load L hangs from a movable pulley block,
           the string runs n times between it and the fixed block C, pulled down with F
  carts    a 3-D train of n carts on a smooth floor joined by ball joints, the front one
           pulled along x; every cart's LMB in x, y, z and AMB about its center of mass
           (6n equations, 5n - 3 unknowns, the rest redundant)
  pendulums  n simple pendulums (bobs of mass m on rods of length l) hanging a distance d
           apart, neighbours joined by springs (k, rest length d) at a distance a below the
           pins; the equations of motion (nonlinear: the springs turn), linearised about
           hanging straight down, and the frequencies of small oscillations:
           lambda_j^2 = g/l + (4 k a^2/(m l^2)) sin^2(j pi/(2 n)), j = 0 ... n - 1
"""
import sys


def chain(n):
    out = [f'title: "Benchmark: a chain of {n} blocks pulled at the front"', "axes: [x]", "parameters:",
           "  F: {value: 10, unit: N}"]
    out += [f"  m_{i}: {{value: {1 + i % 3}, unit: kg}}" for i in range(1, n + 1)]
    out.append("bodies:")
    out += [f"  b{i}: {{mass: m_{i}, position: x_{i}}}" for i in range(1, n + 1)]
    out += ["loads:", f"  - {{on: b{n}, force: F}}", "strings:"]
    out += [f"  - {{name: s{i}, path: [b{i}, b{i + 1}], tension: T_{i}}}" for i in range(1, n)]
    out.append("layout: {" + ", ".join(f"x_{i}: {2 * i}" for i in range(1, n + 1)) + "}")
    out.append("find: [" + ", ".join([f"ddot(x_{i})" for i in range(1, n + 1)] + [f"T_{i}" for i in range(1, n)]) + "]")
    return "\n".join(out) + "\n"


def cascade(n):
    out = [f'title: "Benchmark: a compound Atwood machine of {n} levels"', "axes: [y]", "parameters:",
           "  g: {value: 9.81, unit: m/s^2}"]
    out += [f"  m_{i}: {{value: {1 + i % 4}, unit: kg}}" for i in range(1, n + 2)]
    out += ["gravity: -g", "bodies:"]
    out += [f"  P{k}: {{mass: 0, position: y_P{k}}}" for k in range(1, n + 1)]
    out += [f"  B{i}: {{mass: m_{i}, position: y_{i}}}" for i in range(1, n + 2)]
    out.append("strings:")
    for k in range(1, n):
        out.append(f"  - {{name: s{k}, path: [B{k}, P{k}, P{k + 1}], tension: T_{k}}}")
    out.append(f"  - {{name: s{n}, path: [B{n}, P{n}, B{n + 1}], tension: T_{n}}}")
    out += ["connections:", "  - {type: fixed, body: P1}"]
    out += [f"  - {{type: pulley, at: P{k}}}" for k in range(1, n + 1)]
    layout = [f"y_P{k}: {-2 * (k - 1)}" for k in range(1, n + 1)]
    layout += [f"y_{i}: {-2 * (i - 1) - 1}" for i in range(1, n + 1)] + [f"y_{n + 1}: {-2 * (n - 1) - 1.5}"]
    out.append("layout: {" + ", ".join(layout) + "}")
    out.append("find: [" + ", ".join([f"ddot(y_{i})" for i in range(1, n + 2)] + [f"T_{k}" for k in range(1, n + 1)]) + "]")
    return "\n".join(out) + "\n"


def block_and_tackle(n):
    # n strands between the movable block M and the fixed block C, then one down to the hand H.
    path = []
    at_m = n % 2 == 1  # start at M when n is odd, so that the n-th strand ends at C
    for _ in range(n + 1):
        path.append("M" if at_m else "C")
        at_m = not at_m
    path.append("H")
    out = [f'title: "Benchmark: a block-and-tackle of {n} strands"', "axes: [y]", "parameters:",
           "  g: {value: 9.81, unit: m/s^2}", "  m: {value: 100, unit: kg}", "  m_H: {value: 1, unit: kg}",
           "  F: {value: 300, unit: N}", "gravity: -g", "bodies:", "  L: {mass: m, position: y_M}",
           "  H: {mass: m_H, position: y_H}", "points:", "  C: 0", "  M: {on: L}",
           "loads:", "  - {on: H, force: -F}", "strings:",
           "  - {name: rope, path: [" + ", ".join(path) + "], tension: T}",
           "connections:", "  - {type: pulley, at: C}", "  - {type: pulley, at: M}",
           "layout: {y_M: -3, y_H: -1}", "find: [T, ddot(y_M), ddot(y_H)]"]
    return "\n".join(out) + "\n"


def pendulums(n):
    out = [f'title: "Benchmark: a chain of {n} pendulums coupled by springs"', "axes: [x, y]", "parameters:",
           "  m: {value: 1, unit: kg}", "  l: {value: 1, unit: m}", "  a: {value: 0.5, unit: m}",
           "  d: {value: 0.4, unit: m}", "  k: {value: 10, unit: N/m}", "  g: {value: 9.81, unit: m/s^2}",
           "gravity: [0, -g]", "bodies:"]
    out += [f'  b{i}: {{mass: m, angle: theta_{i}, center_of_mass: ["{i - 1}*d + l*sin(theta_{i})", "-l*cos(theta_{i})"]}}'
            for i in range(1, n + 1)]
    out.append("points:")
    out += [f'  O{i}: ["{i - 1}*d", 0]' for i in range(1, n + 1)]
    out += [f'  K{i}: {{on: b{i}, offset: [0, "l - a"]}}' for i in range(1, n + 1)]
    out.append("connections:")
    out += [f"  - {{type: pin, body: b{i}, at: O{i}}}" for i in range(1, n + 1)]
    out += [f"  - {{type: spring, name: sp{i}, path: [K{i}, K{i + 1}], k: k, rest_length: d}}" for i in range(1, n)]
    out.append("layout: {" + ", ".join(f"theta_{i}: 0" for i in range(1, n + 1)) + "}")
    out.append("find: [" + ", ".join(f"ddot(theta_{i})" for i in range(1, n + 1)) + "]")
    initial = ", ".join([f"theta_{i}: {0.05 if i == 1 else 0}, dot(theta_{i}): 0" for i in range(1, n + 1)])
    out += ["motion:", f"  initial: {{{initial}}}", "  until: 1"]
    return "\n".join(out) + "\n"


def carts(n):
    out = [f'title: "Benchmark: a 3-D train of {n} carts joined by ball joints"', "axes: [x, y, z]", "parameters:",
           "  F: {value: 8, unit: N}", "  g: {value: 9.81, unit: m/s^2}", "  b: {value: 1, unit: m}"]
    out += [f"  m_{i}: {{value: {1 + i % 3}, unit: kg}}" for i in range(1, n + 1)]
    out += ["gravity: [0, 0, -g]", "bodies:"]
    out += [f"  C{i}: {{mass: m_{i}, position: x_{i}, center_of_mass: [x_{i}, 0, 0]}}" for i in range(1, n + 1)]
    out.append("points:")
    out += [f"  J{i}: {{on: C{i + 1}, offset: [\"-b\", 0, 0]}}" for i in range(1, n)]
    out.append("connections:")
    out += [f"  - {{type: roller, body: C{i}, at: C{i}, normal: [0, 0, 1]}}" for i in range(1, n + 1)]
    out += [f"  - {{type: ball_joint, body: C{i + 1}, other: C{i}, at: J{i}}}" for i in range(1, n)]
    out.append(f"  - {{type: force, on: C{n}, at: C{n}, force: [F, 0, 0]}}")
    out.append("layout: {" + ", ".join(f"x_{i}: {3 * i}" for i in range(1, n + 1)) + "}")
    return "\n".join(out) + "\n"


KINDS = {"chain": chain, "cascade": cascade, "tackle": block_and_tackle, "carts": carts, "pendulums": pendulums}

if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in KINDS:
        sys.exit("usage: generate.py {" + ",".join(KINDS) + "} N")
    sys.stdout.write(KINDS[sys.argv[1]](int(sys.argv[2])))
