"""The PrairieLearn question and the Gradescope autograder in examples/, driven with the data
shapes the platforms document (no platform needed). Sample 12.3: T = 2 F m_B/(9 m_A + 4 m_B).
Usage: test_platforms.py SOURCE_DIR TACKLE_PROGRAM"""
import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import unittest

SOURCE = sys.argv.pop(1)
TACKLE = sys.argv.pop(1)


def load_server():
    path = os.path.join(SOURCE, "examples/prairielearn/pulley-tension/server.py")
    spec = importlib.util.spec_from_file_location("server", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def new_data():
    return {"params": {}, "correct_answers": {}, "submitted_answers": {}, "format_errors": {},
            "partial_scores": {}, "score": 0.0, "feedback": {}}


class PrairieLearnTest(unittest.TestCase):
    def test_generate_parse_grade(self):
        server = load_server()
        data = new_data()
        server.generate(data)
        self.assertEqual(sorted(data["params"]), ["F", "m_A", "m_B"])
        F, m_A, m_B = data["params"]["F"], data["params"]["m_A"], data["params"]["m_B"]
        T = 2 * F * m_B / (9 * m_A + 4 * m_B)
        self.assertIn("N", data["correct_answers"]["T"])
        # The closed form, and the number at this variant's values: both correct.
        for answer in ("2*F*m_B/(9*m_A + 4*m_B)", "%.5g N" % T):
            data["submitted_answers"] = {"T": answer}
            data["format_errors"] = {}
            server.parse(data)
            self.assertEqual(data["format_errors"], {})
            server.grade(data)
            self.assertEqual(data["score"], 1.0, answer)
        # A wrong number: no points, and the feedback does not give the answer away.
        data["submitted_answers"] = {"T": "%.5g N" % (2 * T)}
        server.grade(data)
        self.assertEqual(data["score"], 0.0)
        self.assertEqual(data["partial_scores"]["T"]["score"], 0.0)
        self.assertNotIn("%.4g" % T, data["feedback"]["T"])
        # An answer tackle cannot read: a format error, so no attempt is charged.
        data["submitted_answers"] = {"T": "2*F*"}
        data["format_errors"] = {}
        server.parse(data)
        self.assertIn("T", data["format_errors"])


class GradescopeTest(unittest.TestCase):
    def run_autograder(self, answers):
        root = tempfile.mkdtemp()
        if answers is not None:
            os.makedirs(os.path.join(root, "submission"))
            with open(os.path.join(root, "submission/answers.json"), "w") as f:
                f.write(answers)
        env = dict(os.environ, AUTOGRADER=root, TACKLE=TACKLE)
        subprocess.run([os.path.join(SOURCE, "examples/gradescope/pulley-tension/run_autograder")], env=env, check=True)
        with open(os.path.join(root, "results/results.json")) as f:
            return json.load(f)

    def test_results(self):
        r = self.run_autograder('{"T": "2*F*m_B/(9*m_A + 4*m_B)"}')
        self.assertNotIn("score", r)  # Gradescope sums the tests
        self.assertEqual(r["tests"][0]["score"], 10)
        self.assertEqual(r["tests"][0]["max_score"], 10)
        wrong = self.run_autograder('{"T": "30 N"}')
        self.assertEqual(wrong["tests"][0]["score"], 0)
        self.assertNotIn("20 N", wrong["tests"][0]["output"])
        self.assertEqual(self.run_autograder(None)["tests"], [])
        # Only T is asked: a right answer for another unknown of the problem, or T twice,
        # earns nothing more than the one test of T.
        extra = self.run_autograder('{"T": "2*F*m_B/(9*m_A + 4*m_B)", "ddot(x_A)": "-9*F/(9*m_A + 4*m_B)", '
                                    '"T": "2*F*m_B/(9*m_A + 4*m_B)"}')
        self.assertEqual([t["name"] for t in extra["tests"]], ["answers.json: T"])
        self.assertEqual(sum(t["score"] for t in extra["tests"]), 10)


class ScaleOutTest(unittest.TestCase):
    def test_split_and_merge_equals_one_run(self):
        # Grading is a pure function of (problem, variant, answer): JSON Lines split across
        # workers and joined in order give the same results as one run (each line has an id).
        answers = ["2*F*m_B/(9*m_A + 4*m_B)", "20 N", "30 N", "2*F*", "F*m_B/(9*m_A + 4*m_B)", "20"]
        lines = "".join(json.dumps({"id": "s%d" % i, "unknown": "T", "answer": answers[i % len(answers)],
                                    "params": {"F": 100 + i}}) + "\n" for i in range(40))
        problem = os.path.join(SOURCE, "examples/sample-12.3-two-mass-pulley.yaml")

        def run(text):
            return subprocess.run([TACKLE, "check", problem, "--batch", "-"], input=text, capture_output=True,
                                  text=True, check=True).stdout

        whole = run(lines)
        split = lines.splitlines(keepends=True)
        merged = "".join(run("".join(split[k:k + 10])) for k in range(0, len(split), 10))
        self.assertEqual(whole, merged)
        self.assertEqual(len(whole.splitlines()), 40)


if __name__ == "__main__":
    unittest.main()
