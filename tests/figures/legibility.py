#!/usr/bin/env python3
r"""Legibility of tackle's figures (issue 44, item 6): a measure over the drawn SVG and TikZ.

How it is run
-------------
    python3 tests/figures/legibility.py TACKLE FILE.yaml [FILE.yaml ...] [options]
    python3 tests/figures/legibility.py --svg PAGE.html|FIG.svg ... --tikz DOC.tex ...

With a tackle binary, each description is derived twice, serially:
`TACKLE derive FILE --format html` (its inline `<svg class="fbd">` figures: the mechanism's
sketch and the free body diagrams) and `TACKLE derive FILE --format latex` (the same figures
as `tikzpicture`s); `--sheet` also measures `TACKLE sheet FILE --figures --format latex`.
`--svg`/`--tikz` measure files already written (the self test uses them). Options:
`--format svg|tikz|both` (default both), `--json PATH` (the summary to a file; `-` for stdout,
the default is stdout after the defect lines), `--quiet` (no defect lines), `--tolerance PX`
and `--attach UNITS` (below). Coordinates in the lines are the figure's own: SVG pixels (y
down), TikZ centimetres (y up).

Output: one line per defect,
    FILE: figure N: label 'T_A' crossed by line (x1,y1)-(x2,y2) [svg: Free body diagram of A]
then a JSON summary (counts per file and in all). Exit status 0 when there is no defect, 1
when there is one, 2 on a usage error (or a binary or file that cannot be run or read).
Python 3 standard library only (PyYAML, when present, only to name the bodies that need a
diagram).

What is measured, per figure
----------------------------
Four kinds of defect:
- `crossed`: a label's box is crossed by a drawn line (a string, a spring, a support, the
  ground's hatching), an outline (a body's polygon edge or circle), an arrow (its shaft or its
  head; a couple's arc, sampled; the axes included) or covers a point's dot. One defect per
  label and crossing element (a label under five hatching strokes is five). The label's own
  arrow counts: a label must sit clear of it.
- `overlap`: two labels' boxes overlap (by more than the tolerance below; with `--gap PX`,
  labels closer than PX count too: crowding).
- `detached`: an arrow (a force or an inertial term; not the axes, not a couple) whose tail and
  head are both farther than `--attach` (default 0.1 drawing units: 4 px, 1 mm) from every
  outline, every drawn point and every body's centre (a circle's centre, a polygon's
  centroid: the center of mass a weight leaves).
- `inside` (said as a note, counted apart, not a defect: the issue's "no arrow starts inside
  an outline unless it is a body force" needs to know which forces are body forces, which
  the figure does not say): an arrow whose two ends both lie inside one outline, deeper than
  `--attach`. Its lines are written with `--notes`.
- `undrawn`: a description with no figure, a 2-D description without its sketch, or a body
  with a mass whose balance `derive` writes (every such body when the description has no
  `derive:` key) without a free body diagram naming it.

Label boxes (an estimate, documented so that it can be argued with)
-------------------------------------------------------------------
Across, SVG: tackle writes each label as `<text>` centred at x (`text-anchor="middle"`) with
`textLength` and `lengthAdjust="spacingAndGlyphs"`, so the browser draws it exactly that wide:
the box is [x - textLength/2, x + textLength/2]. (Without textLength, which tackle always
writes, the width is estimated with DejaVu-like widths: a letter 0.6 em, a digit 0.55, an
operator 0.8, punctuation 0.35, a space 0.32, a thin space 0.2; scripts at 70 %.)

Across, TikZ: a label is `\node[font=\small, inner sep=0pt] at (x,y) {...}` whose text is
`$math$` or `\tacklelabel{W}{H}{$math$}` (tackle's macro: the text scaled by
min(1, W/width, H/height)). The natural width is estimated from the math after its commands
are read (Greek letters, \mathrm, \dot, \frac, \left/\right, sub- and superscripts) at
\small (10 pt in tackle's 11 pt documents: 0.3515 cm an em), with widths per character in em
of Latin Modern math, calibrated against pdflatex's own boxes for the 268 distinct labels of
the examples and the generated set (estimate/actual: median 0.97, 0.87 to 1.11):
    italic capital 0.80 (W 1.08, M 0.97, N H K 0.91, T P F 0.72, L 0.68, S 0.67, I 0.50)
    italic small 0.55 (m 0.88, w 0.72, i 0.35, l 0.30, j 0.41, f 0.49, t 0.36)
    upright small (\mathrm, \sin) 0.50 (m 0.83, i l 0.28)     digit 0.50
    Greek small 0.58 (θ 0.50), capital 0.75      ( ) [ ] 0.39    / 0.50
    + - with TeX's spacing 1.22, = 1.34, comma 0.45; spaces are not drawn in math mode
    a sub- or superscript 70 %; a \frac in text style 80 % of its wider part + 0.24 em.
Then \tacklelabel's scale is applied, about the node's centre (inner sep=0pt: the box is the
text's box).

Up and down, both: the ink from the baseline, in em (measured in Chromium on DejaVu Serif
italic and in pdflatex on Latin Modern): 0.75 above when a run has a capital, a digit, an
ascender (b d f h k l t), a parenthesis or a tall Greek letter (θ δ λ β ζ ξ φ), else 0.55
(x-height); 0.22 below when it has a descender (g j p q y, parentheses, comma, β γ ζ η μ ξ ρ
φ χ ψ), else 0. Scripts at 70 %: in SVG shifted 0.4 em of the text around them (Chromium's
`baseline-shift` sub and super: N_A's ink reaches 0.40 em below, θ^2's 0.93 em above); in
TikZ a subscript 0.15 em down and a superscript 0.36 em up (TeX's sub1 and sup2), a \frac's
numerator 0.39 em up and its denominator 0.34 em down, a \dot or \ddot 0.2 em over its
letter. In SVG the accent dots tackle draws over a letter (black circles of r < 2 px right
after a text) are part of the label: its box grows to hold them, and the report puts the
dot back over the letter (m ẍ).

Crossing is decided on the label's box shrunk by `--tolerance` (default 1 px in SVG, 1/40 cm
in TikZ: tackle draws 40 px to a unit) on every side, so that a line that only grazes the
estimate's edge does not count. Segments are the straight parts of outlines, polylines,
arrow shafts and heads; arcs (couples in both formats, `A` in SVG paths) are sampled every
10 degrees; circles are tested exactly (a label inside a disk, clear of its rim, is not
crossed). Arrow heads: SVG from the marker tackle defines (markerWidth 7 in stroke widths, tip
at the line's end, 9/10 of its length behind it); TikZ
`stealth` as PGF draws it (for a line width w: d = 0.28 pt + 0.3 w, 8 d long and 8 d wide:
0.18 cm by 0.18 cm for very thick arrows). SVG heads are twice as big
as TikZ's (14 px = 0.35 units across for a 2 px line), so a label that clears a TikZ head may
touch the SVG one.

Figures are found as `<svg ...class="fbd"...>...</svg>` (outside <script>s) and as
`tikzpicture`s that use `\tacklelabel` (tackle's figures; plots are not measured).
Anything in a figure the reader does not know is counted in the summary as `unread`, so a
change in what tackle draws shows up rather than passing silently.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG_NS = "{http://www.w3.org/2000/svg}"
PX_PER_UNIT = 40.0  # tackle's SVG: 40 px to a drawing unit (about a centimetre)

# ---------------------------------------------------------------------------------------
# Text extents


# SVG text without textLength (tackle always writes one): DejaVu-like widths, in em.
WIDTH_LETTER = 0.60
WIDTH_DIGIT = 0.55
WIDTH_OPERATOR = 0.80
WIDTH_PUNCT = 0.35
WIDTH_SPACE = 0.32
WIDTH_THIN = 0.20
SCRIPT = 0.70  # a sub- or superscript's size, of its level's

# Ink up and down from the baseline, in em (measured in Chromium on DejaVu Serif italic and in
# pdflatex on Latin Modern: capitals 0.73 and 0.68, x-height 0.52 and 0.43, descenders 0.21).
TALL = set("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789bdfhklt()[]/|!?" "βδζθϑλξφΓΔΘΛΞΠΣΦΨΩℓ√∂")
DESCENDING = set("gjpqy()[],;|" "βγζημξρφχψ")
UP_TALL, UP_SHORT, DOWN = 0.75, 0.55, 0.22


def ink(text):
    """(up, down) of a run of plain characters, in em."""
    shown = [c for c in text if not c.isspace()]
    if not shown:
        return 0.0, 0.0
    up = UP_TALL if any(c in TALL for c in shown) else UP_SHORT
    down = DOWN if any(c in DESCENDING for c in shown) else 0.0
    return up, down


GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "varepsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "vartheta": "ϑ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν",
    "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "upsilon": "υ", "phi": "φ", "varphi": "φ",
    "chi": "χ", "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ",
    "Pi": "Π", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω", "ell": "ℓ", "infty": "∞", "cdot": "·",
    "times": "×",
}


def char_width(c):
    """SVG fallback: the advance of one character, in em (DejaVu-like)."""
    if c.isdigit():
        return WIDTH_DIGIT
    if c in "+=-−×·":
        return WIDTH_OPERATOR
    if c in "()[]/,.;:|'!":
        return WIDTH_PUNCT
    if c == " ":
        return WIDTH_SPACE
    if c == "\u2009":
        return WIDTH_THIN
    return WIDTH_LETTER


def text_width(s):
    return sum(char_width(c) for c in s)


def tex_char_width(c, upright=False):
    """TikZ: the advance of one character in Latin Modern math at its size, in em (the table
    calibrated against pdflatex's boxes; docs/figures-legibility-2026-11-28.md)."""
    if c.isdigit():
        return 0.50
    if c in "+-−":
        return 0.78 + 0.44  # the glyph and TeX's medium spaces around a binary operator
    if c == "=":
        return 0.78 + 0.56  # and the thick spaces around a relation
    if c in "()[]":
        return 0.39
    if c == "/":
        return 0.50
    if c in ",;":
        return 0.28 + 0.17  # punctuation and the thin space after it
    if c == ".":
        return 0.28
    if c == " ":
        return 0.0  # spaces are not drawn in math mode
    if "A" <= c <= "Z":
        return {"W": 1.08, "M": 0.97, "N": 0.91, "H": 0.91, "K": 0.92, "I": 0.50, "J": 0.60, "T": 0.72,
                "L": 0.68, "S": 0.67, "P": 0.72, "F": 0.72, "V": 0.70, "Y": 0.70}.get(c, 0.80)
    if "a" <= c <= "z":
        if upright:
            return {"m": 0.83, "w": 0.72, "i": 0.28, "l": 0.28, "j": 0.30, "t": 0.39, "f": 0.31, "r": 0.39}.get(c, 0.50)
        return {"m": 0.88, "w": 0.72, "i": 0.35, "l": 0.30, "j": 0.41, "f": 0.49, "t": 0.36}.get(c, 0.55)
    if c in "ΓΔΘΛΞΠΣΦΨΩ":
        return 0.75
    if c in "θι":
        return 0.50
    return 0.58  # Greek lower case and the rest


class Extent:
    """A run of math: its width, its ink above and below the baseline (em)."""

    def __init__(self, w=0.0, up=0.0, down=0.0):
        self.w, self.up, self.down = w, up, down

    def add(self, o):
        self.w += o.w
        self.up = max(self.up, o.up)
        self.down = max(self.down, o.down)


def plain(text, upright=False):
    up, down = ink(text)
    return Extent(sum(tex_char_width(c, upright) for c in text), up, down)


class TexReader:
    """Reads the LaTeX math of a tackle label into its shown text and extent (em of its font):
    sub- and superscripts at 70 %, lowered 0.15 em and raised 0.36 em (TeX's sub1 and sup2
    for text style), fractions in text style (script-size parts, the numerator 0.39 em up,
    the denominator 0.34 em down), accents 0.2 em over their letter."""

    def __init__(self, s):
        self.s, self.i = s, 0
        self.upright = 0

    def run(self):
        out, ext = "", Extent()
        while self.i < len(self.s):
            t, e = self.item()
            out += t
            ext.add(e)
        return out, ext

    def group(self):
        if self.i < len(self.s) and self.s[self.i] == "{":
            self.i += 1
            out, ext = "", Extent()
            while self.i < len(self.s) and self.s[self.i] != "}":
                t, e = self.item()
                out += t
                ext.add(e)
            self.i += 1
            return out, ext
        if self.i < len(self.s):
            return self.item()
        return "", Extent()

    def item(self):
        c = self.s[self.i]
        if c == "\\":
            self.i += 1
            m = re.match(r"[A-Za-z]+", self.s[self.i:])
            if not m:
                e = self.s[self.i] if self.i < len(self.s) else " "
                self.i += 1
                if e in ",;: ":
                    return " ", Extent(0.17 if e == "," else 0.28)
                if e == "!":
                    return "", Extent(-0.17)
                return e, plain(e)
            name = m.group(0)
            self.i += len(name)
            if name in ("left", "right"):
                if self.i < len(self.s) and self.s[self.i] == ".":
                    self.i += 1
                    return "", Extent()
                return self.item()
            if name in GREEK:
                g = GREEK[name]
                up, down = ink(g)
                return g, Extent(tex_char_width(g), up, down)
            if name in ("dot", "ddot"):
                t, e = self.group()
                e.up += 0.2
                return t + ("\u0307" if name == "dot" else "\u0308"), e
            if name == "frac":
                a, ea = self.group()
                b, eb = self.group()
                w = max(ea.w, eb.w) * 0.8 + 0.24  # script size (a 7 pt font is wider per em), delimiters
                paren = lambda t: "(" + t + ")" if re.search(r"[-+−]", t) else t
                return f"{paren(a)}/{paren(b)}", Extent(w, 0.39 + SCRIPT * ea.up, 0.34 + SCRIPT * eb.down)
            if name == "sqrt":
                t, e = self.group()
                return "√(" + t + ")", Extent(e.w + 0.85, max(e.up + 0.15, 0.85), max(e.down, 0.2))
            if name in ("mathrm", "text", "operatorname", "mathit", "mathbf"):
                self.upright += name != "mathit"
                t, e = self.group()
                self.upright -= name != "mathit"
                return t, e
            if name in ("quad", "qquad"):
                return " ", Extent(1.0 if name == "quad" else 2.0)
            return name, plain(name, upright=True)  # \sin, \cos, ...: upright letters
        self.i += 1
        if c in "_^":
            t, e = self.group()
            if c == "_":
                return "_" + (t if len(t) == 1 else "{" + t + "}"), Extent(
                    e.w * SCRIPT, max(0.0, SCRIPT * e.up - 0.15), 0.15 + SCRIPT * e.down)
            return "^" + (t if len(t) == 1 else "{" + t + "}"), Extent(e.w * SCRIPT, 0.36 + SCRIPT * e.up, 0.0)
        if c == "{":
            self.i -= 1
            return self.group()
        if c == " ":
            return "" if self.s[self.i:self.i + 1] in "_^" else " ", Extent()
        return c, plain(c, upright=self.upright > 0)


def tex_label(tex):
    """A TikZ label's math: (its shown text, Extent in em)."""
    tex = tex.strip()
    if tex.startswith("$") and tex.endswith("$"):
        tex = tex[1:-1]
    return TexReader(tex).run()


# ---------------------------------------------------------------------------------------
# Geometry


def seg_seg(p, q, a, b):
    """Whether segments p-q and a-b meet."""

    def orient(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    d1, d2 = orient(a, b, p), orient(a, b, q)
    d3, d4 = orient(p, q, a), orient(p, q, b)
    if ((d1 > 0) != (d2 > 0)) and ((d3 > 0) != (d4 > 0)) and d1 != 0 and d2 != 0 and d3 != 0 and d4 != 0:
        return True

    def on(u, v, w):
        return min(u[0], v[0]) <= w[0] <= max(u[0], v[0]) and min(u[1], v[1]) <= w[1] <= max(u[1], v[1])

    return ((d1 == 0 and on(a, b, p)) or (d2 == 0 and on(a, b, q)) or (d3 == 0 and on(p, q, a))
            or (d4 == 0 and on(p, q, b)))


def box_hits_segment(box, p, q):
    x0, y0, x1, y1 = box
    if x0 >= x1 or y0 >= y1:
        return False
    inside = lambda u: x0 < u[0] < x1 and y0 < u[1] < y1
    if inside(p) or inside(q):
        return True
    if max(p[0], q[0]) < x0 or min(p[0], q[0]) > x1 or max(p[1], q[1]) < y0 or min(p[1], q[1]) > y1:
        return False
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return any(seg_seg(p, q, corners[k], corners[(k + 1) % 4]) for k in range(4))


def box_hits_circle_rim(box, c, r):
    """Whether the circle's rim passes through the box."""
    x0, y0, x1, y1 = box
    if x0 >= x1 or y0 >= y1:
        return False
    nx, ny = min(max(c[0], x0), x1), min(max(c[1], y0), y1)
    near = math.hypot(nx - c[0], ny - c[1])
    far = max(math.hypot(x - c[0], y - c[1]) for x in (x0, x1) for y in (y0, y1))
    return near < r < far


def box_hits_disk(box, c, r):
    """Whether a filled disk (a point's dot) touches the box."""
    x0, y0, x1, y1 = box
    if x0 >= x1 or y0 >= y1:
        return False
    nx, ny = min(max(c[0], x0), x1), min(max(c[1], y0), y1)
    return math.hypot(nx - c[0], ny - c[1]) < r


def point_in_polygon(p, poly):
    inside = False
    n = len(poly)
    for k in range(n):
        a, b = poly[k], poly[(k + 1) % n]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                inside = not inside
    return inside


def box_hits_polygon(box, poly):
    """Whether a filled polygon (an arrow head) touches the box."""
    x0, y0, x1, y1 = box
    if x0 >= x1 or y0 >= y1:
        return False
    n = len(poly)
    if any(box_hits_segment(box, poly[k], poly[(k + 1) % n]) for k in range(n)):
        return True
    return point_in_polygon(((x0 + x1) / 2, (y0 + y1) / 2), poly)


def boxes_overlap(a, b, tol):
    return (min(a[2], b[2]) - max(a[0], b[0]) > tol) and (min(a[3], b[3]) - max(a[1], b[1]) > tol)


def shrink(box, t):
    return (box[0] + t, box[1] + t, box[2] - t, box[3] - t)


def dist_point_segment(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2))
    return math.hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy))


def arrow_head(tail, head, length, half_width):
    """The triangle of an arrow head whose tip is at `head`."""
    dx, dy = head[0] - tail[0], head[1] - tail[1]
    L = math.hypot(dx, dy) or 1.0
    ux, uy = dx / L, dy / L
    bx, by = head[0] - ux * length, head[1] - uy * length
    return [head, (bx - uy * half_width, by + ux * half_width), (bx + uy * half_width, by - ux * half_width)]


def fmt_num(v):
    s = f"{v:.2f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def fp(p):
    return f"({fmt_num(p[0])},{fmt_num(p[1])})"


# ---------------------------------------------------------------------------------------
# The figure, as both readers make it


class Label:
    def __init__(self, text, box, owner=None):
        self.text, self.box, self.owner = text, box, owner  # owner: an index into arrows, or None
        self.dots = []  # SVG: the accent dots drawn over its letters
        self.svg = None


class Arrow:
    def __init__(self, tail, head, kind, head_poly):
        self.tail, self.head, self.kind = tail, head, kind  # kind: force, inertial, axis
        self.head_poly = head_poly
        self.label = None


class Figure:
    def __init__(self, fmt, index, caption):
        self.fmt, self.index, self.caption = fmt, index, caption
        self.labels = []
        self.polygons = []  # outlines: lists of points
        self.circles = []  # outlines: (centre, r)
        self.lines = []  # polylines: lists of points
        self.dots = []  # (centre, r)
        self.arrows = []
        self.couples = []  # (sampled points, head polygon, label text)
        self.unread = []

    def add_label(self, text, box, owner=None):
        self.labels.append(Label(text, box, owner))
        if owner is not None:
            self.arrows[owner].label = text


# ---------------------------------------------------------------------------------------
# SVG


def tag(e):
    return e.tag.replace(SVG_NS, "")


def svg_chars(e, size=1.0, mode=""):
    """A <text>'s characters in order: (character, size, "" or "_" or "^")."""
    out = [(c, size, mode) for c in (e.text or "")]
    for ch in e:
        m, s = mode, size
        if ch.get("baseline-shift") == "sub":
            m = "_"
        elif ch.get("baseline-shift") == "super":
            m = "^"
        if ch.get("font-size", "").endswith("%"):
            s = size * float(ch.get("font-size")[:-1]) / 100
        out += svg_chars(ch, s, m)
        out += [(c, size, mode) for c in (ch.tail or "")]
    return out


def tackle_advance(c):
    """The advance tackle's SVG writer assumes for a character (src/figure/render.cpp,
    svg_shown), in em: where it puts a letter's dots. Used only to name the dotted letter."""
    if c == "\u2009":
        return 0.17
    if c == " ":
        return 0.25
    if ord(c) > 127:
        return 0.6
    if c in "mwMW":
        return 0.85
    if c in "ijltfr()/,.:;'|!":
        return 0.33
    if c.isupper():
        return 0.7
    if c.isdigit():
        return 0.5
    if c in "+=":
        return 0.6
    return 0.52


def svg_label_text(e, x0=0.0, width=0.0, dots=()):
    """A <text>'s content as a label is written (T_A, m_A g, θ̇^2): scripts marked with _ and
    ^, thin spaces as spaces, and the dots tackle draws over a letter (circles after the text)
    put back over the letter under them, as a combining dot or diaeresis."""
    chars = svg_chars(e)
    marks = [""] * len(chars)
    if dots and chars and width > 0:
        advances = [tackle_advance(c) * size for c, size, _ in chars]
        scale = width / (sum(advances) or 1.0)
        groups = []
        for x, y in sorted(dots):
            if groups and abs(groups[-1][1] - y) < 0.5 and x - groups[-1][2] < 6:
                groups[-1] = (groups[-1][0], y, x, groups[-1][3] + 1, (groups[-1][4] + x) / 2)
            else:
                groups.append((x, y, x, 1, x))
        for _first, _y, _last, count, centre in groups:
            at, best = 0.0, (float("inf"), None)
            for k, adv in enumerate(advances):
                mid = x0 + (at + adv / 2) * scale
                at += adv
                if not chars[k][0].isspace() and abs(mid - centre) < best[0]:
                    best = (abs(mid - centre), k)
            if best[1] is not None:
                marks[best[1]] += "\u0307" if count == 1 else "\u0308"
    out, k = "", 0
    while k < len(chars):
        mode = chars[k][2]
        run = ""
        while k < len(chars) and chars[k][2] == mode:
            c = " " if chars[k][0] == "\u2009" else chars[k][0]
            run += c + marks[k]
            k += 1
        if mode:
            n = len(re.sub("[\u0307\u0308]", "", run))
            out += mode + (run if n == 1 else "{" + run + "}")
        else:
            out += run
    return out


def svg_ink(e, size=1.0, rise=0.0):
    """(up, down) of a <text>'s ink from its baseline, in em of its font: each run's
    characters (the ink table) at its size, sub- and superscripts at 70 % shifted 0.4 em of
    the text around them (as measured in Chromium)."""
    up, down = 0.0, 0.0

    def run(text):
        nonlocal up, down
        u, d = ink(text or "")
        if u or d:
            up = max(up, rise + u * size)
            down = max(down, -rise + d * size)

    run(e.text)
    for ch in e:
        s, r = size, rise
        if ch.get("baseline-shift") == "sub":
            r -= 0.4 * size
        elif ch.get("baseline-shift") == "super":
            r += 0.4 * size
        if ch.get("font-size", "").endswith("%"):
            s = size * float(ch.get("font-size")[:-1]) / 100
        u, d = svg_ink(ch, s, r)
        up, down = max(up, u), max(down, d)
        run(ch.tail)
    return up, down


def svg_shown(e):
    return "".join(e.itertext())


def fnum(v):
    return float(v)


def parse_points(s):
    nums = [float(t) for t in re.split(r"[ ,]+", s.strip()) if t]
    return [(nums[k], nums[k + 1]) for k in range(0, len(nums) - 1, 2)]


def arc_points(x1, y1, rx, ry, large, sweep, x2, y2):
    """An SVG elliptical arc (circular here: rx = ry) sampled every 10 degrees."""
    r = rx
    mx, my = (x1 - x2) / 2, (y1 - y2) / 2
    d2 = mx * mx + my * my
    r = max(r, math.sqrt(d2))
    f = math.sqrt(max(0.0, (r * r - d2) / d2)) if d2 > 0 else 0.0
    if large == sweep:
        f = -f
    cx = (x1 + x2) / 2 + f * my  # the centre (SVG's implementation notes, F.6.5, rx = ry)
    cy = (y1 + y2) / 2 - f * mx
    a1 = math.atan2(y1 - cy, x1 - cx)
    a2 = math.atan2(y2 - cy, x2 - cx)
    da = a2 - a1
    if sweep and da < 0:
        da += 2 * math.pi
    if not sweep and da > 0:
        da -= 2 * math.pi
    n = max(2, int(abs(da) / math.radians(10)) + 1)
    return [(cx + r * math.cos(a1 + da * k / n), cy + r * math.sin(a1 + da * k / n)) for k in range(n + 1)]


def svg_path_points(d):
    """The points of an SVG path (M, L, A, Z; absolute), curved parts sampled."""
    toks = re.findall(r"[MLAZmlaz]|-?[0-9.]+(?:e-?[0-9]+)?", d)
    pts, k, cmd, cur = [], 0, None, (0.0, 0.0)
    ok = True
    while k < len(toks):
        t = toks[k]
        if t.isalpha():
            cmd = t
            k += 1
            if cmd in "Zz":
                if pts:
                    pts.append(pts[0])
                continue
            continue
        if cmd in ("M", "L"):
            cur = (float(toks[k]), float(toks[k + 1]))
            pts.append(cur)
            k += 2
        elif cmd == "A":
            rx, ry, _rot, large, sweep, x, y = (float(v) for v in toks[k:k + 7])
            pts.extend(arc_points(cur[0], cur[1], rx, ry, int(large), int(sweep), x, y)[1:])
            cur = (x, y)
            k += 7
        else:
            ok = False
            k += 1
    return pts, ok


def svg_marker_head(tail, head, stroke_width):
    # tackle's marker: viewBox 10x10, markerWidth/Height 7 (in stroke widths), refX 9: the tip
    # at 9/10 of its length from its back, at the line's end.
    size = 7 * stroke_width
    dx, dy = head[0] - tail[0], head[1] - tail[1]
    L = math.hypot(dx, dy) or 1.0
    tip = (head[0] + dx / L * size * 0.1, head[1] + dy / L * size * 0.1)
    return arrow_head(tail, tip, size, size / 2)


def read_svg_figure(svg_text, index):
    root = ET.fromstring(svg_text)
    title = root.find(SVG_NS + "title")
    caption = (title.text if title is not None else root.get("aria-label")) or ""
    fig = Figure("svg", index, caption.strip())
    last_label = None  # the label that accent dots follow
    pending_owner = None  # the arrow whose label comes next
    for e in root:
        t = tag(e)
        if t in ("title", "defs"):
            continue
        if t == "polygon":
            fig.polygons.append(parse_points(e.get("points")))
        elif t == "polyline":
            fig.lines.append(parse_points(e.get("points")))
        elif t == "circle":
            c = (fnum(e.get("cx")), fnum(e.get("cy")))
            r = fnum(e.get("r"))
            if e.get("stroke") not in (None, "none"):
                fig.circles.append((c, r))
            elif r < 2 and last_label is not None:  # an accent dot of the label before it
                last_label.dots.append(c)
                b = last_label.box
                last_label.box = (min(b[0], c[0] - r), min(b[1], c[1] - r), max(b[2], c[0] + r), max(b[3], c[1] + r))
            elif (c, r) not in fig.dots:  # a point (drawn twice where two things are there)
                fig.dots.append((c, r))
            continue
        elif t == "line":
            p = (fnum(e.get("x1")), fnum(e.get("y1")))
            q = (fnum(e.get("x2")), fnum(e.get("y2")))
            sw = float(e.get("stroke-width", "1"))
            kind = "axis" if sw < 1.5 else ("inertial" if e.get("stroke-dasharray") else "force")
            head = svg_marker_head(p, q, sw) if e.get("marker-end") else None
            fig.arrows.append(Arrow(p, q, kind, head))
            pending_owner = len(fig.arrows) - 1
            last_label = None
            continue
        elif t == "path":
            pts, ok = svg_path_points(e.get("d", ""))
            if not ok:
                fig.unread.append("path " + e.get("d", "")[:40])
            sw = float(e.get("stroke-width", "1"))
            head = svg_marker_head(pts[-2], pts[-1], sw) if e.get("marker-end") and len(pts) > 1 else None
            fig.couples.append([pts, head, None, None])
            pending_owner = ("couple", len(fig.couples) - 1)
            last_label = None
            continue
        elif t == "text":
            x, y = fnum(e.get("x")), fnum(e.get("y"))
            fs = fnum(e.get("font-size", "14"))
            shown = svg_shown(e)
            if e.get("textLength"):
                w = fnum(e.get("textLength"))
            else:
                w = text_width(shown) * fs
            anchor = e.get("text-anchor", "start")
            x0 = x - w / 2 if anchor == "middle" else (x - w if anchor == "end" else x)
            up, down = svg_ink(e)
            top, bottom = y - up * fs, y + down * fs
            owner = None
            if isinstance(pending_owner, int):
                owner = pending_owner
            text = svg_label_text(e)
            fig.add_label(text, (x0, top, x0 + w, bottom), owner)
            fig.labels[-1].svg = (e, x0, w)
            if isinstance(pending_owner, tuple):
                fig.couples[pending_owner[1]][2] = text
                fig.couples[pending_owner[1]][3] = len(fig.labels) - 1
            pending_owner = None
            last_label = fig.labels[-1]
            continue
        else:
            fig.unread.append(t)
        last_label = None
        pending_owner = None
    for k, lab in enumerate(fig.labels):  # the accents back over their letters
        if lab.dots:
            e, x0, w = lab.svg
            lab.text = svg_label_text(e, x0, w, lab.dots)
            if lab.owner is not None:
                fig.arrows[lab.owner].label = lab.text
            for cp in fig.couples:
                if cp[3] == k:
                    cp[2] = lab.text
    return fig


def svg_figures(page):
    """The tackle figures of an HTML page or an SVG file, as SVG texts."""
    page = re.sub(r"<script\b.*?</script>", "", page, flags=re.S)
    out = []
    for m in re.finditer(r"<svg\b[^>]*>.*?</svg>", page, flags=re.S):
        head = m.group(0)[: m.group(0).find(">") + 1]
        if re.search(r'class="[^"]*\bfbd\b', head):
            out.append(m.group(0))
    return out


# ---------------------------------------------------------------------------------------
# TikZ

TIKZ_SMALL_PT = {"10pt": 9.0, "11pt": 10.0, "12pt": 10.95}
PT_CM = 2.54 / 72.27
COORD = r"\(\s*(-?[0-9.]+)\s*,\s*(-?[0-9.]+)\s*\)"


def tikz_coords(s):
    return [(float(a), float(b)) for a, b in re.findall(COORD, s)]


def balanced(s, i):
    """The text of the {...} group starting at s[i] == '{', and the index after it."""
    assert s[i] == "{"
    depth = 0
    for k in range(i, len(s)):
        if s[k] == "{":
            depth += 1
        elif s[k] == "}":
            depth -= 1
            if depth == 0:
                return s[i + 1:k], k + 1
    return s[i + 1:], len(s)


def to_cm(v):
    m = re.fullmatch(r"\s*(-?[0-9.]+)\s*(cm|pt|mm)?\s*", v)
    if not m:
        return None
    x = float(m.group(1))
    return x * {"cm": 1, None: 1, "pt": PT_CM, "mm": 0.1}[m.group(2)]


def tikz_node_box(content, at, em_cm):
    """The box of a node's text: its natural extent, scaled as \\tacklelabel scales it."""
    scale_w = scale_h = None
    content = content.strip()
    m = re.match(r"\\tacklelabel\s*", content)
    if m:
        i = m.end()
        w, i = balanced(content, i)
        h, i = balanced(content, i)
        text, _ = balanced(content, i)
        scale_w, scale_h = to_cm(w), to_cm(h)
    else:
        text = content
    shown, ext = tex_label(text)
    nat_w = ext.w * em_cm
    up = ext.up * em_cm
    down = ext.down * em_cm
    nat_h = up + down
    s = 1.0
    if scale_w:
        s = min(s, scale_w / max(nat_w, 1e-6))
    if scale_h:
        s = min(s, scale_h / max(nat_h, 1e-6))
    # inner sep=0pt, anchor=center: the box is centred on the node's point
    w, h = nat_w * s, nat_h * s
    return shown, (at[0] - w / 2, at[1] - h / 2, at[0] + w / 2, at[1] + h / 2)


TIKZ_WIDTHS = {"ultra thin": 0.1, "very thin": 0.2, "thin": 0.4, "semithick": 0.6, "thick": 0.8,
               "very thick": 1.2, "ultra thick": 1.6}


def tikz_head(tail, head, style):
    """PGF's `stealth` tip for the path's line width w (pt): d = 0.28 pt + 0.3 w, the tip at
    the end, its back corners 8 d behind it and 4 d to either side (pgflibraryarrows)."""
    width = 0.4
    for opt in style.split(","):
        width = TIKZ_WIDTHS.get(opt.strip(), width)
    d = (0.28 + 0.3 * width) * PT_CM
    return arrow_head(tail, head, 8 * d, 4 * d)


def read_tikz_figure(body, index, caption, em_cm):
    fig = Figure("tikz", index, caption)
    pending_owner = None
    # one statement per line, as tackle writes them; a statement may only end with ';'
    statements, part = [], ""
    for line in body.split("\n"):
        if not line.strip():
            continue
        if line.strip().startswith("\\providecommand"):  # tackle's \tacklelabel, on a line of its own
            continue
        part += (" " if part else "") + line.strip()
        if part.endswith(";"):
            statements.append(part)
            part = ""
    if part:
        fig.unread.append(part[:50])
    for st in statements:
        st = st.rstrip(";").strip()
        if st.startswith("\\providecommand") or st.startswith("%"):
            continue
        m = re.match(r"\\(filldraw|draw|fill|node|path)\s*(\[[^\]]*\])?\s*(.*)$", st, re.S)
        if not m:
            fig.unread.append(st[:50])
            continue
        cmd, style, rest = m.group(1), (m.group(2) or "[]")[1:-1], m.group(3)
        if cmd == "node":
            mm = re.match(r"at\s*" + COORD + r"\s*", rest)
            if not mm:
                fig.unread.append(st[:50])
                continue
            at = (float(mm.group(1)), float(mm.group(2)))
            i = rest.find("{", mm.end())
            content, _ = balanced(rest, i)
            shown, box = tikz_node_box(content, at, em_cm)
            owner = pending_owner if isinstance(pending_owner, int) else None
            fig.add_label(shown, box, owner)
            if isinstance(pending_owner, tuple):
                fig.couples[pending_owner[1]][2] = shown
            pending_owner = None
            continue
        pending_owner = None
        if cmd == "path":
            fig.unread.append(st[:50])  # tackle draws nothing with \path
            continue
        if " node" in rest:
            fig.unread.append(st[:50])
        mc = re.match(COORD + r"\s*circle\s*\(\s*([0-9.]+)\s*(pt|cm)?\s*\)\s*$", rest)
        if mc:
            c = (float(mc.group(1)), float(mc.group(2)))
            r = float(mc.group(3)) * (PT_CM if mc.group(4) == "pt" else 1)
            if cmd == "fill":
                if (c, r) not in fig.dots:  # a point (drawn twice where two things are there)
                    fig.dots.append((c, r))
            else:
                fig.circles.append((c, r))
            continue
        ma = re.match(COORD + r"\s*arc\s*\[([^\]]*)\]\s*$", rest)
        if ma:
            opts = dict(re.findall(r"([a-z ]+?)\s*=\s*(-?[0-9.]+)", ma.group(3)))
            opts = {k.strip(): float(v) for k, v in opts.items()}
            s0, s1, r = opts.get("start angle"), opts.get("end angle"), opts.get("radius")
            if None in (s0, s1, r):
                fig.unread.append(st[:50])
                continue
            p0 = (float(ma.group(1)), float(ma.group(2)))
            cx, cy = p0[0] - r * math.cos(math.radians(s0)), p0[1] - r * math.sin(math.radians(s0))
            n = max(2, int(abs(s1 - s0) / 10) + 1)
            pts = [(cx + r * math.cos(math.radians(s0 + (s1 - s0) * k / n)),
                    cy + r * math.sin(math.radians(s0 + (s1 - s0) * k / n))) for k in range(n + 1)]
            head = tikz_head(pts[-2], pts[-1], style) if "->" in style else None
            fig.couples.append([pts, head, None, None])
            pending_owner = ("couple", len(fig.couples) - 1)
            continue
        pts = tikz_coords(rest)
        stripped = re.sub(COORD, "", rest)
        stripped = re.sub(r"--|cycle", "", stripped).strip()
        if stripped or not pts:
            fig.unread.append(st[:50])
            continue
        closed = "cycle" in rest
        if cmd == "filldraw" or (cmd == "fill" and closed):
            fig.polygons.append(pts)
        elif "->" in style and len(pts) == 2:
            kind = "axis" if re.search(r"(^|,)\s*thin\s*(,|$)", style) else (
                "inertial" if "dashed" in style else "force")
            fig.arrows.append(Arrow(pts[0], pts[1], kind, tikz_head(pts[0], pts[1], style)))
            pending_owner = len(fig.arrows) - 1
        else:
            fig.lines.append(pts + ([pts[0]] if closed else []))
    return fig


def tikz_figures(doc):
    """(body, caption) of each tackle tikzpicture in a LaTeX document, and the em in cm."""
    m = re.search(r"\\documentclass\[([^\]]*)\]", doc)
    size = "10pt"
    if m:
        for opt in m.group(1).split(","):
            if opt.strip() in TIKZ_SMALL_PT:
                size = opt.strip()
    em_cm = TIKZ_SMALL_PT[size] * PT_CM
    out = []
    for mm in re.finditer(r"\\begin\{tikzpicture\}(\[[^\]]*\])?(.*?)\\end\{tikzpicture\}", doc, flags=re.S):
        body = mm.group(2)
        if "\\tacklelabel" not in body:
            continue
        after = doc[mm.end():mm.end() + 400]
        cap = re.match(r"\s*\}?\s*(?:\\\\\[[^\]]*\])?\s*\{\\small\s+([^}]*)\}", after)
        caption = cap.group(1).strip() if cap else ""
        caption = re.sub(r"\\([_&%$#{}])", r"\1", caption)  # LaTeX's escapes: block\_1
        out.append((body, caption))
    return out, em_cm


# ---------------------------------------------------------------------------------------
# The measure


def arrow_name(fig, k):
    a = fig.arrows[k]
    what = {"axis": "axis", "inertial": "inertial arrow", "force": "arrow"}[a.kind]
    return f"{what} '{a.label}'" if a.label else what


GRAVITY = re.compile(r"^g( (sin|cos)\(.*\))?$")


def measure(fig, tol, attach, gap=0.0):
    """The defects of one figure: a list of (kind, message)."""
    defects = []
    for li, lab in enumerate(fig.labels):
        box = shrink(lab.box, tol)
        hits = []
        for poly in fig.polygons:
            n = len(poly)
            for k in range(n):
                p, q = poly[k], poly[(k + 1) % n]
                if box_hits_segment(box, p, q):
                    hits.append(f"outline {fp(p)}-{fp(q)}")
        for c, r in fig.circles:
            if box_hits_circle_rim(box, c, r):
                hits.append(f"outline circle {fp(c)} r {fmt_num(r)}")
        for line in fig.lines:
            for k in range(len(line) - 1):
                if box_hits_segment(box, line[k], line[k + 1]):
                    hits.append(f"line {fp(line[k])}-{fp(line[k + 1])}")
                    break  # one per polyline
        for k, a in enumerate(fig.arrows):
            if box_hits_segment(box, a.tail, a.head) or (a.head_poly and box_hits_polygon(box, a.head_poly)):
                own = " (its own)" if lab.owner == k else ""
                hits.append(f"{arrow_name(fig, k)}{own} {fp(a.tail)}-{fp(a.head)}")
        for pts, head, text, _ in fig.couples:
            crossed = any(box_hits_segment(box, pts[k], pts[k + 1]) for k in range(len(pts) - 1))
            if crossed or (head and box_hits_polygon(box, head)):
                hits.append(f"couple '{text or ''}' {fp(pts[0])}-{fp(pts[-1])}")
        for c, r in fig.dots:
            if box_hits_disk(box, c, r):
                hits.append(f"point {fp(c)}")
        for h in hits:
            defects.append(("crossed", f"label '{lab.text}' crossed by {h}"))
    for i in range(len(fig.labels)):
        for j in range(i + 1, len(fig.labels)):
            a, b = fig.labels[i], fig.labels[j]
            if boxes_overlap(a.box, b.box, tol - gap):
                defects.append(("overlap", f"labels '{a.text}' and '{b.text}' overlap at "
                                           f"{fp(((a.box[0] + a.box[2]) / 2, (a.box[1] + a.box[3]) / 2))}"))
    anchors = [c for c, _ in fig.dots] + [c for c, _ in fig.circles]
    for poly in fig.polygons:
        anchors.append((sum(p[0] for p in poly) / len(poly), sum(p[1] for p in poly) / len(poly)))

    def distance(p):
        d = [math.hypot(p[0] - c[0], p[1] - c[1]) for c in anchors]
        for poly in fig.polygons:
            d += [dist_point_segment(p, poly[k], poly[(k + 1) % len(poly)]) for k in range(len(poly))]
        d += [abs(math.hypot(p[0] - c[0], p[1] - c[1]) - r) for c, r in fig.circles]
        return min(d) if d else float("inf")

    for k, a in enumerate(fig.arrows):  # not a defect of the measure: said, and counted apart
        if a.kind == "axis":
            continue
        for poly in fig.polygons:
            if all(point_in_polygon(p, poly) and min(dist_point_segment(p, poly[j], poly[(j + 1) % len(poly)])
                                                     for j in range(len(poly))) > attach for p in (a.tail, a.head)):
                defects.append(("inside", f"note: {arrow_name(fig, k)} {fp(a.tail)}-{fp(a.head)} lies inside an "
                                          "outline, both ends (not counted as a defect)"))
                break
        else:
            for c, r in fig.circles:
                if all(math.hypot(p[0] - c[0], p[1] - c[1]) < r - attach for p in (a.tail, a.head)):
                    defects.append(("inside", f"note: {arrow_name(fig, k)} {fp(a.tail)}-{fp(a.head)} lies inside "
                                              "an outline, both ends (not counted as a defect)"))
                    break
    for k, a in enumerate(fig.arrows):
        if a.kind == "axis" or (fig.caption.startswith("Sketch") and a.label and GRAVITY.match(a.label)):
            continue  # the axes, and a sketch's gravity arrow beside the mechanism, belong to no body
        dt, dh = distance(a.tail), distance(a.head)
        if min(dt, dh) > attach:
            defects.append(("detached", f"{arrow_name(fig, k)} {fp(a.tail)}-{fp(a.head)}: tail {fmt_num(dt)} and head "
                                        f"{fmt_num(dh)} from every outline and point"))
    return defects


# ---------------------------------------------------------------------------------------
# What should be drawn


def expected_diagrams(path):
    """(2-D?, the bodies that should have a free body diagram), from the description; None
    where it cannot be read (no PyYAML)."""
    try:
        import yaml  # python3-yaml
    except ImportError:
        return None
    try:
        with open(path) as f:
            d = yaml.safe_load(f)
    except Exception:
        return None
    if not isinstance(d, dict):
        return None
    axes = d.get("axes") or ["x"]
    bodies = d.get("bodies") or {}
    massive = []
    for name, b in bodies.items():
        if isinstance(b, dict) and b.get("mass") not in (None, 0, "0"):
            massive.append(str(name))
    if "derive" in d:
        wanted = set()
        for entry in d.get("derive") or []:
            if isinstance(entry, dict):
                for key in ("lmb", "amb"):
                    v = entry.get(key)
                    if isinstance(v, list):
                        wanted.update(str(x) for x in v)
                    elif v is not None:
                        wanted.add(str(v))
        massive = [b for b in massive if b in wanted]
    return len(axes) == 2, massive


def undrawn(path, captions):
    out = []
    if not captions:
        exp = expected_diagrams(path)
        if exp is None or exp[0] or exp[1]:
            return ["no figure drawn"]
        return []
    exp = expected_diagrams(path)
    if exp is None:
        return []
    two_d, bodies = exp
    if two_d and not any(c.startswith("Sketch") for c in captions):
        out.append("no sketch of the 2-D mechanism")
    for b in bodies:
        if not any(re.search(r"(^|[ ,])" + re.escape(b) + r"($|[ ,])", c.replace("Free body diagram of", ""))
                   for c in captions if not c.startswith("Sketch")):
            out.append(f"no free body diagram of body '{b}'")
    return out


# ---------------------------------------------------------------------------------------


def run(cmd):
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, str(e)
    if r.returncode != 0:
        return None, f"exit {r.returncode}: {r.stderr.strip()[:300]}"
    return r.stdout, None


def measure_text(name, fmt, text, tol_px, attach_units, report, totals, source=None, gap_px=0.0, notes=False):
    """Measures the figures of one output; returns (figures, captions)."""
    figs = []
    if fmt == "svg":
        for k, s in enumerate(svg_figures(text)):
            try:
                figs.append(read_svg_figure(s, k + 1))
            except ET.ParseError as e:
                f = Figure("svg", k + 1, "")
                f.unread.append(f"XML: {e}")
                figs.append(f)
        tol, attach, gap = tol_px, attach_units * PX_PER_UNIT, gap_px
    else:
        pics, em_cm = tikz_figures(text)
        figs = [read_tikz_figure(b, k + 1, cap, em_cm) for k, (b, cap) in enumerate(pics)]
        tol, attach, gap = tol_px / PX_PER_UNIT, attach_units, gap_px / PX_PER_UNIT
    entry = report.setdefault(name, {})
    counts = entry.setdefault(source or fmt, {"figures": 0, "labels": 0, "crossed": 0, "crossed_labels": 0,
                                               "overlap": 0, "detached": 0, "inside": 0, "unread": 0, "worst": []})
    counts["figures"] += len(figs)
    for fig in figs:
        defects = measure(fig, tol, attach, gap)
        counts["labels"] += len(fig.labels)
        counts["unread"] += len(fig.unread)
        crossed_labels = set()
        for kind, msg in defects:
            counts[kind] += 1
            if kind == "crossed":
                crossed_labels.add(msg.split("' crossed")[0])
            totals[kind] = totals.get(kind, 0) + 1
            if kind != "inside" or notes:
                yield f"{name}: figure {fig.index}: {msg} [{source or fmt}: {fig.caption}]"
        counts["crossed_labels"] += len(crossed_labels)
        totals["crossed_labels"] = totals.get("crossed_labels", 0) + len(crossed_labels)
        counted = [d for d in defects if d[0] != "inside"]
        if counted:
            counts["worst"].append({"figure": fig.index, "caption": fig.caption, "defects": len(counted)})
        for u in fig.unread:
            yield f"{name}: figure {fig.index}: note: not read: {u} [{source or fmt}: {fig.caption}]"
    counts["worst"].sort(key=lambda w: -w["defects"])
    totals["figures"] = totals.get("figures", 0) + len(figs)
    totals["labels"] = totals.get("labels", 0) + sum(len(f.labels) for f in figs)
    entry.setdefault("_captions_" + fmt, [f.caption for f in figs])


def main(argv):
    ap = argparse.ArgumentParser(
        description="Legibility of tackle's figures: labels crossed or overlapping, arrows off their body, "
                    "descriptions not drawn.")
    ap.add_argument("tackle", nargs="?", help="the tackle binary (then FILEs are descriptions)")
    ap.add_argument("files", nargs="*", help="description files (.yaml)")
    ap.add_argument("--svg", nargs="*", default=[], help="HTML pages or SVG files to measure as they are")
    ap.add_argument("--tikz", nargs="*", default=[], help="LaTeX documents to measure as they are")
    ap.add_argument("--format", choices=["svg", "tikz", "both"], default="both")
    ap.add_argument("--sheet", action="store_true", help="also measure `sheet FILE --figures --format latex`")
    ap.add_argument("--tolerance", type=float, default=1.0, help="px (SVG; /40 cm in TikZ) a label's box is shrunk by")
    ap.add_argument("--attach", type=float, default=0.1,
                    help="drawing units (cm; 40 px) within which an arrow's end is on an outline or point")
    ap.add_argument("--gap", type=float, default=0.0,
                    help="px (SVG; /40 cm in TikZ): labels closer than this count as overlapping (default 0)")
    ap.add_argument("--json", default="-", help="write the JSON summary here ('-': stdout)")
    ap.add_argument("--quiet", action="store_true", help="no defect lines")
    ap.add_argument("--notes", action="store_true", help="also a line for each arrow inside an outline")
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        return 2 if e.code else 0
    if not a.tackle and not a.svg and not a.tikz:
        ap.print_usage(sys.stderr)
        print("legibility.py: nothing to measure (give TACKLE FILE..., or --svg/--tikz files)", file=sys.stderr)
        return 2
    if a.tackle and not a.files:
        ap.print_usage(sys.stderr)
        print("legibility.py: a tackle binary needs description files", file=sys.stderr)
        return 2
    if a.tackle and not (os.path.isfile(a.tackle) and os.access(a.tackle, os.X_OK)):
        print(f"legibility.py: {a.tackle}: not an executable file", file=sys.stderr)
        return 2
    report, totals, lines = {}, {}, []
    undrawn_count = 0
    errors = 0
    formats = ["svg", "tikz"] if a.format == "both" else [a.format]

    def emit(gen):
        for line in gen:
            lines.append(line)
            if not a.quiet:
                print(line)

    for path in a.files if a.tackle else []:
        captions = {}
        for fmt in formats:
            out, err = run([a.tackle, "derive", path, "--format", "html" if fmt == "svg" else "latex"])
            if err:
                emit([f"{path}: tackle derive ({fmt}) failed: {err}"])
                errors += 1
                report.setdefault(path, {})["error"] = err
                continue
            emit(measure_text(path, fmt, out, a.tolerance, a.attach, report, totals, gap_px=a.gap, notes=a.notes))
            captions[fmt] = report[path].get("_captions_" + fmt, [])
        if a.sheet and "tikz" in formats:
            out, err = run([a.tackle, "sheet", path, "--figures", "--format", "latex"])
            if err:
                emit([f"{path}: tackle sheet failed: {err}"])
                errors += 1
            else:
                emit(measure_text(path, "tikz", out, a.tolerance, a.attach, report, totals, source="sheet-tikz",
                                  gap_px=a.gap, notes=a.notes))
        for fmt, caps in captions.items():
            for msg in undrawn(path, caps):
                undrawn_count += 1
                report[path].setdefault(fmt, {})["undrawn"] = report[path][fmt].get("undrawn", 0) + 1
                emit([f"{path}: figure -: {msg} [{fmt}]"])
    for fmt, paths in (("svg", a.svg), ("tikz", a.tikz)):
        for path in paths:
            try:
                with open(path, encoding="utf-8") as f:
                    text = f.read()
            except OSError as e:
                print(f"legibility.py: {path}: {e}", file=sys.stderr)
                return 2
            emit(measure_text(path, fmt, text, a.tolerance, a.attach, report, totals, gap_px=a.gap, notes=a.notes))
    for entry in report.values():
        for k in [k for k in entry if k.startswith("_captions_")]:
            del entry[k]
        for v in entry.values():
            if isinstance(v, dict):
                v.setdefault("undrawn", 0)
                v["defects"] = v["crossed"] + v["overlap"] + v["detached"] + v["undrawn"]
                v["worst"] = v["worst"][:3]
    totals["undrawn"] = undrawn_count
    totals["errors"] = errors
    for k in ("crossed", "crossed_labels", "overlap", "detached", "inside", "figures", "labels"):
        totals.setdefault(k, 0)
    totals["defects"] = totals["crossed"] + totals["overlap"] + totals["detached"] + totals["undrawn"] + errors
    by_format = {}
    for entry in report.values():
        for src, v in entry.items():
            if isinstance(v, dict):
                bf = by_format.setdefault(src, {"figures": 0, "crossed": 0, "crossed_labels": 0, "overlap": 0,
                                                "detached": 0, "undrawn": 0, "defects": 0, "inside": 0})
                for k in bf:
                    bf[k] += v.get(k, 0)
    summary = {"tolerance_px": a.tolerance, "attach_units": a.attach, "gap_px": a.gap, "totals": totals, "by_format": by_format,
               "files": report}
    text = json.dumps(summary, indent=1, ensure_ascii=False)
    if a.json == "-":
        print(text)
    else:
        with open(a.json, "w") as f:
            f.write(text + "\n")
    return 0 if totals["defects"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
