#!/usr/bin/env python3
"""Self test of the legibility measure (tests/figures/legibility.py): small hand-written SVG
and TikZ figures, written as tackle writes them, whose defects are known, so that the measure
is seen to fail where it should and to pass where it should.

    python3 tests/figures/legibility_selftest.py        (exit 0 when every case holds)

Python 3 standard library only (the `undrawn` cases are skipped without PyYAML).
"""
import io
import json
import os
import subprocess
import sys
import tempfile
import importlib.util
import unittest
from contextlib import redirect_stdout

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import legibility as L  # noqa: E402

MARKER = ('<defs><marker id="h" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" '
          'orient="auto-start-reverse"><path d="M 0 0 L 10 5 L 0 10 z" fill="black"/></marker></defs>\n')


def svg(body, caption="Free body diagram of A"):
    return ('<svg xmlns="http://www.w3.org/2000/svg" class="fbd" width="300" height="200" viewBox="-4 -4 300 200" '
            f'role="img" aria-label="{caption}">\n<title>{caption}</title>\n' + MARKER + body + "</svg>\n")


def text(x, y, content, length):
    return (f'<text x="{x}" y="{y}" textLength="{length}" lengthAdjust="spacingAndGlyphs" text-anchor="middle" '
            f'font-family="serif" font-style="italic" font-size="14">{content}</text>\n')


BLOCK = '<polygon points="100,120 140,120 140,80 100,80" fill="#ebebeb" stroke="black" stroke-width="1.6"/>\n'
DOT = '<circle cx="120" cy="100" r="2.5" fill="black"/>\n'
# T leaves the top of the block, its label above its head; m g leaves the bottom.
ARROW_T = ('<line x1="120" y1="80" x2="120" y2="30" stroke="black" stroke-width="2" marker-end="url(#h)"/>\n'
           + text(120, 18, "T", 9.6))
ARROW_W = ('<line x1="120" y1="120" x2="120" y2="170" stroke="black" stroke-width="2" marker-end="url(#h)"/>\n'
           + text(120, 190, "m g", 21.56))
AXES = ('<line x1="6" y1="180" x2="38" y2="180" stroke="black" stroke-width="1" marker-end="url(#h)"/>\n'
        + text(48, 184, "x", 7.28))
CLEAN = BLOCK + DOT + ARROW_T + ARROW_W + AXES


def tikz(body, caption="Free body diagram of A"):
    return ("\\documentclass[11pt]{article}\n\\begin{document}\n"
            "\\begin{center}\n\\begin{minipage}{\\linewidth}\\centering\n"
            "\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!}{%\n"
            "\\begin{tikzpicture}[>=stealth, line cap=round, line join=round]\n"
            "  \\providecommand{\\tacklelabel}[3]{\\setbox0=\\hbox{#3}\\pgfmathsetmacro{\\tacklescale}{min(1, "
            "#1/max(\\the\\wd0, 0.01pt), #2/max(\\the\\dimexpr\\ht0+\\dp0\\relax, 0.01pt))}\\scalebox{\\tacklescale}"
            "{\\box0}}\n" + body + "\\end{tikzpicture}\n}\\\\[2pt]{\\small " + caption + "}\n"
            "\\end{minipage}\n\\end{center}\n\\end{document}\n")


def node(x, y, tex, w="0.52cm", h="0.42cm"):
    return f"  \\node[font=\\small, inner sep=0pt] at ({x},{y}) {{\\tacklelabel{{{w}}}{{{h}}}{{${tex}$}}}};\n"


T_BLOCK = "  \\filldraw[fill=black!8, draw=black, thick] (0.5,-0.5) -- (0.5,0.5) -- (-0.5,0.5) -- (-0.5,-0.5) -- cycle;\n"
T_DOT = "  \\fill (0,0) circle (1.5pt);\n"
T_ARROW_T = "  \\draw[->, very thick] (0,0.5) -- (0,1.7);\n" + node(0, 2.0, "T", "0.32cm")
T_ARROW_W = "  \\draw[->, very thick] (0,-0.5) -- (0,-1.7);\n" + node(0, -2.0, "m g", "0.92cm")
T_AXES = "  \\draw[->, thin] (-2,-2) -- (-1.2,-2);\n" + node(-0.95, -2, "x", "0.32cm")
T_CLEAN = T_BLOCK + T_DOT + T_ARROW_T + T_ARROW_W + T_AXES


def measure_svg(body, caption="Free body diagram of A"):
    figs = [L.read_svg_figure(s, k + 1) for k, s in enumerate(L.svg_figures(svg(body, caption)))]
    return [d for f in figs for d in L.measure(f, 1.0, 0.1 * L.PX_PER_UNIT)], figs


def measure_tikz(body, caption="Free body diagram of A"):
    pics, em = L.tikz_figures(tikz(body, caption))
    figs = [L.read_tikz_figure(b, k + 1, c, em) for k, (b, c) in enumerate(pics)]
    return [d for f in figs for d in L.measure(f, 1.0 / L.PX_PER_UNIT, 0.1)], figs


def kinds(defects):
    return sorted(k for k, _ in defects)


class Svg(unittest.TestCase):
    def test_clean_figure_has_no_defect(self):
        d, figs = measure_svg(CLEAN)
        self.assertEqual(d, [])
        self.assertEqual(len(figs), 1)
        self.assertEqual(len(figs[0].labels), 3)
        self.assertEqual(figs[0].unread, [])

    def test_label_crossed_by_a_line(self):
        # a string drawn straight through T's label
        line = '<polyline points="80,14 160,14" fill="none" stroke="black" stroke-width="1.6"/>\n'
        d, _ = measure_svg(CLEAN + line)
        self.assertEqual(kinds(d), ["crossed"])
        self.assertIn("label 'T' crossed by line (80,14)-(160,14)", d[0][1])

    def test_line_that_misses_the_label(self):
        line = '<polyline points="80,40 160,40" fill="none" stroke="black" stroke-width="1.6"/>\n'
        d, _ = measure_svg(CLEAN.replace(ARROW_T, "") + line)
        self.assertEqual(d, [])

    def test_two_labels_overlapping(self):
        d, _ = measure_svg(CLEAN + text(200, 60, "N<tspan baseline-shift=\"sub\" font-size=\"70%\">A</tspan>", 16.66)
                           + text(208, 62, "F", 9.6))
        self.assertEqual(kinds(d), ["overlap"])
        self.assertIn("labels 'N_A' and 'F' overlap", d[0][1])

    def test_label_on_an_outline(self):
        # a point's name astride the block's left edge (as in the incline's B)
        d, _ = measure_svg(CLEAN + text(100, 104, "B", 9.6))
        self.assertEqual(kinds(d), ["crossed"])
        self.assertIn("label 'B' crossed by outline (100,80)-(100,120)", d[0][1])

    def test_label_inside_a_disk_is_not_crossed_but_one_on_its_rim_is(self):
        disk = '<circle cx="220" cy="100" r="40" fill="#ebebeb" stroke="black" stroke-width="1.6"/>\n'
        d, _ = measure_svg(CLEAN + disk + text(220, 104, "C", 9.6))
        self.assertEqual(d, [])
        d, _ = measure_svg(CLEAN + disk + text(260, 104, "C", 9.6))
        self.assertEqual(kinds(d), ["crossed"])
        self.assertIn("outline circle (220,100) r 40", d[0][1])

    def test_label_touching_its_own_arrow_head(self):
        # T's label moved down onto its arrow's head
        d, _ = measure_svg(CLEAN.replace(text(120, 18, "T", 9.6), text(120, 36, "T", 9.6)))
        self.assertEqual(kinds(d), ["crossed"])
        self.assertIn("arrow 'T' (its own)", d[0][1])

    def test_arrow_away_from_the_body(self):
        # a force drawn beside the block, touching neither its outline nor a point
        arrow = ('<line x1="200" y1="60" x2="250" y2="60" stroke="black" stroke-width="2" marker-end="url(#h)"/>\n'
                 + text(268, 64, "F", 9.6))
        d, _ = measure_svg(CLEAN + arrow)
        self.assertEqual(kinds(d), ["detached"])
        # distances in the figure's units (px): to the block's nearest corner, (140,80)
        self.assertIn("arrow 'F' (200,60)-(250,60): tail 63.25 and head 111.8 from every outline and point", d[0][1])

    def test_arrow_leaving_the_center_of_mass_is_attached(self):
        arrow = ('<line x1="120" y1="100" x2="200" y2="100" stroke="black" stroke-width="2" stroke-dasharray="6 4" '
                 'marker-end="url(#h)"/>\n' + text(220, 104, "m a", 21.0))
        d, _ = measure_svg(CLEAN + arrow)
        self.assertEqual(d, [])

    def test_an_arrow_inside_its_outline_is_a_note_not_a_defect(self):
        big = '<polygon points="20,150 220,150 220,60 20,60" fill="#ebebeb" stroke="black" stroke-width="1.6"/>\n'
        arrow = ('<line x1="60" y1="100" x2="100" y2="100" stroke="black" stroke-width="2" marker-end="url(#h)"/>\n'
                 + text(80, 120, "P", 9.6) + '<circle cx="60" cy="100" r="2.5" fill="black"/>\n')
        d, _ = measure_svg(big + arrow)
        self.assertEqual(kinds(d), ["inside"])
        with tempfile.TemporaryDirectory() as tmp:
            page = os.path.join(tmp, "inside.html")
            with open(page, "w") as f:
                f.write(svg(big + arrow))
            out = io.StringIO()
            with redirect_stdout(out):
                code = L.main(["--svg", page])
            self.assertEqual(code, 0)
            self.assertEqual(json.loads(out.getvalue())["totals"]["inside"], 1)

    def test_axes_and_a_sketchs_gravity_arrow_are_not_detached(self):
        g = ('<line x1="250" y1="20" x2="250" y2="60" stroke="black" stroke-width="2" marker-end="url(#h)"/>\n'
             + text(262, 40, "g", 7.28))
        d, _ = measure_svg(CLEAN + g, caption="Sketch of the mechanism")
        self.assertEqual(d, [])
        d, _ = measure_svg(CLEAN + g)  # in a free body diagram it is a force like any other
        self.assertEqual(kinds(d), ["detached"])

    def test_couple_arc_crossing_a_label(self):
        arc = ('<path d="M 140 134.64 A 40 40 0 1 0 80 100" fill="none" stroke="black" stroke-width="2" '
               'marker-end="url(#h)"/>\n' + text(60, 150, "M<tspan baseline-shift=\"sub\" font-size=\"70%\">0</tspan>",
                                                   16.0))
        # the arc runs from below-right of the block's centre, over its top (120,60), to its left
        d, _ = measure_svg(CLEAN.replace(ARROW_T, "").replace(ARROW_W, "") + arc + text(120, 144, "W", 12))
        self.assertEqual(d, [])  # under the centre, where the arc does not go
        d, _ = measure_svg(CLEAN.replace(ARROW_T, "").replace(ARROW_W, "") + arc + text(120, 64, "W", 12))
        self.assertIn("crossed", kinds(d))
        self.assertTrue(any("label 'W' crossed by couple 'M_0'" in m for _, m in d), d)

    def test_accent_dots_name_their_letter_and_join_the_box(self):
        # m ẍ as tackle writes it: the text, then its two dots over the x
        label = text(200, 60, "m\u2009x", 22.68) + ('<circle cx="209.3" cy="47.4" r="1.05" fill="black"/>\n'
                                                    '<circle cx="212.9" cy="47.4" r="1.05" fill="black"/>\n')
        arrow = '<line x1="140" y1="100" x2="190" y2="70" stroke="black" stroke-width="2" marker-end="url(#h)"/>\n'
        d, figs = measure_svg(CLEAN + arrow + label)
        self.assertEqual(figs[0].labels[-1].text, "m x\u0308")
        self.assertLess(figs[0].labels[-1].box[1], 47.4 - 1.0)  # the dots are inside the label's box
        # a line through the dots (above the letters) crosses the label
        line = '<polyline points="190,48 230,48" fill="none" stroke="black" stroke-width="1.6"/>\n'
        d, _ = measure_svg(CLEAN + arrow + label + line)
        self.assertEqual(kinds(d), ["crossed"])

    def test_figures_are_found_by_their_class_only(self):
        page = ("<html><script>var s='<svg xmlns=\"http://www.w3.org/2000/svg\">';</script>"
                + svg(CLEAN) + '<svg xmlns="http://www.w3.org/2000/svg" class="plot"><line x1="0" y1="0" x2="1" '
                'y2="1"/></svg></html>')
        self.assertEqual(len(L.svg_figures(page)), 1)


class Tikz(unittest.TestCase):
    def test_clean_figure_has_no_defect(self):
        d, figs = measure_tikz(T_CLEAN)
        self.assertEqual(d, [])
        self.assertEqual(len(figs), 1)
        self.assertEqual(figs[0].caption, "Free body diagram of A")
        self.assertEqual(len(figs[0].labels), 3)
        self.assertEqual(len(figs[0].polygons), 1)
        self.assertEqual(figs[0].unread, [])

    def test_label_crossed_by_a_line(self):
        d, _ = measure_tikz(T_CLEAN + "  \\draw[thick] (-1,2) -- (1,2);\n")
        self.assertEqual(kinds(d), ["crossed"])
        self.assertIn("label 'T' crossed by line (-1,2)-(1,2)", d[0][1])

    def test_two_labels_overlapping(self):
        d, _ = measure_tikz(T_CLEAN + node(2, 1, "N_{A}") + node(2.15, 1.05, "F", "0.32cm"))
        self.assertEqual(kinds(d), ["overlap"])
        self.assertIn("labels 'N_A' and 'F' overlap", d[0][1])

    def test_label_on_an_outline(self):
        d, _ = measure_tikz(T_CLEAN + node(-0.5, 0.1, "B", "0.32cm"))
        self.assertEqual(kinds(d), ["crossed"])
        self.assertIn("label 'B' crossed by outline (-0.5,0.5)-(-0.5,-0.5)", d[0][1])

    def test_arrow_away_from_the_body(self):
        d, _ = measure_tikz(T_CLEAN + "  \\draw[->, very thick] (1.5,1) -- (2.5,1);\n" + node(2.8, 1, "F", "0.32cm"))
        self.assertEqual(kinds(d), ["detached"])
        self.assertIn("arrow 'F' (1.5,1)-(2.5,1): tail 1.12 and head 2.06 from every outline and point", d[0][1])

    def test_couple_arc_and_its_label(self):
        arc = ("  \\draw[->, thick, dashed] (0.4,-0.693) arc[start angle=-60, end angle=240, radius=0.8];\n"
               + node(0, 0.8, "\\frac{m R^{2} \\ddot{\\phi}}{2}", "1.2cm", "0.6cm"))
        d, figs = measure_tikz(T_CLEAN.replace(T_ARROW_T, "") + arc)
        self.assertEqual(figs[0].couples[0][2], "m R^2 φ̈/2")
        self.assertTrue(any("crossed by couple 'm R^2 φ̈/2'" in m for _, m in d), d)

    def test_tacklelabel_scales_the_text_into_its_box(self):
        # a long label in a small box: scaled down to the box's width and height
        _, box = L.tikz_node_box("\\tacklelabel{0.5cm}{0.42cm}{$m l \\dot{\\theta}^{2} \\sin(\\theta)$}", (0, 0),
                                 10 * L.PT_CM)
        self.assertAlmostEqual(box[2] - box[0], 0.5, places=6)
        self.assertLess(box[3] - box[1], 0.42)
        shown, _ = L.tex_label("$m l \\dot{\\theta}^{2} \\sin(\\theta)$")
        self.assertEqual(shown, "m l θ̇^2 sin(θ)")

    def test_plots_are_not_figures(self):
        doc = tikz(T_CLEAN) + "\\begin{tikzpicture}\\begin{axis}\\addplot coordinates {(0,0) (1,1)};\\end{axis}" \
                              "\\end{tikzpicture}"
        pics, _ = L.tikz_figures(doc)
        self.assertEqual(len(pics), 1)

    def test_unknown_commands_are_counted_not_ignored(self):
        _, figs = measure_tikz(T_CLEAN + "  \\shade (0,0) circle (1);\n")
        self.assertEqual(len(figs[0].unread), 1)


class Geometry(unittest.TestCase):
    def test_segment_and_box(self):
        box = (0, 0, 10, 10)
        self.assertTrue(L.box_hits_segment(box, (-5, 5), (15, 5)))  # through
        self.assertTrue(L.box_hits_segment(box, (5, 5), (20, 20)))  # from inside
        self.assertFalse(L.box_hits_segment(box, (-5, 12), (15, 12)))  # above
        self.assertFalse(L.box_hits_segment(box, (11, -5), (30, 5)))  # beside
        self.assertTrue(L.box_hits_segment(box, (-1, 5), (5, -1)))  # across a corner

    def test_circle_rim_and_box(self):
        self.assertFalse(L.box_hits_circle_rim((-1, -1, 1, 1), (0, 0), 10))  # inside the disk
        self.assertTrue(L.box_hits_circle_rim((9, -1, 11, 1), (0, 0), 10))  # on the rim
        self.assertFalse(L.box_hits_circle_rim((12, -1, 14, 1), (0, 0), 10))  # outside

    def test_arc_sampling(self):
        pts = L.arc_points(10, 0, 10, 10, 0, 1, 0, 10)  # a quarter circle about the origin
        self.assertTrue(all(abs((x * x + y * y) ** 0.5 - 10) < 1e-9 for x, y in pts))


class CommandLine(unittest.TestCase):
    def run_cli(self, *args):
        out = io.StringIO()
        with redirect_stdout(out):
            code = L.main(list(args))
        return code, out.getvalue()

    def test_exit_status_and_report(self):
        with tempfile.TemporaryDirectory() as tmp:
            clean = os.path.join(tmp, "clean.html")
            bad = os.path.join(tmp, "bad.html")
            tex = os.path.join(tmp, "bad.tex")
            with open(clean, "w") as f:
                f.write(svg(CLEAN))
            with open(bad, "w") as f:
                f.write(svg(CLEAN + '<polyline points="80,14 160,14" fill="none" stroke="black"/>\n'))
            with open(tex, "w") as f:
                f.write(tikz(T_CLEAN + node(-0.5, 0.1, "B", "0.32cm")))
            code, out = self.run_cli("--svg", clean)
            self.assertEqual(code, 0)
            self.assertEqual(json.loads(out)["totals"]["defects"], 0)
            code, out = self.run_cli("--svg", bad, "--tikz", tex)
            self.assertEqual(code, 1)
            lines = out.split("\n{")[0].splitlines()
            self.assertEqual(lines[0], f"{bad}: figure 1: label 'T' crossed by line (80,14)-(160,14) "
                                       "[svg: Free body diagram of A]")
            self.assertTrue(lines[1].startswith(f"{tex}: figure 1: label 'B' crossed by outline"))
            summary = json.loads("{" + out.split("\n{", 1)[1])
            self.assertEqual(summary["totals"]["crossed"], 2)
            self.assertEqual(summary["files"][bad]["svg"]["crossed"], 1)
            self.assertEqual(summary["files"][tex]["tikz"]["crossed"], 1)

    def test_usage_errors(self):
        err = io.StringIO()
        from contextlib import redirect_stderr
        with redirect_stderr(err):
            self.assertEqual(self.run_cli()[0], 2)
            self.assertEqual(self.run_cli("/nonexistent/tackle", "x.yaml")[0], 2)
            self.assertEqual(self.run_cli("--bogus")[0], 2)
        r = subprocess.run([sys.executable, os.path.join(HERE, "legibility.py")], capture_output=True)
        self.assertEqual(r.returncode, 2)


@unittest.skipUnless(L.expected_diagrams.__module__ and importlib.util.find_spec("yaml"),
                     "PyYAML is needed to read which bodies need a diagram")
class Undrawn(unittest.TestCase):
    def description(self, text):
        f = tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False)
        f.write(text)
        f.close()
        self.addCleanup(os.unlink, f.name)
        return f.name

    def test_a_body_without_its_diagram_and_a_plane_without_its_sketch(self):
        path = self.description("title: t\naxes: [x, y]\nbodies:\n  A: {mass: m}\n  B: {mass: m}\n  P: {mass: 0}\n")
        self.assertEqual(L.undrawn(path, ["Sketch of the mechanism", "Free body diagram of A",
                                          "Free body diagram of B"]), [])
        self.assertEqual(L.undrawn(path, ["Free body diagram of A"]),
                         ["no sketch of the 2-D mechanism", "no free body diagram of body 'B'"])
        self.assertEqual(L.undrawn(path, []), ["no figure drawn"])

    def test_a_system_diagram_counts_for_its_bodies_and_derive_limits_them(self):
        path = self.description("title: t\naxes: [x]\nbodies:\n  car1: {mass: m}\n  car2: {mass: m}\n"
                                "derive:\n  - {lmb: [car1, car2]}\n")
        self.assertEqual(L.undrawn(path, ["Free body diagram of the system car1 and car2"]), [])
        path = self.description("title: t\naxes: [x]\nbodies:\n  A: {mass: m}\n  B: {mass: m}\n"
                                "derive:\n  - {lmb: A}\n")
        self.assertEqual(L.undrawn(path, ["Free body diagram of A"]), [])


if __name__ == "__main__":
    unittest.main(verbosity=1)
