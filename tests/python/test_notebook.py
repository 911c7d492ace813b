"""The tutorial notebook (docs/tutorial.ipynb), executed as Jupyter executes it: nbclient runs
its cells in a Python kernel (ipykernel) with the build tree's module on PYTHONPATH, and the
outputs are what a notebook's page would show. Cells are found by their tags. Then the math of
those outputs is typeset in Chromium, as the notebook's page would typeset it.

Sample 12.3 by hand (the example's notes): T = 2 F m_B/(9 m_A + 4 m_B) = 20 N at F = 130 N and
m_A = m_B = 40 kg, so 20 N and that closed form are right, and 30 N and half of it
(F m_B/(9 m_A + 4 m_B)) are wrong; A's balance is 2 T - F = m_A ddot(x_A) (two strands), so
T - F = m_A ddot(x_A) is wrong; B bears three strands at pB, each pulling toward C (-x).

Usage: test_notebook.py SOURCE_DIR. Exit 77 (the test's SKIP_RETURN_CODE) when nbclient,
nbformat or ipykernel is not installed (scripts/setup installs Debian's python3-nbclient,
python3-nbformat and python3-ipykernel)."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

SOURCE = os.path.abspath(sys.argv.pop(1) if len(sys.argv) > 1 else ".")
NOTEBOOK = os.path.join(SOURCE, "docs", "tutorial.ipynb")
SKIP = 77

try:
    import nbclient
    import nbformat
    import ipykernel  # noqa: F401 (the kernel nbclient starts)
except ImportError as e:
    print("skipped: %s (install python3-nbclient, python3-nbformat and python3-ipykernel)" % e)
    sys.exit(SKIP)

executed = None


def setUpModule():
    global executed
    executed = nbformat.read(NOTEBOOK, as_version=4)
    os.environ["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"  # ipykernel's debugger: no warning on stderr
    # The kernel's connection file and IPython's profile in a directory of this run's, not $HOME.
    scratch = tempfile.mkdtemp(prefix="tackle-notebook-")
    os.environ["JUPYTER_RUNTIME_DIR"] = os.path.join(scratch, "runtime")
    os.environ["IPYTHONDIR"] = os.path.join(scratch, "ipython")
    # The kernel inherits this environment (PYTHONPATH: the build tree's module) and starts in
    # docs/, as Jupyter starts a notebook's kernel in the notebook's directory.
    client = nbclient.NotebookClient(executed, timeout=300, kernel_name="python3", allow_errors=False,
                                     resources={"metadata": {"path": os.path.dirname(NOTEBOOK)}})
    try:
        client.execute()
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def cell(tag):
    found = [c for c in executed.cells if tag in c.metadata.get("tags", [])]
    if len(found) != 1:
        raise AssertionError("%d cells tagged %r" % (len(found), tag))
    return found[0]


def shown(tag):
    """The data (by MIME type) of the cell's displayed result."""
    results = [o for o in cell(tag).outputs if o.output_type in ("execute_result", "display_data")]
    if len(results) != 1:
        raise AssertionError("cell %r shows %d results" % (tag, len(results)))
    return results[0].data


def math(html):
    """The TeX of each \\( \\) and \\[ \\] of a fragment (HTML-unescaped), as MathJax finds it."""
    import html as h
    return [h.unescape(m) for m in re.findall(r"\\\(.*?\\\)|\\\[.*?\\\]", html, re.S)]


class CheckedInTest(unittest.TestCase):
    def test_outputs_cleared(self):
        # The notebook is kept without outputs (they are made here, and by whoever runs it):
        # a change to tackle's output does not leave a stale picture in docs/.
        with open(NOTEBOOK) as f:
            nb = json.load(f)
        for c in nb["cells"]:
            if c["cell_type"] == "code":
                self.assertEqual(c["outputs"], [], "".join(c["source"])[:60])
                self.assertIsNone(c["execution_count"])
        nbformat.validate(nbformat.reads(json.dumps(nb), as_version=4))


class ExecutedTest(unittest.TestCase):
    def test_no_errors(self):
        for c in executed.cells:
            if c.cell_type != "code":
                continue
            for o in c.outputs:
                self.assertNotEqual(o.output_type, "error", "".join(o.get("traceback", []))[-2000:])
                if o.output_type == "stream":
                    self.assertNotEqual(o.name, "stderr", o.text)

    def test_problem_shows_itself(self):
        data = shown("problem")
        html = data["text/html"]
        # One fragment (no document, no script), its figures inline SVG.
        self.assertTrue(html.startswith('<div class="tackle" id="tackle-'), html[:80])
        self.assertNotRegex(html, r"(?i)<(html|head|body|script)\b")
        self.assertIn("<h3>Sample 12.3: a two-mass pulley system</h3>", html)
        self.assertIn('<svg xmlns="http://www.w3.org/2000/svg" class="fbd"', html)
        self.assertIn("Free body diagram of B", html)  # in the folded derivation
        self.assertIn("<details>", html)
        # The math for the page's MathJax: the statement's, what is asked, the answers.
        tex = math(html)
        self.assertIn("\\(m_A\\)", tex)
        self.assertTrue(any(t.startswith("\\[\\boxed{T =") and "20\\,\\mathrm{N}" in t for t in tex), tex[:20])
        self.assertTrue(any("\\ddot{x}_{A}" in t and "-2.25\\,\\mathrm{m/s^{2}}" in t for t in tex), tex[:20])
        # Every id of the fragment is its own.
        own = re.match(r'<div class="tackle" id="([\w-]+)"', html).group(1)
        for i in re.findall(r'\bid="([^"]+)"', html):
            self.assertTrue(i.startswith(own), i)
        # And its LaTeX: the equations in one align* block, A's balance among them.
        latex = data["text/latex"]
        self.assertTrue(latex.startswith("\\begin{align*}"), latex[:40])
        self.assertRegex(latex, r"2 T - F &= m_{A} \\ddot\{x\}_{A}.*\\tag\*\{LMB A \(x\)\}")
        self.assertIn("text/plain", data)

    def assertVerdict(self, tag, verdict):
        data = shown(tag)
        self.assertIn('data-verdict="%s"' % verdict, data["text/html"])
        self.assertIn(">%s</span>" % verdict, data["text/html"])
        self.assertIn("'verdict': '%s'" % verdict, data["text/plain"])  # still the dict it was
        return data["text/html"]

    def test_checks_show_their_verdicts(self):
        html = self.assertVerdict("check-right", "correct")
        self.assertIn("\\(\\displaystyle T = 20\\,\\mathrm{N}\\)", html)
        self.assertVerdict("check-right-closed-form", "correct")
        html = self.assertVerdict("check-wrong", "incorrect")
        self.assertIn("not within 1 % of the correct value", html)
        self.assertVerdict("check-wrong-closed-form", "incorrect")
        self.assertEqual(json.loads(cell("check-json").outputs[0].text)["verdict"], "incorrect")
        html = self.assertVerdict("equation-right", "correct")
        self.assertIn("\\(\\displaystyle 2 T - F = m_{A} \\ddot{x}_{A}\\)", html)
        html = self.assertVerdict("equation-wrong", "incorrect")
        self.assertIn("missing", html)
        html = self.assertVerdict("fbd", "correct")
        self.assertEqual(html.count(">drawn as your T</td>"), 3)

    def test_answers_and_variant(self):
        html = shown("answers")["text/html"]
        self.assertEqual(html.count("<tr>"), 4)  # the head, T, ddot(x_A), ddot(x_B)
        self.assertIn("\\(\\ddot{x}_{A}\\)", html)
        plain = shown("answers-plain")["text/plain"]
        self.assertIn("'T': ('2*F*m_B/(9*m_A + 4*m_B)', 20.0, 'N')", plain)
        html = shown("variant")["text/html"]
        self.assertIn("variant of seed 3", html)
        # The variant's own T, by hand from its drawn numbers, is checked right there.
        self.assertVerdict("variant-check", "correct")

    def test_derivation(self):
        data = shown("derivation")
        self.assertEqual(data["text/html"].count("<svg"), 3)  # the sketch, A's and B's diagrams
        self.assertNotIn("<details>", data["text/html"])
        self.assertIn("\\begin{align*}", data["text/latex"])
        text = "".join(o.text for o in cell("derive-text").outputs if o.output_type == "stream")
        self.assertIn("T = 2*F*m_B/(9*m_A + 4*m_B)", text)


class TypesetTest(unittest.TestCase):
    """The outputs' math, typeset in a browser as a notebook's page typesets it: the page's
    typesetter finds \\( \\) and \\[ \\] in the HTML. KaTeX (Debian's libjs-katex, with its
    auto-render) stands in for Jupyter's MathJax, which is not installed: every formula of the
    problem and of the checks is found and typeset, none is an error."""

    def test_every_formula_typesets(self):
        browser = shutil.which("chromium") or shutil.which("chromium-browser")
        katex = os.environ.get("TACKLE_KATEX_DIR", "/usr/share/javascript/katex")
        if not browser or not os.path.exists(os.path.join(katex, "contrib", "auto-render.js")):
            self.skipTest("needs chromium and libjs-katex")
        fragments = [shown(tag)["text/html"] for tag in ("problem", "answers", "check-right", "check-wrong-closed-form",
                                                           "equation-wrong", "fbd", "variant", "derivation")]
        formulas = sum(len(math(f)) for f in fragments)
        work = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, work, True)
        page = os.path.join(work, "outputs.html")
        with open(page, "w") as f:
            f.write('<!DOCTYPE html><html><head><meta charset="utf-8"><link rel="stylesheet" href="file://%s/katex.min.css">'
                    '<script src="file://%s/katex.min.js"></script><script src="file://%s/contrib/auto-render.js"></script>'
                    '</head><body>%s<script>renderMathInElement(document.body, {delimiters: ['
                    '{left: "\\\\[", right: "\\\\]", display: true}, {left: "\\\\(", right: "\\\\)", display: false}],'
                    ' throwOnError: false}); document.body.setAttribute("data-typeset", "true");</script></body></html>'
                    % (katex, katex, katex, "".join('<div class="output">' + f + "</div>" for f in fragments)))
        r = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--user-data-dir=" + work,
                            "--allow-file-access-from-files", "--virtual-time-budget=10000", "--dump-dom", "file://" + page],
                           capture_output=True, text=True, timeout=120)
        dom = r.stdout
        self.assertIn('data-typeset="true"', dom, r.stderr[-2000:])
        self.assertGreater(formulas, 50)
        self.assertEqual(dom.count('<span class="katex">'), formulas)  # (a displayed one inside its katex-display)
        self.assertEqual(dom.count('class="katex-error"'), 0)
        left = re.search(r"\\[(\[].{0,60}", dom.split("<script>renderMathInElement")[0])
        self.assertIsNone(left, "a delimiter left as text")


if __name__ == "__main__":
    unittest.main()
