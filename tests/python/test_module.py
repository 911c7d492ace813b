"""The Python module against hand-derived values (run by CTest with the build tree's module
on PYTHONPATH). Sample 12.3: T = 2 F m_B/(9 m_A + 4 m_B) = 20 N at F = 130 N, m_A = m_B = 40 kg;
at F = 120 N it is 9600/520 = 18.4615 N."""
import json
import os
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


if __name__ == "__main__":
    unittest.main()
