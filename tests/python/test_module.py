"""The Python module against hand-derived values (run by CTest with the build tree's module
on PYTHONPATH). Sample 12.3: T = 2 F m_B/(9 m_A + 4 m_B) = 20 N at F = 130 N, m_A = m_B = 40 kg;
at F = 120 N it is 9600/520 = 18.4615 N."""
import json
import os
import pickle
import re
import sys
import unittest

import tackle

SOURCE = sys.argv.pop(1) if len(sys.argv) > 1 else "."
EXAMPLES = os.path.join(SOURCE, "examples")


class ModuleTest(unittest.TestCase):
    def setUp(self):
        self.p = tackle.Problem(os.path.join(EXAMPLES, "sample-12.3-two-mass-pulley.yaml"))

    def test_answers(self):
        t = next(a for a in self.p.answers() if a["name"] == "T")
        self.assertEqual(t["closed_form"], "2*F*m_B/(9*m_A + 4*m_B)")
        self.assertAlmostEqual(t["value"], 20.0)
        self.assertEqual(t["unit"], "N")

    def test_derive_formats(self):
        self.assertIn("T = 2*F*m_B/(9*m_A + 4*m_B)", self.p.derive("text"))
        self.assertTrue(self.p.derive("latex").startswith("\\documentclass"))
        self.assertEqual(json.loads(self.p.derive("json"))["status"], "determined")
        with self.assertRaises(ValueError):
            self.p.derive("pdf")

    def test_variant_is_reproducible_and_consistent(self):
        v = self.p.variant(seed=3)
        self.assertEqual(v, self.p.variant(seed=3))
        F = v["parameters"]["F"]["value"]
        m_A = v["parameters"]["m_A"]["value"]
        m_B = v["parameters"]["m_B"]["value"]
        self.assertAlmostEqual(v["answers"]["T"]["value"], 2 * F * m_B / (9 * m_A + 4 * m_B))

    def test_check_with_the_students_numbers(self):
        self.assertEqual(self.p.check("T", "20 N")["verdict"], "correct")
        self.assertEqual(self.p.check("T", "18.46 N", params={"F": 120})["verdict"], "correct")
        wrong = self.p.check("T", "30 N")
        self.assertEqual(wrong["summary"], "not within 1 % of the correct value (got 30 N)")
        self.assertEqual(self.p.check("T", "30 N", reveal=True)["summary"], "expected 20 N within 1 %; got 30 N")
        with self.assertRaises(ValueError):
            self.p.check("T", "20 N", params={"G": 1})

    def test_check_equation(self):
        right = self.p.check_equation("2*T - F = m_A*ddot(x_A)")
        self.assertEqual(right["verdict"], "correct")
        self.assertEqual(right["identified_as"], ["LMB A (x)"])
        wrong = self.p.check_equation("T - F = m_A*ddot(x_A)")
        self.assertEqual(wrong["verdict"], "incorrect")
        self.assertEqual(wrong["findings"][0]["code"], "missing_force")
        self.assertEqual(wrong["summary"], "a strand of string s at pA is missing (LMB A (x))")

    def test_no_equation_ends_a_check(self):
        # Issue "verdicts": these made the grader fail (an internal error); each now has a
        # verdict, and a batch with them grades every line. By hand: T = 2 F m_B/(9 m_A + 4
        # m_B) > 0, so sqrt(T^2) = T holds whatever T is; F/T is not 1; ddot(x_A) is
        # negative (its cube's real cube root is not what is computed); ddot(x_A)/ddot(x_B) =
        # 3/2, whose sine is not 0.
        verdicts = {"sqrt(T^2) = T": "incorrect", "log(F/T) = 0": "incorrect",
                    "(ddot(x_A)^3)^(1/3) = ddot(x_B)": "undecided", "sin(ddot(x_A)/ddot(x_B)) = 0": "incorrect"}
        for text, verdict in verdicts.items():
            self.assertEqual(self.p.check_equation(text)["verdict"], verdict, text)
        lines = "".join(json.dumps({"id": str(i), "equation": t}) + "\n" for i, t in enumerate(verdicts))
        lines += json.dumps({"id": "last", "equation": "2*T - F = m_A*ddot(x_A)"}) + "\n"
        out, _ = self.p.check_batch(lines, results_format="gradescope")
        graded = [json.loads(l) for l in out.splitlines()]
        self.assertEqual([g["verdict"] for g in graded], list(verdicts.values()) + ["correct"])

    def test_check_fbd(self):
        # By hand: B is pulled toward C (left, -x) by three strands of the string at pB.
        right = self.p.check_fbd({"body": "B", "forces": [{"name": "T", "at": "pB", "direction": [-1]}] * 3})
        self.assertEqual(right["verdict"], "correct")
        self.assertEqual(right["score"], 3)
        wrong = self.p.check_fbd("body: B\nforces:\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, at: pB, direction: [1]}\n")
        self.assertEqual(wrong["verdict"], "incorrect")
        self.assertEqual(wrong["findings"][0]["code"], "missing_force")
        self.assertEqual(wrong["findings"][1]["message"], "your T stands for a strand of string s at pB, which points the other way")
        with self.assertRaises(tackle.InputError) as e:
            self.p.check_fbd({"body": "Q", "forces": []})
        self.assertIn("'Q' is not a body of the problem (expected one of: A, B)", str(e.exception))

    def test_check_solution(self):
        grade, results = self.p.check_solution(
            "steps:\n  - fbd: {body: B, forces: [{name: T, at: pB, direction: [-1]}]}\n"
            "  - equation: '-3*T = m_B*ddot(x_B)'\n", rubric="fbds: 1\nbalances: 1\n", results_format="prairielearn")
        self.assertEqual(grade["first_wrong"], 1)
        self.assertEqual([p["name"] for p in grade["parts"]], ["fbds", "balances"])
        self.assertEqual(json.loads(results)["tests"][0]["name"], "step 1: free body diagram of B")

    def test_checkers_kept_across_calls(self):
        # One problem, many calls, with tolerances and reveal changing between them (a checker
        # each, kept; past eight, one made for the call): every verdict as by hand, and the
        # same answer the same verdict each time.
        for k in range(12):
            tolerance = 0.01 + k / 1000
            self.assertEqual(self.p.check("T", "20 N", tolerance=tolerance, reveal=k % 2 == 1)["verdict"], "correct")
            self.assertEqual(self.p.check("T", "30 N", tolerance=tolerance)["verdict"], "incorrect")
            self.assertEqual(self.p.check_equation("%d*T - %d*F = %d*m_A*ddot(x_A)" % (2 * k + 2, k + 1, k + 1))["verdict"], "correct")
            self.assertEqual(self.p.check("T", "2*F*m_B/(9*m_A + 4*m_B)")["verdict"], "correct")
        self.assertEqual(self.p.check("T", "20.5 N", tolerance=0.05)["verdict"], "correct")
        self.assertEqual(self.p.check("T", "20.5 N", tolerance=0.01)["verdict"], "incorrect")
        with self.assertRaises(ValueError):
            self.p.check("T", "20 N", tolerance=2)

    def test_solution_time_limit(self):
        # A limit no check fits in leaves each step not begun undecided (time_limit), none
        # wrong; a generous one grades as without.
        solution = "steps:\n" + "".join("  - equation: '%d*T - %d*F = %d*m_A*ddot(x_A)'\n" % (2 * k, k, k) for k in range(1, 101))
        grade, _ = self.p.check_solution(solution, time_limit=1e-6)
        self.assertEqual((grade["steps"][-1]["verdict"], grade["steps"][-1]["findings"][0]["code"]), ("undecided", "time_limit"))
        self.assertEqual(grade["wrong"], 0)
        self.assertEqual(self.p.check_solution(solution, time_limit=3600)[0], self.p.check_solution(solution)[0])
        with self.assertRaises(ValueError):
            self.p.check_solution(solution, time_limit=-1)

    def test_batch_for_prairielearn(self):
        lines = ('{"id": "a", "unknown": "T", "answer": "2*F*m_B/(9*m_A + 4*m_B)"}\n'
                 '{"id": "b", "unknown": "T", "answer": "3*"}\n')
        out, results = self.p.check_batch(lines, results_format="prairielearn")
        self.assertEqual(len(out.splitlines()), 2)
        r = json.loads(results)
        self.assertFalse(r["gradable"])
        self.assertEqual(len(r["format_errors"]), 1)

    def test_input_errors_and_phases(self):
        with self.assertRaises(tackle.InputError) as e:
            tackle.Problem(os.path.join(SOURCE, "tests/data/bad/17-interval.yaml"))
        self.assertIn("17-interval.yaml:11:3: 'interval' needs exactly one of 'duration' and 'distance'", str(e.exception))
        with self.assertRaises(ValueError):
            tackle.Problem(os.path.join(EXAMPLES, "sample-12.5-pile-driver.yaml"))
        stop = tackle.Problem(os.path.join(EXAMPLES, "sample-12.5-pile-driver.yaml"), phase="stop")
        self.assertAlmostEqual(next(a for a in stop.answers() if a["name"] == "F_s")["value"], 16938.6, places=1)


class DisplayTest(unittest.TestCase):
    """The display in notebooks (Jupyter calls _repr_html_ and _repr_latex_): the problem as one
    HTML fragment with math for the notebook's MathJax, its equations as LaTeX, and results that
    show themselves while staying the dicts and lists they were."""

    def setUp(self):
        self.p = tackle.Problem(os.path.join(EXAMPLES, "sample-12.3-two-mass-pulley.yaml"))

    def test_html_is_a_fragment_of_its_own(self):
        html = self.p._repr_html_()
        own = re.match(r'<div class="tackle" id="(tackle-[0-9a-f]{16})">\n<style>\n', html)
        self.assertIsNotNone(own, html[:80])
        self.assertTrue(html.endswith("</div>\n"))
        self.assertNotRegex(html, r"(?i)<(html|head|body|script|link)\b")
        # Its style and its figures' ids are its own: two problems on one page meet nowhere.
        self.assertTrue(all(line.startswith("#" + own.group(1)) for line in html.split("<style>\n")[1].split("</style>")[0].splitlines()))
        ids = re.findall(r'\bid="([^"]+)"', html)
        self.assertGreater(len(ids), 3)  # the fragment's, the sketch's and two diagrams' arrowheads
        self.assertTrue(all(i.startswith(own.group(1)) for i in ids), ids)
        self.assertEqual(len(set(re.findall(r'url\(#([^)]+)\)', html)) - set(ids)), 0)
        self.assertNotEqual(own.group(1), re.match(r'<div class="tackle" id="([^"]+)"', self.p._repr_html_()).group(1))
        # The title, the sketch and both free body diagrams, the statement's numbers and the
        # answers as math for MathJax (T = 2 F m_B/(9 m_A + 4 m_B) = 20 N by hand).
        self.assertIn("<h3>Sample 12.3: a two-mass pulley system</h3>", html)
        self.assertEqual(html.count('<svg xmlns="http://www.w3.org/2000/svg" class="fbd"'), 4)  # the sketch twice
        self.assertIn("<title>Free body diagram of A</title>", html)
        self.assertIn('<span class="math">\\(130\\,\\mathrm{N}\\)</span>', html)
        self.assertIn('<span class="math display">\\[\\boxed{T = \\frac{2 m_{B} F}{9 m_{A} + 4 m_{B}}} \\quad \\left(= 20\\,\\mathrm{N}\\right)\\]</span>', html)
        self.assertEqual(html.count("<details>"), 1)
        # The page of `derive --format html` is as it was: KaTeX's spans, no delimiters.
        body = self.p.derive("html").split("<body>")[1]
        self.assertIn('<span class="math">F</span>', body)
        self.assertNotIn("\\(", body)
        self.assertIn('<marker id="headFree-body-diagram-of-A"', body)

    def test_latex_is_the_equations(self):
        tex = self.p._repr_latex_()
        self.assertTrue(tex.startswith("\\begin{align*}\n") and tex.endswith("\\end{align*}\n"), tex)
        self.assertIn("  2 T - F &= m_{A} \\ddot{x}_{A} \\tag*{LMB A (x)} \\\\\n", tex)
        self.assertIn("  -3 T &= m_{B} \\ddot{x}_{B} \\tag*{LMB B (x)} \\\\\n", tex)
        self.assertIn("  0 &= 3 \\ddot{x}_{B} - 2 \\ddot{x}_{A} \\tag*{string s: acceleration} \\\\\n", tex)
        answers = self.p.derivation(full=False)._repr_latex_()
        self.assertEqual(answers.count("\\boxed{"), 3)
        self.assertNotIn("\\tag*", answers)

    def test_results_show_themselves_and_stay_dicts(self):
        right = self.p.check("T", "20 N")
        self.assertIsInstance(right, dict)
        self.assertIsInstance(right, tackle.CheckResult)
        plain = dict(right)
        self.assertEqual(right, plain)
        self.assertEqual(json.loads(json.dumps(right)), plain)
        self.assertEqual(pickle.loads(pickle.dumps(right)), plain)
        html = right._repr_html_()
        self.assertIn('data-verdict="correct"', html)
        self.assertIn("#2e7d32", html)
        self.assertIn("\\(\\displaystyle T = 20\\,\\mathrm{N}\\)", html)
        wrong = self.p.check("T", "30 N")._repr_html_()
        self.assertIn('data-verdict="incorrect"', wrong)
        self.assertIn("not within 1 % of the correct value (got 30 N)", wrong)
        # What cannot be read is shown as typed, escaped.
        typed = self.p.check("T", "<b>3*</b>")
        self.assertEqual(typed["verdict"], "invalid")
        self.assertIn("<code>&lt;b&gt;3*&lt;/b&gt;</code>", typed._repr_html_())
        self.assertNotIn("<b>3*", typed._repr_html_())
        equation = self.p.check_equation("T - F = m_A*ddot(x_A)")._repr_html_()
        self.assertIn("\\(\\displaystyle T - F = m_{A} \\ddot{x}_{A}\\)", equation)
        self.assertIn("a strand of string s at pA is missing (LMB A (x))", equation)
        fbd = self.p.check_fbd({"body": "B", "forces": [{"name": "T", "at": "pB", "direction": [-1]}] * 2})
        self.assertIsInstance(fbd, tackle.FbdGrade)
        self.assertEqual(fbd._repr_html_().count(">drawn as your T</td>"), 2)
        self.assertEqual(fbd._repr_html_().count(">missing</td>"), 1)
        grade, results = self.p.check_solution("steps:\n  - equation: '-3*T = m_B*ddot(x_B)'\n  - {unknown: T, answer: 20 N}\n")
        self.assertIsInstance(grade, tackle.SolutionGrade)
        self.assertIsInstance(results, str)
        self.assertEqual(grade._repr_html_().count('data-verdict="correct"'), 2)

    def test_answers_variant_and_derivation(self):
        answers = self.p.answers()
        self.assertIsInstance(answers, list)
        self.assertEqual([a["name"] for a in answers], ["T", "ddot(x_A)", "ddot(x_B)"])
        html = answers._repr_html_()
        self.assertEqual(html.count("<tr>"), 4)
        self.assertIn("\\(\\ddot{x}_{A}\\)", html)
        self.assertIn("\\(-2.25\\,\\mathrm{m/s^{2}}\\)", html)
        v = self.p.variant(3)
        self.assertEqual(v, self.p.variant(seed=3))
        self.assertIn("variant of seed 3", v._repr_html_())
        self.assertIn("\\(170\\,\\mathrm{N}\\)", v._repr_html_())
        self.assertIsNone(tackle.Problem(os.path.join(EXAMPLES, "incline-and-hanging-block.yaml")).variant(seed=1))
        d = self.p.derivation()
        self.assertEqual(str(d), self.p.derive("text"))
        self.assertEqual(repr(d), self.p.derive("text"))
        self.assertNotIn("<details>", d._repr_html_())
        self.assertEqual(d._repr_html_().count('class="fbd"'), 3)
        self.assertEqual(self.p.derivation(full=False)._repr_html_().count("\\boxed{"), 3)
        with self.assertRaises(ValueError):
            self.p._notebook_html("page")
        self.assertEqual(repr(self.p), "<tackle.Problem: Sample 12.3: a two-mass pulley system>")

    def test_a_phase_shows_itself(self):
        stop = tackle.Problem(os.path.join(EXAMPLES, "sample-12.5-pile-driver.yaml"), phase="stop")
        self.assertIn("<h3>Sample 12.5", stop._repr_html_())
        self.assertIn("stop", re.search(r"<h3>.*</h3>", stop._repr_html_()).group(0))


if __name__ == "__main__":
    unittest.main()
