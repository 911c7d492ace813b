"""The PrairieLearn questions and the Gradescope autograders in examples/, driven with the data
shapes the platforms document (no platform needed), the step server (scripts/step-server) and
the page it serves, in headless Chromium.

Sample 12.3 by hand (the example's notes): LMB A: 2 T - F = m_A ddot(x_A); LMB B:
-3 T = m_B ddot(x_B); the string's length 3 x_B - 2 x_A = const, so 3 ddot(x_B) = 2 ddot(x_A);
T = 2 F m_B/(9 m_A + 4 m_B) (20 N at F = 130 N, m_A = m_B = 40 kg). The free body diagrams (A at
x_A = -1 left of the fixed pulley C at 0, B at x_B = 1 right of it): A has two strands at pA
pulling toward +x (to C) and F at A toward -x; B three strands at pB pulling toward -x.
Usage: test_platforms.py SOURCE_DIR TACKLE_PROGRAM"""
import http.client
import importlib.util
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest
import urllib.parse

SOURCE = sys.argv.pop(1)
TACKLE = sys.argv.pop(1)


def load_server(question="pulley-tension"):
    path = os.path.join(SOURCE, "examples/prairielearn", question, "server.py")
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


# A worked solution of sample 12.3, by hand (above): each step correct.
LMB_A = "2*T - F = m_A*ddot(x_A)"
LMB_B = "-3*T = m_B*ddot(x_B)"
LENGTH = "3*x_B - 2*x_A = const"
ACCELERATION = "3*ddot(x_B) = 2*ddot(x_A)"
T_CLOSED = "2*F*m_B/(9*m_A + 4*m_B)"
# ... and wrong ones: B's balance with one strand of the three missing.
LMB_B_TWO_STRANDS = "-2*T = m_B*ddot(x_B)"
FBD_A = {"body": "A", "forces": [{"name": "T", "at": "pA", "direction": [1]}, {"name": "T", "at": "pA", "direction": [1]},
                                 {"name": "F", "at": "A", "direction": [-1]}]}
FBD_B = {"body": "B", "forces": [{"name": "T", "at": "pB", "direction": [-1]}] * 3}


class PrairieLearnSolutionTest(unittest.TestCase):
    """examples/prairielearn/pulley-solution: the steps in step1..step6, T, graded as a whole with
    its rubric (balances 4, constraints 2, answers 4)."""

    def submit(self, server, answers):
        data = new_data()
        server.generate(data)
        data["submitted_answers"] = dict({"step%d" % k: "" for k in range(1, 7)}, **answers)
        server.parse(data)
        if not data["format_errors"]:
            server.grade(data)
        return data

    def test_generate(self):
        server = load_server("pulley-solution")
        data = new_data()
        server.generate(data)
        # The description's numbers, and T there: 2*130*40/(9*40 + 4*40) = 20 N.
        self.assertEqual(data["params"], {"F": 130, "m_A": 40, "m_B": 40})
        self.assertEqual(data["correct_answers"]["T"], "20 N")

    def test_whole_solution(self):
        server = load_server("pulley-solution")
        data = self.submit(server, {"step1": LMB_A, "step2": LMB_B, "step3": LENGTH, "step4": ACCELERATION, "T": T_CLOSED})
        self.assertEqual(data["format_errors"], {})
        self.assertEqual(data["score"], 1.0)
        for name in ("step1", "step2", "step3", "step4", "T"):
            self.assertEqual(data["partial_scores"][name]["score"], 1.0, name)
        self.assertIn("LMB A (x)", data["feedback"]["step1"])
        self.assertIn("Missing (needed for T): none", data["feedback"]["solution"])

    def test_partial_solution(self):
        server = load_server("pulley-solution")
        # LMB A right, B's balance a strand short, no constraint, T right as a number: balances
        # 1 of 2 (2 of 4 points), constraints 0 of 1 (0 of 2), answers 1 of 1 (4 of 4): 6 of 10,
        # less the wrong step's share, 10 points over twice the 4 items: 4.75 of 10.
        data = self.submit(server, {"step1": LMB_A, "step2": LMB_B_TWO_STRANDS, "T": "20 N"})
        self.assertEqual(data["format_errors"], {})
        self.assertAlmostEqual(data["score"], 0.475)
        self.assertIn("1 incorrect step: -1.25", data["feedback"]["solution"])
        self.assertEqual(data["partial_scores"]["step2"]["score"], 0.0)
        self.assertIn("a strand of string s at pB is missing", data["feedback"]["step2"])
        self.assertNotIn("3*T", data["feedback"]["step2"])  # never the correct equation
        self.assertIn("LMB B (x)", data["feedback"]["solution"])
        self.assertIn("string s: acceleration", data["feedback"]["solution"])
        # Nothing written but T: the answer's points only; and T restated as an equation as well:
        # still the answer's points only (it is derived from the balances, not written as them).
        data = self.submit(server, {"T": T_CLOSED})
        self.assertAlmostEqual(data["score"], 0.4)
        data = self.submit(server, {"step1": "T = " + T_CLOSED, "T": T_CLOSED})
        self.assertAlmostEqual(data["score"], 0.4)
        self.assertIn("it earns no balance or constraint points", data["feedback"]["step1"])
        # Nothing at all: nothing.
        self.assertEqual(self.submit(server, {})["score"], 0.0)

    def test_unreadable_steps_are_format_errors(self):
        server = load_server("pulley-solution")
        data = self.submit(server, {"step1": LMB_A, "step2": "2*T - F", "step3": "2*T = Q", "T": "2*F*"})
        self.assertEqual(sorted(data["format_errors"]), ["T", "step2", "step3"])
        self.assertIn("=", data["format_errors"]["step2"])
        self.assertEqual(data["partial_scores"], {})  # not graded: no attempt charged


class GradescopeSolutionTest(unittest.TestCase):
    """examples/gradescope/pulley-solution: solution.yaml graded with its rubric (fbds 2,
    balances 3, constraints 2, answers 3)."""

    def run_autograder(self, solution):
        root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, root)
        if solution is not None:
            os.makedirs(os.path.join(root, "submission"))
            with open(os.path.join(root, "submission/solution.yaml"), "w") as f:
                f.write(solution if isinstance(solution, str) else json.dumps({"steps": solution}, indent=1))
        env = dict(os.environ, AUTOGRADER=root, TACKLE=TACKLE)
        subprocess.run([os.path.join(SOURCE, "examples/gradescope/pulley-solution/run_autograder")], env=env, check=True)
        with open(os.path.join(root, "results/results.json")) as f:
            return json.load(f)

    def parts(self, results):
        return {t["name"]: t["score"] for t in results["tests"] if not t["name"].startswith("step ")}

    def test_whole_solution(self):
        r = self.run_autograder([{"fbd": FBD_A}, {"fbd": FBD_B}, {"equation": LMB_A}, {"equation": LMB_B},
                                 {"equation": LENGTH}, {"answer": T_CLOSED, "unknown": "T"}])
        self.assertEqual(self.parts(r), {"fbds": 2, "balances": 3, "constraints": 2, "answers": 3})
        self.assertEqual(r["score"], 10)
        steps = [t for t in r["tests"] if t["name"].startswith("step ")]
        self.assertEqual(len(steps), 6)
        self.assertTrue(all(t["status"] == "passed" for t in steps), steps)
        self.assertEqual(steps[1]["name"], "step 2: free body diagram of B")

    def test_partial_solution(self):
        # A's diagram right, B's missing: 1 of 2; LMB A right, B's a strand short: 1.5 of 3; no
        # constraint: 0 of 2; T right as a number: 3 of 3. 5.5, less the wrong step's share: 10
        # points over twice the 6 items (2 diagrams, 2 balances, 1 constraint, 1 answer).
        r = self.run_autograder([{"fbd": FBD_A}, {"equation": LMB_A}, {"equation": LMB_B_TWO_STRANDS}, {"answer": "20 N", "unknown": "T"}])
        self.assertEqual(self.parts(r), {"fbds": 1, "balances": 1.5, "constraints": 0, "answers": 3, "wrong steps": -10 / 12})
        self.assertAlmostEqual(r["score"], 5.5 - 10 / 12)
        wrong = [t for t in r["tests"] if t["name"].startswith("step 3")][0]
        self.assertEqual(wrong["status"], "failed")
        self.assertIn("a strand of string s at pB is missing", wrong["output"])
        # B's diagram a strand short: 2 of its 3 forces.
        r = self.run_autograder([{"fbd": dict(FBD_B, forces=FBD_B["forces"][:2])}])
        step = r["tests"][0]
        self.assertEqual(step["status"], "failed")
        self.assertIn("a strand of string s at pB is missing", step["output"])

    def test_missing_and_invalid_submissions(self):
        r = self.run_autograder(None)
        self.assertEqual((r["tests"], r["score"]), ([], 0))
        self.assertIn("No solution.yaml was submitted", r["output"])
        # A body the problem does not have, and a step of no known kind: located in solution.yaml.
        r = self.run_autograder("steps:\n  - fbd: {body: Q, forces: []}\n  - frobnicate: 1\n")
        self.assertEqual((r["tests"], r["score"]), ([], 0))
        self.assertIn("could not be graded", r["output"])
        self.assertRegex(r["output"], r"solution\.yaml:2:\d+: .*Q")
        self.assertRegex(r["output"], r"solution\.yaml:3:\d+: ")
        r = self.run_autograder("{not yaml: [")
        self.assertEqual(r["tests"], [])
        self.assertIn("solution.yaml:", r["output"])


class StepServer:
    """scripts/step-server (gunicorn's workers) on a free port of 127.0.0.1, with every request it saw."""

    def __init__(self, problem, *options):
        self.process = subprocess.Popen([sys.executable, os.path.join(SOURCE, "scripts/step-server"), problem, "--port", "0",
                                         "--build", os.path.dirname(TACKLE), *options],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.url = self.process.stdout.readline().strip()
        if not self.url:
            raise RuntimeError("the step server did not start: " + self.process.stderr.read())
        self.port = urllib.parse.urlparse(self.url).port
        self.log = []
        threading.Thread(target=self._read_log, daemon=True).start()

    def _read_log(self):
        for line in self.process.stderr:
            self.log.append(line)

    def request(self, method, path, body=None, headers=None):
        c = http.client.HTTPConnection("127.0.0.1", self.port, timeout=30)
        c.request(method, path, body=body, headers=headers or {})
        r = c.getresponse()
        data = r.read()
        c.close()
        return r.status, r.getheader("Content-Type"), data

    def post(self, path, obj):
        status, _, data = self.request("POST", path, json.dumps(obj), {"Content-Type": "application/json"})
        return status, json.loads(data)

    def raw(self, request, sock=None):
        """`request` sent as bytes (on `sock`, else a new connection), the sending side then
        closed: the answer's head and body."""
        c = sock or socket.create_connection(("127.0.0.1", self.port), timeout=30)
        c.sendall(request)
        c.shutdown(socket.SHUT_WR)
        answer = b""
        while True:
            chunk = c.recv(65536)
            if not chunk:
                break
            answer += chunk
        c.close()
        head, _, body = answer.partition(b"\r\n\r\n")
        return head, body

    def close(self):
        self.process.terminate()
        self.process.wait(timeout=10)
        self.process.stdout.close()
        self.process.stderr.close()


class StepServerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = StepServer(os.path.join(SOURCE, "examples/sample-12.3-two-mass-pulley.yaml"))

    @classmethod
    def tearDownClass(cls):
        cls.server.close()

    def step(self, obj):
        status, r = self.server.post("/step", obj)
        self.assertEqual(status, 200, r)
        return r

    def test_page(self):
        status, content_type, data = self.server.request("GET", "/")
        self.assertEqual(status, 200)
        self.assertTrue(content_type.startswith("text/html"))
        page = data.decode("utf-8")
        self.assertIn("<h1>Sample 12.3: a two-mass pulley system</h1>", page)
        self.assertIn("id=\"tackle-problem\"", page)

    def test_equations(self):
        r = self.step({"kind": "equation", "equation": LMB_A})
        self.assertEqual((r["verdict"], r["identified_as"]), ("correct", ["LMB A (x)"]))
        self.assertTrue(r["latex"])
        r = self.step({"kind": "equation", "equation": "T - F = m_A*ddot(x_A)"})
        self.assertEqual(r["verdict"], "incorrect")
        self.assertIn("a strand of string s at pA is missing", r["summary"])
        self.assertEqual(r["findings"][0]["code"], "missing_force")
        self.assertEqual(self.step({"kind": "equation", "equation": LENGTH})["verdict"], "correct")
        self.assertEqual(self.step({"kind": "equation", "equation": "2*T - F"})["verdict"], "invalid")

    def test_answers(self):
        self.assertEqual(self.step({"kind": "answer", "unknown": "T", "answer": T_CLOSED})["verdict"], "correct")
        self.assertEqual(self.step({"kind": "answer", "unknown": "T", "answer": "20 N"})["verdict"], "correct")
        self.assertEqual(self.step({"kind": "answer", "unknown": "T", "answer": "30 N"})["verdict"], "incorrect")
        self.assertEqual(self.step({"kind": "answer", "unknown": "Q", "answer": "1"})["verdict"], "invalid")

    def test_free_body_diagrams(self):
        self.assertEqual(self.step({"kind": "fbd", "fbd": FBD_B})["verdict"], "correct")
        r = self.step({"kind": "fbd", "fbd": dict(FBD_B, forces=FBD_B["forces"][:2])})
        self.assertEqual(r["verdict"], "incorrect")
        self.assertIn("a strand of string s at pB is missing", r["summary"])
        # The student's mistakes in the data are a verdict, not a server error.
        r = self.step({"kind": "fbd", "fbd": {"body": "Q", "forces": [{"name": "T", "at": "nowhere", "direction": [1]}]}})
        self.assertEqual(r["verdict"], "invalid")
        self.assertIn("Q", r["summary"])
        self.assertEqual(self.step({"kind": "fbd", "fbd": {"body": "B", "forces": [{"name": "T", "direction": [1, 2]}]}})["verdict"], "invalid")

    def test_solution(self):
        status, g = self.server.post("/solution", {"steps": [{"equation": LMB_A}, {"equation": LMB_B}, {"equation": ACCELERATION},
                                                            {"answer": T_CLOSED, "unknown": "T"}]})
        self.assertEqual(status, 200)
        # No rubric: 1 point a part; the answers' part asks for all three unknowns of the
        # description (T answered: 1 of 3), the balances and the constraint all given.
        self.assertEqual(g["missing"], [])
        self.assertEqual([s["verdict"] for s in g["steps"]], ["correct"] * 4)
        self.assertAlmostEqual(g["score"], 2 + 1 / 3)
        status, g = self.server.post("/solution", {"steps": [{"equation": LMB_A}], "rubric": {"balances": 4, "constraints": 0, "answers": 0}})
        self.assertEqual((status, g["score"], g["max_score"]), (200, 2, 4))
        status, g = self.server.post("/solution", {"steps": [{"fbd": {"body": "Q", "forces": []}}]})
        self.assertEqual((status, g["verdict"]), (200, "invalid"))

    def refused(self, status, method, path, body=None, headers=None):
        """The request is answered `status` with {"error": "..."}; the message."""
        got, content_type, data = self.server.request(method, path, body, headers)
        self.assertEqual(got, status, data[:300])
        self.assertTrue(content_type.startswith("application/json"), content_type)
        return json.loads(data)["error"]

    def raw(self, request):
        """`request` sent as bytes, the sending side then closed: the status line's code and
        reason (its HTTP version is the server's: gunicorn answers 1.1) and the body."""
        head, body = self.server.raw(request)
        return re.sub(rb"^HTTP/1\.[01] ", b"", head.split(b"\r\n")[0]), body

    def test_bad_requests(self):
        s = self.server
        self.refused(413, "POST", "/step", "x" * (64 * 1024 + 1))
        # A megabyte: read and dropped before the 413, which the client, still sending, then
        # reads (a connection closed with a body unread would be reset under it).
        self.refused(413, "POST", "/step", "x" * (1024 * 1024))
        self.assertEqual(self.refused(400, "POST", "/step", "{not json"), "the request is not JSON (UTF-8)")
        self.assertEqual(self.refused(400, "POST", "/step", "[1, 2]"), "the request is not a JSON object")
        self.refused(400, "POST", "/step", b"\xff\xfe")
        self.assertEqual(self.refused(400, "POST", "/step", "[" * 5000 + "]" * 5000), "the request's JSON is nested too deeply")
        self.assertEqual(self.refused(400, "POST", "/step", '{"kind": "fbd", "fbd": {"body": "B", "forces": [{"direction": [NaN]}]}}'),
                         "the request is not JSON (UTF-8)")
        self.assertEqual(self.refused(400, "POST", "/step", json.dumps({"kind": "poem"})), "'kind' must be equation, answer or fbd")
        self.assertEqual(self.refused(400, "POST", "/step", json.dumps({"kind": "equation", "equation": 3})), "'equation' must be a string")
        self.assertEqual(self.refused(400, "POST", "/step", '{"kind": "equation", "equation": "T = \\ud800"}'),
                         "'equation' is not text (it has a lone surrogate)")
        self.assertEqual(self.refused(400, "POST", "/step", json.dumps({"kind": "fbd", "fbd": "B"})), "'fbd' must be an object (body, forces)")
        self.assertEqual(self.refused(400, "POST", "/solution", json.dumps({"steps": "all"})), "'steps' must be a list")
        self.assertEqual(self.refused(400, "POST", "/solution", json.dumps({"steps": [{"equation": LMB_A}, 3]})),
                         'step 2 must be an object ({"equation": ...}, {"answer": ..., "unknown": ...} or {"fbd": {...}})')
        self.assertEqual(self.refused(400, "POST", "/solution", json.dumps({"steps": [{"answer": 20, "unknown": "T"}]})),
                         "step 1: 'answer' must be a string")
        self.assertEqual(self.refused(400, "POST", "/solution", json.dumps({"steps": [{"fbd": []}]})), "step 1: 'fbd' must be an object (body, forces)")
        self.refused(404, "POST", "/elsewhere", "{}")
        self.refused(404, "GET", "/etc/passwd")
        self.refused(405, "PUT", "/step", "{}")
        self.refused(405, "OPTIONS", "/step")
        self.refused(405, "BREW", "/step")
        # A name that is not this machine's (DNS rebinding).
        self.refused(403, "GET", "/", headers={"Host": "attacker.example:80"})
        # No Content-Length, two of them, or one that is not a number: refused, not waited for;
        # a body shorter than it says, or a request line that cannot be read: refused too.
        status, body = self.raw(b"POST /step HTTP/1.1\r\nHost: 127.0.0.1\r\nTransfer-Encoding: chunked\r\n\r\n5\r\nhello\r\n0\r\n\r\n")
        self.assertEqual((status, json.loads(body)["error"]), (b"411 Length Required", "send the body with a Content-Length"))
        for lengths in (b"Content-Length: 2\r\nContent-Length: 2\r\n", b"Content-Length: -1\r\n", b"Content-Length: 1e3\r\n"):
            status, body = self.raw(b"POST /step HTTP/1.1\r\nHost: 127.0.0.1\r\n" + lengths + b"\r\n{}")
            self.assertEqual((status, json.loads(body)["error"]), (b"400 Bad Request", "the Content-Length is not one whole number"))
        status, body = self.raw(b"POST /step HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 100\r\n\r\n{}")
        self.assertEqual((status, json.loads(body)["error"]), (b"408 Request Timeout", "the request's body is shorter than its Content-Length"))
        status, body = self.raw(b"POST /step HTTP/1.1 extra\r\n\r\n")
        self.assertEqual(status, b"400 Bad Request")
        self.assertIn("error", json.loads(body))
        # The server is still there.
        self.assertEqual(self.step({"kind": "equation", "equation": LMB_A})["verdict"], "correct")

    def test_cross_origin_posts_are_refused(self):
        # A page of another origin (a browser says where it comes from): refused before it is read.
        body = json.dumps({"kind": "equation", "equation": LMB_A})
        for headers in ({"Origin": "http://attacker.example"}, {"Origin": "null"}, {"Sec-Fetch-Site": "cross-site"},
                        {"Origin": "http://127.0.0.1:%d" % (self.server.port + 1)}):
            self.assertEqual(self.refused(403, "POST", "/step", body, headers), "a page of another origin may not post here")
        # The page's own origin, by either of this machine's names, and a client that says none.
        for headers in ({"Origin": "http://127.0.0.1:%d" % self.server.port}, {"Origin": "http://localhost:%d" % self.server.port},
                        {"Sec-Fetch-Site": "same-origin"}, {}):
            status, _, data = self.server.request("POST", "/step", body, headers)
            self.assertEqual((status, json.loads(data)["verdict"]), (200, "correct"), headers)


class StepServiceTest(unittest.TestCase):
    """The step service with two gunicorn workers: the verdicts of sample 12.3's steps by hand,
    requests side by side, one worker held by a request in flight while the other answers, and
    a solution's time limit. Nothing here is timed: what is asserted is each answer, and the
    order in which things happen."""

    @classmethod
    def setUpClass(cls):
        cls.server = StepServer(os.path.join(SOURCE, "examples/sample-12.3-two-mass-pulley.yaml"), "--workers", "2", "--quiet")

    @classmethod
    def tearDownClass(cls):
        cls.server.close()

    def test_two_workers(self):
        # The launcher (gunicorn's arbiter) and its two workers, each a process of its own.
        children = subprocess.run(["ps", "-o", "pid=", "--ppid", str(self.server.process.pid)],
                                  capture_output=True, text=True).stdout.split()
        self.assertEqual(len(children), 2, children)

    def test_verdicts(self):
        steps = [({"kind": "equation", "equation": LMB_A}, "correct"), ({"kind": "equation", "equation": LMB_B_TWO_STRANDS}, "incorrect"),
                 ({"kind": "answer", "unknown": "T", "answer": "20 N"}, "correct"),
                 ({"kind": "answer", "unknown": "T", "answer": "30 N"}, "incorrect"),
                 ({"kind": "fbd", "fbd": FBD_B}, "correct"), ({"kind": "fbd", "fbd": dict(FBD_B, forces=FBD_B["forces"][:2])}, "incorrect")]
        for step, verdict in steps:
            status, r = self.server.post("/step", step)
            self.assertEqual((status, r["verdict"]), (200, verdict), step)
        status, g = self.server.post("/solution", {"steps": [{"equation": LMB_A}, {"equation": LMB_B}, {"equation": ACCELERATION},
                                                            {"answer": T_CLOSED, "unknown": "T"}]})
        self.assertEqual((status, g["missing"], g["score"]), (200, [], 2 + 1 / 3))
        self.assertEqual([s["verdict"] for s in g["steps"]], ["correct"] * 4)

    def test_side_by_side(self):
        # 20 students at once, each an equation and an answer, half of them wrong: every
        # request answered, each with its own verdict.
        results = {}
        start = threading.Barrier(20)

        def student(k):
            start.wait()
            wrong = k % 2 == 1
            a = self.server.post("/step", {"kind": "equation", "equation": LMB_B_TWO_STRANDS if wrong else LMB_B})
            b = self.server.post("/step", {"kind": "answer", "unknown": "T", "answer": "30 N" if wrong else "20 N"})
            results[k] = (a[0], a[1]["verdict"], b[0], b[1]["verdict"])

        threads = [threading.Thread(target=student, args=(k,)) for k in range(20)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(120)
        expected = {k: (200, "incorrect", 200, "incorrect") if k % 2 else (200, "correct", 200, "correct") for k in range(20)}
        self.assertEqual(results, expected)

    def test_request_in_flight_holds_one_worker_only(self):
        # A solution whose body is still coming holds the worker that took it (a sync worker
        # answers one request at a time, as it would while checking a long solution); the other
        # worker answers a step meanwhile; then the rest of the body comes and the solution is
        # graded.
        body = json.dumps({"steps": [{"equation": LMB_A}, {"equation": LMB_B}, {"equation": ACCELERATION}]}).encode()
        slow = socket.create_connection(("127.0.0.1", self.server.port), timeout=30)
        self.addCleanup(slow.close)
        slow.sendall(b"POST /solution HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                     b"Content-Length: %d\r\n\r\n" % len(body) + body[:10])
        # (Connections are accepted in the order they came: by the time the first step is
        # answered, a worker has taken the solution and waits for the rest of its body.)
        for _ in range(3):
            status, r = self.server.post("/step", {"kind": "equation", "equation": LMB_A})
            self.assertEqual((status, r["verdict"]), (200, "correct"))
        slow.setblocking(False)
        with self.assertRaises(BlockingIOError):  # still in flight: nothing answered yet
            slow.recv(1)
        slow.setblocking(True)
        head, data = self.server.raw(body[10:], slow)
        self.assertRegex(head, rb"^HTTP/1\.1 200 OK")
        self.assertEqual([s["verdict"] for s in json.loads(data)["steps"]], ["correct"] * 3)

    def test_time_limit(self):
        # A time limit of a millisecond: 200 distinct equations (each check some tens of
        # microseconds at the least) are not all checked within it; those not begun are
        # undecided (time_limit), never a dropped connection; the answer still says the parts.
        server = StepServer(os.path.join(SOURCE, "examples/sample-12.3-two-mass-pulley.yaml"), "--workers", "1", "--quiet",
                            "--time-limit", "0.001")
        self.addCleanup(server.close)
        steps = [{"equation": "%d*T - %d*F = %d*m_A*ddot(x_A)" % (2 * k, k, k)} for k in range(1, 201)]
        status, g = server.post("/solution", {"steps": steps})
        self.assertEqual(status, 200)
        self.assertEqual(len(g["steps"]), 200)
        last = g["steps"][-1]
        self.assertEqual((last["verdict"], last["findings"][0]["code"]), ("undecided", "time_limit"))
        self.assertIn("time limit", last["summary"])
        self.assertEqual({s["verdict"] for s in g["steps"]} - {"correct"}, {"undecided"})
        self.assertEqual(g["wrong"], 0)  # not checked is not wrong
        # A step alone is checked whole (its own budget bounds it).
        status, r = server.post("/step", {"kind": "equation", "equation": LMB_A})
        self.assertEqual((status, r["verdict"]), (200, "correct"))

    def test_gunicorn_refusals_are_json(self):
        # What gunicorn itself refuses (before the application sees the request) is said as the
        # application says its own: two Content-Lengths, a header it cannot read.
        for request in (b"POST /step HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 2\r\nContent-Length: 2\r\n\r\n{}",
                        b"POST /step HTTP/1.1\r\nHost: 127.0.0.1\r\nBad Header: x\r\nContent-Length: 2\r\n\r\n{}",
                        b"GET / HTTP/one\r\nHost: 127.0.0.1\r\n\r\n"):
            head, body = self.server.raw(request)
            self.assertRegex(head, rb"^HTTP/1\.1 400 Bad Request\r\n", request)
            self.assertIn(b"Content-Type: application/json", head)
            self.assertTrue(json.loads(body)["error"])


class RecordingProxy:
    """A proxy that answers nothing and records every request: the browser is told to send
    everything that is not for this machine through it, so a page that fetched anything from
    the network would show here (with its address as Referer or Origin; the browser's own
    requests, a clock or an update service, have neither)."""

    def __init__(self):
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(16)
        self.port = self.sock.getsockname()[1]
        self.seen = []
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            conn.settimeout(2)
            try:
                self.seen.append(conn.recv(8192))
            except OSError:
                self.seen.append(b"")
            conn.close()

    def close(self):
        self.sock.close()


@unittest.skipUnless(shutil.which("chromium") or shutil.which("chromium-browser"), "chromium is not installed")
class PageInChromiumTest(unittest.TestCase):
    """The page as a browser shows it, served by the step server and pre-filled from its address
    with a correct and an incorrect equation (and graded on load)."""
    maxDiff = 2000

    def assertIn(self, member, container, msg=None):  # the DOM is 650 KB: not printed whole
        if member not in container:
            self.fail(msg or "%r not in the page (%d characters)" % (member, len(container)))

    def open_page(self, problem, query):
        """The DOM after the page was opened at its server with `query` and its steps checked,
        and the requests the server saw; asserts that nothing went to the network."""
        browser = shutil.which("chromium") or shutil.which("chromium-browser")
        server = StepServer(os.path.join(SOURCE, "examples", problem))
        self.addCleanup(server.close)
        proxy = RecordingProxy()
        self.addCleanup(proxy.close)
        profile = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, profile, True)
        r = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--user-data-dir=" + profile,
                            "--disable-background-networking", "--disable-component-update", "--disable-sync",
                            "--proxy-server=http://127.0.0.1:%d" % proxy.port, "--virtual-time-budget=15000",
                            "--window-size=1000,1400", "--dump-dom", server.url + "?" + urllib.parse.urlencode(query)],
                           capture_output=True, text=True, timeout=120)
        self.assertIn('data-checked="true"', r.stdout, "the page did not finish checking its steps: " + r.stderr[-2000:])
        self.assertEqual(r.stdout.count('class="katex-error"'), 0)
        time.sleep(0.3)  # the server's log, read by a thread, has every request the browser made
        requests = [re.search(r'"(\w+ [^ ?]+)', line).group(1) for line in list(server.log) if '"' in line]
        # Nothing fetched from the network: the page names nothing elsewhere, its policy lets it
        # connect to its own origin only, and no request of the page's reached the proxy.
        status, _, page = server.request("GET", "/")
        page = page.decode("utf-8")
        self.assertIsNone(re.search(r'(src|href)="(https?:)?//|url\((https?:)?//', page))
        self.assertIn("default-src 'none';", page)
        self.assertIn("connect-src 'self';", page)
        from_page = [q[:200] for q in proxy.seen if re.search(rb"(?im)^(referer|origin):", q)]
        self.assertEqual(from_page, [])
        return r.stdout, [q for q in requests if q != "GET /favicon.ico"]  # (the browser's own, if it asks)

    def test_prefilled_page(self):
        dom, requests = self.open_page("sample-12.3-two-mass-pulley.yaml",
                                       [("eq", LMB_A), ("eq", "T - F = m_A*ddot(x_A)"), ("grade", "1")])
        # The two verdicts, beside their steps, in order.
        verdicts = re.findall(r'<li class="step" data-kind="equation" data-verdict="(\w+)"', dom)
        self.assertEqual(verdicts, ["correct", "incorrect"])
        self.assertIn("it is LMB A (x)", dom)  # the summary
        self.assertIn("a strand of string s at pA is missing", dom)
        # Each echoed equation typeset by KaTeX (and no KaTeX error anywhere: open_page).
        echoes = re.findall(r'<div class="echo">(.*?)</div>\s*<div class="verdict"', dom, re.S)
        self.assertEqual(len(echoes), 2)
        for echo in echoes:
            self.assertIn('class="katex"', echo)
        # The whole solution graded (no rubric: 1 point a part): LMB A used, LMB B and the
        # string's acceleration missing: balances 1 of 2, constraints 0 of 1, answers 0 of 3,
        # 0.5 points; the wrong step takes a quarter back (3 points over twice the 6 items).
        self.assertRegex(dom, r'id="grade"[^>]*data-score="0.25/3"')
        self.assertIn("LMB B (x), string s: acceleration", dom)
        self.assertIn('<tr class="wrong-steps"><td>wrong steps</td><td>\u22120.25</td><td>1 incorrect</td></tr>', dom)
        # The hint in each equation's field is this problem's own first balance, its forces left out.
        self.assertIn('placeholder="LMB A (x): ... = m_A*ddot(x_A)"', dom)
        # The server saw the page, the two steps and the solution only.
        self.assertEqual(sorted(requests), ["GET /", "POST /solution", "POST /step", "POST /step"])

    def test_prefilled_diagrams_in_2d(self):
        # Sample 12.7 by hand: the suitcase slides to +x on the ground at A and B; its weight
        # points down (270 degrees from x), each normal force up (90), each friction force
        # against the sliding (180).
        right = {"body": "suitcase", "forces": [
            {"name": "W", "at": "suitcase", "angle": 270, "kind": "weight"}, {"name": "N_A", "at": "A", "angle": 90},
            {"name": "F_A", "at": "A", "angle": 180}, {"name": "N_B", "at": "B", "angle": 90},
            {"name": "F_B", "at": "B", "angle": 180}]}
        wrong = json.loads(json.dumps(right))
        wrong["forces"][4]["angle"] = 0  # friction at B along the sliding
        # The weight said to be a support's force: it is none of the suitcase's (the kind chosen
        # in the form reaches the checker).
        misnamed = json.loads(json.dumps(right))
        misnamed["forces"][0]["kind"] = "support"
        dom, requests = self.open_page("sample-12.7-suitcase.yaml",
                                       [("fbd", json.dumps(right)), ("fbd", json.dumps(wrong)), ("fbd", json.dumps(misnamed))])
        verdicts = re.findall(r'<li class="step" data-kind="fbd" data-verdict="(\w+)"', dom)
        self.assertEqual(verdicts, ["correct", "incorrect", "incorrect"])
        self.assertIn("your F_B stands for", dom)
        self.assertIn("points the other way", dom)
        self.assertIn("the weight of suitcase is missing", dom)
        self.assertEqual(sorted(requests), ["GET /", "POST /step", "POST /step", "POST /step"])


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
