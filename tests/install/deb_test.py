"""The Debian package: cpack -G DEB from the build directory (the packages and cpack's staging
in a temporary directory of each run, so that two runs do not meet; cpack leaves only its
install_manifest_*.txt in the build directory, which nothing reads), its control fields and
contents, and the package unpacked into a fresh root with dpkg -x, where the program,
finding its rules in that root,
grades a batch and the Python module checks an answer. Then the graders of the platforms,
run from the unpacked package against a scratch directory laid out as each platform lays it
out: Gradescope's setup.sh and run_autograder (/autograder), PrairieLearn's external grader
entrypoint (/grade).

Sample 12.3 by hand (the example's notes): T = 2 F m_B/(9 m_A + 4 m_B), 20 N at F = 130 N,
m_A = m_B = 40 kg; at F = 120 N, m_A = 55 kg, m_B = 50 kg: T = 12000/695 = 17.27 N.
Usage: deb_test.py BUILD_DIR SOURCE_DIR [unittest class names]"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import urllib.request

BUILD = os.path.abspath(sys.argv.pop(1))
SOURCE = os.path.abspath(sys.argv.pop(1))
T_CLOSED = "2*F*m_B/(9*m_A + 4*m_B)"
# Nothing of what builds the documents or tests the reports may be needed to run tackle.
DOCUMENT_TOOLS = re.compile(r"\b(texlive[\w-]*|lmodern|chromium[\w-]*|poppler-utils|libjs-katex|mkdocs|cmark-gfm|"
                            r"python3-jsonschema|python3-nbclient|python3-ipykernel|python3-nbformat|groff[\w-]*)\b")

work = None
debs = {}
root = None


def setUpModule():
    global work, root
    work = tempfile.mkdtemp(prefix="tackle-deb-")
    out = subprocess.run(["cpack", "-G", "DEB", "--config", os.path.join(BUILD, "CPackConfig.cmake"),
                          "-B", os.path.join(work, "packages")],
                         cwd=work, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError("cpack failed:\n" + out.stdout + out.stderr)
    for path in glob.glob(os.path.join(work, "packages", "*.deb")):
        debs[field(path, "Package")] = path
    root = os.path.join(work, "root")
    os.makedirs(root)
    subprocess.run(["dpkg", "-x", debs["tackle"], root], check=True)


def tearDownModule():
    shutil.rmtree(work, ignore_errors=True)


def field(deb, name):
    return subprocess.run(["dpkg-deb", "-f", deb, name], check=True, capture_output=True, text=True).stdout.strip()


def contents(deb):
    listing = subprocess.run(["dpkg-deb", "-c", deb], check=True, capture_output=True, text=True).stdout
    return [line.split()[5] for line in listing.splitlines()], listing


def depends_names(deb):
    # "libc6 (>= 2.34), python3 (<< 3.12), a | b" -> {"libc6", "python3", "a", "b"}
    return {alt.strip().split(" ")[0] for part in field(deb, "Depends").split(",") for alt in part.split("|") if alt.strip()}


def tackle(*args, **kwargs):
    return subprocess.run([os.path.join(root, "usr/bin/tackle"), *args], capture_output=True, text=True, **kwargs)


class PackageTest(unittest.TestCase):
    def test_control(self):
        deb = debs["tackle"]
        self.assertEqual(field(deb, "Section"), "science")
        with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
            self.assertEqual(field(deb, "Version"), re.search(r"project\(tackle VERSION ([0-9.]+)", f.read()).group(1))
        self.assertTrue(field(deb, "Maintainer"))
        depends = field(deb, "Depends")
        self.assertIsNone(DOCUMENT_TOOLS.search(depends), depends)
        # The libraries the Python module links (dpkg-shlibdeps), and python3 of its version.
        names = depends_names(deb)
        for needed in ("libginac11", "libcln6", "libyaml-0-2", "libc6", "python3"):
            self.assertIn(needed, names, depends)
        self.assertRegex(depends, r"python3 \(>= 3\.\d+~\), python3 \(<< 3\.\d+\)")
        # The step service runs under gunicorn, which grading does not need.
        self.assertEqual(field(deb, "Recommends"), "gunicorn")
        # scripts/setup --runtime installs every one of them, and nothing of the documents.
        runtime = subprocess.run([os.path.join(SOURCE, "scripts/setup"), "--runtime", "--dry-run"],
                                 check=True, capture_output=True, text=True).stdout.split()
        self.assertLessEqual(names, set(runtime), "scripts/setup --runtime lacks some of: " + depends)
        self.assertIsNone(DOCUMENT_TOOLS.search(" ".join(runtime)))

    def test_contents(self):
        files, listing = contents(debs["tackle"])
        for path in ("./usr/bin/tackle", "./usr/share/tackle/rules/pulley.yaml", "./usr/share/tackle/derivation.schema.json",
                     "./usr/share/man/man1/tackle.1", "./usr/share/man/man1/tackle-check.1",
                     "./usr/share/bash-completion/completions/tackle", "./usr/share/doc/tackle/LICENSE",
                     "./usr/share/doc/tackle/grading.md", "./usr/share/doc/tackle/examples/atwood-machine.yaml",
                     "./usr/share/doc/tackle/examples/gradescope/pulley-tension/run_autograder",
                     "./usr/share/doc/tackle/examples/prairielearn/pulley-tension-external/tests/grade",
                     "./usr/share/doc/tackle/examples/prairielearn/grader-image/Dockerfile"):
            self.assertIn(path, files)
        self.assertTrue(any(re.fullmatch(r"\./usr/lib/python3/dist-packages/tackle\.cpython-\d+-.*\.so", f) for f in files))
        self.assertIn("./usr/lib/python3/dist-packages/tackle_step_service.py", files)
        # The development files are tackle-dev's, not the runtime's.
        self.assertFalse([f for f in files if f.endswith(".a") or "/include/" in f or "/cmake/" in f])
        # Owned by root, the program executable by all.
        self.assertNotRegex(listing, r"(?m)^\S+ (?!root/root)")
        self.assertRegex(listing, r"(?m)^-rwxr-xr-x root/root .* \./usr/bin/tackle$")

    def test_dev_package(self):
        deb = debs["tackle-dev"]
        files, _ = contents(deb)
        self.assertIn("./usr/lib/libtackle.a", files)
        self.assertIn("./usr/include/tackle/check/check.hpp", files)
        self.assertIn("./usr/lib/cmake/tackle/tackleConfig.cmake", files)
        self.assertFalse([f for f in files if f.startswith("./usr/bin/") or "/rules/" in f])
        self.assertIn("tackle (= %s)" % field(debs["tackle"], "Version"), field(deb, "Depends"))

    def test_program_grades(self):
        # The rules of the fresh root, found from the program's own place (usr/bin/../share),
        # as /usr/bin/tackle finds /usr/share/tackle/rules; no TACKLE_RULES, no --rules.
        env = {k: v for k, v in os.environ.items() if k != "TACKLE_RULES"}
        version = tackle("--version", env=env, check=True).stdout
        self.assertEqual(version.strip().split(" (rules: ")[1], os.path.join(root, "usr/share/tackle/rules") + ")")
        problem = os.path.join(root, "usr/share/doc/tackle/examples/sample-12.3-two-mass-pulley.yaml")
        batch = os.path.join(work, "answers.jsonl")
        with open(batch, "w") as f:
            for i, answer in enumerate([T_CLOSED, "20 N", "40 N", "2*F*", "17.27 N"]):
                line = {"id": "s%d" % i, "unknown": "T", "answer": answer}
                if i == 4:
                    line["params"] = {"F": 120, "m_A": 55, "m_B": 50}
                f.write(json.dumps(line) + "\n")
        out = os.path.join(work, "graded.jsonl")
        results = os.path.join(work, "results.json")
        tackle("check", problem, "--batch", batch, "-o", out, "--results", results, "--results-format", "gradescope",
               env=env, check=True)
        with open(out) as f:
            verdicts = [json.loads(line)["verdict"] for line in f]
        self.assertEqual(verdicts, ["correct", "correct", "incorrect", "invalid", "correct"])
        with open(results) as f:
            self.assertEqual([t["score"] for t in json.load(f)["tests"]], [1, 1, 0, 0, 1])
        # The program needs no shared library at all (static where the archives are there),
        # and the module's are all found on this system.
        module = glob.glob(os.path.join(root, "usr/lib/python3/dist-packages/tackle*.so"))[0]
        self.assertNotIn("not found", subprocess.run(["ldd", module], capture_output=True, text=True).stdout)

    def test_python_module(self):
        site = os.path.join(root, "usr/lib/python3/dist-packages")
        env = {k: v for k, v in os.environ.items() if k not in ("TACKLE_RULES", "PYTHONHOME")}
        env["PYTHONPATH"] = site
        problem = os.path.join(root, "usr/share/doc/tackle/examples/sample-12.3-two-mass-pulley.yaml")
        script = """
import json, sys, tackle
p = tackle.Problem(sys.argv[1])
print(json.dumps({"file": tackle.__file__, "rules": tackle.rules_dir(),
                  "right": p.check("T", sys.argv[2])["verdict"], "wrong": p.check("T", "40 N")["verdict"]}))
"""
        # Debian's python3, as an installed package's module is run.
        out = subprocess.run(["/usr/bin/python3", "-s", "-c", script, problem, T_CLOSED], env=env, check=True,
                             capture_output=True, text=True).stdout
        got = json.loads(out)
        self.assertTrue(got["file"].startswith(site + "/"), got["file"])
        self.assertEqual(got["rules"], os.path.join(root, "usr/share/tackle/rules"))
        self.assertEqual((got["right"], got["wrong"]), ("correct", "incorrect"))

    @unittest.skipUnless(os.path.exists("/usr/bin/gunicorn"), "gunicorn is not installed")
    def test_step_service(self):
        # The step service of the installed package (python3 -m tackle_step_service) under
        # Debian's python3 and gunicorn, one worker: its address first, then a step judged.
        site = os.path.join(root, "usr/lib/python3/dist-packages")
        env = {k: v for k, v in os.environ.items() if k not in ("TACKLE_RULES", "PYTHONHOME", "TACKLE_BUILD_DIR")}
        env["PYTHONPATH"] = site
        problem = os.path.join(root, "usr/share/doc/tackle/examples/sample-12.3-two-mass-pulley.yaml")
        server = subprocess.Popen(["/usr/bin/python3", "-s", "-m", "tackle_step_service", problem, "--workers", "1", "--quiet"],
                                  env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            url = server.stdout.readline().strip()
            self.assertRegex(url, r"^http://127\.0\.0\.1:\d+/$")
            request = urllib.request.Request(url + "step", data=json.dumps({"kind": "answer", "unknown": "T", "answer": T_CLOSED}).encode(),
                                             headers={"Content-Type": "application/json"})
            with urllib.request.urlopen(request, timeout=60) as r:
                self.assertEqual(json.load(r)["verdict"], "correct")
        finally:
            server.terminate()
            server.wait(timeout=30)
            server.stdout.close()
            server.stderr.close()


def examples(*parts):
    return os.path.join(root, "usr/share/doc/tackle/examples", *parts)


class PlatformTest(unittest.TestCase):
    """The files each platform runs, from the unpacked package, with the platform's layout
    in a scratch directory (AUTOGRADER, GRADE_ROOT) and the unpacked program (TACKLE)."""

    def gradescope(self, example, submission_name, submission):
        base = tempfile.mkdtemp(dir=work)
        shutil.copytree(examples("gradescope", example), os.path.join(base, "source"), symlinks=False)
        os.remove(os.path.join(base, "source/make_autograder_zip"))
        if submission is not None:
            os.makedirs(os.path.join(base, "submission"))
            with open(os.path.join(base, "submission", submission_name), "w") as f:
                f.write(submission)
        env = dict(os.environ, AUTOGRADER=base, TACKLE=os.path.join(root, "usr/bin/tackle"))
        subprocess.run([os.path.join(base, "source/run_autograder")], env=env, check=True, capture_output=True)
        with open(os.path.join(base, "results/results.json")) as f:
            return json.load(f)

    def test_gradescope_answers(self):
        right = self.gradescope("pulley-tension", "answers.json", json.dumps({"T": T_CLOSED}))
        self.assertEqual([(t["name"], t["score"], t["max_score"]) for t in right["tests"]], [("answers.json: T", 10, 10)])
        wrong = self.gradescope("pulley-tension", "answers.json", '{"T": "30 N"}')
        self.assertEqual(wrong["tests"][0]["score"], 0)
        self.assertNotIn("20 N", wrong["tests"][0]["output"])
        self.assertEqual(self.gradescope("pulley-tension", "answers.json", None)["tests"], [])

    def test_gradescope_solution(self):
        steps = ("steps:\n  - equation: \"2*T - F = m_A*ddot(x_A)\"\n  - equation: \"-3*T = m_B*ddot(x_B)\"\n"
                 "  - equation: \"3*ddot(x_B) = 2*ddot(x_A)\"\n  - {answer: \"%s\", unknown: T}\n" % T_CLOSED)
        graded = self.gradescope("pulley-solution", "solution.yaml", steps)
        # The rubric's parts (diagrams 2, balances 3, constraints 2, answers 3): every part but
        # the diagrams, which were not drawn.
        parts = {t["name"]: (t["score"], t["max_score"]) for t in graded["tests"] if not t["name"].startswith("step ")}
        self.assertEqual(parts, {"fbds": (0, 2), "balances": (3, 3), "constraints": (2, 2), "answers": (3, 3)})
        self.assertEqual(graded["score"], 8)
        broken = self.gradescope("pulley-solution", "solution.yaml", "steps: [{fbd: {body: Q}}]\n")
        self.assertEqual((broken["score"], broken["tests"]), (0, []))
        self.assertIn("solution.yaml:", broken["output"])

    def test_gradescope_setup_installs_the_deb(self):
        # setup.sh as Gradescope runs it, with the .deb in source/ as make_autograder_zip --deb
        # packs it; apt-get is a stand-in that records its arguments (no system is changed).
        base = tempfile.mkdtemp(dir=work)
        shutil.copytree(examples("gradescope/pulley-tension"), os.path.join(base, "source"), symlinks=False)
        shutil.copy(debs["tackle"], os.path.join(base, "source"))
        bin_dir = os.path.join(base, "bin")
        os.makedirs(bin_dir)
        with open(os.path.join(bin_dir, "apt-get"), "w") as f:
            f.write('#!/bin/sh\necho "$@" >> "%s/apt-get.log"\n' % base)
        os.chmod(os.path.join(bin_dir, "apt-get"), 0o755)
        env = dict(os.environ, AUTOGRADER=base, PATH=bin_dir + ":" + os.environ["PATH"])
        subprocess.run([os.path.join(base, "source/setup.sh")], env=env, check=True)
        with open(os.path.join(base, "apt-get.log")) as f:
            calls = f.read().splitlines()
        deb = os.path.join(base, "source", os.path.basename(debs["tackle"]))
        self.assertEqual(calls[0], "update -qq")
        self.assertEqual(calls[1], "install -y -qq --no-install-recommends " + deb)

    def prairielearn(self, submitted, params=None):
        base = tempfile.mkdtemp(dir=work)
        # /grade/tests is the question's tests/ (links followed, as PrairieLearn copies
        # files); the entrypoint made executable, as PrairieLearn does before running it.
        shutil.copytree(examples("prairielearn/pulley-tension-external/tests"), os.path.join(base, "tests"), symlinks=False)
        os.chmod(os.path.join(base, "tests/grade"), 0o755)
        os.makedirs(os.path.join(base, "data"))
        os.makedirs(os.path.join(base, "student"))
        data = {"params": params or {}, "correct_answers": {}, "submitted_answers": submitted, "format_errors": {},
                "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": 1, "options": {}, "raw_submitted_answers": submitted,
                "editable": False, "panel": "question", "extensions": {}, "num_valid_submissions": 1}
        with open(os.path.join(base, "data/data.json"), "w") as f:
            json.dump(data, f)
        env = dict(os.environ, GRADE_ROOT=base, TACKLE=os.path.join(root, "usr/bin/tackle"))
        subprocess.run([os.path.join(base, "tests/grade")], env=env, check=True, capture_output=True)
        with open(os.path.join(base, "results/results.json")) as f:
            return json.load(f)

    def test_prairielearn_external(self):
        right = self.prairielearn({"T": T_CLOSED})
        self.assertEqual((right["gradable"], right["score"]), (True, 1.0))
        self.assertEqual([(t["name"], t["points"], t["max_points"]) for t in right["tests"]], [("answer: T", 1.0, 1.0)])
        self.assertEqual(self.prairielearn({"T": "20 N"})["score"], 1.0)
        wrong = self.prairielearn({"T": "30 N"})
        self.assertEqual((wrong["gradable"], wrong["score"]), (True, 0.0))
        self.assertNotIn("20 N", json.dumps(wrong))
        # An answer tackle cannot read: not gradable, no attempt charged, the reason given.
        invalid = self.prairielearn({"T": "2*F*"})
        self.assertFalse(invalid["gradable"])
        self.assertTrue(invalid["format_errors"])
        self.assertNotIn("score", invalid)
        # A variant's numbers from data.json's params: 17.27 N is right there, 20 N is not.
        variant = {"F": 120, "m_A": 55, "m_B": 50}
        self.assertEqual(self.prairielearn({"T": "17.27 N"}, variant)["score"], 1.0)
        self.assertEqual(self.prairielearn({"T": "20 N"}, variant)["score"], 0.0)

    def test_prairielearn_files(self):
        with open(examples("prairielearn/pulley-tension-external/info.json")) as f:
            info = json.load(f)
        self.assertEqual(info["gradingMethod"], "External")
        options = info["externalGradingOptions"]
        self.assertTrue(options["enabled"])
        self.assertEqual(options["entrypoint"], "/grade/tests/grade")
        with open(examples("prairielearn/grader-image/Dockerfile")) as f:
            dockerfile = f.read()
        # The release this package is built on (its Depends are Debian 12's libraries).
        self.assertRegex(dockerfile, r"(?m)^FROM debian:bookworm")
        self.assertRegex(dockerfile, r"apt-get install -y --no-install-recommends /tmp/tackle_\*\.deb")


if __name__ == "__main__":
    unittest.main(verbosity=2)
