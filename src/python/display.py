"""The Python half of tackle's display in notebooks (Jupyter).

Compiled into the module (src/python/display.cpp runs it in the module `tackle` when it is
imported). Problem's own _repr_html_ and _repr_latex_ are the C++ report writers'
(src/report/notebook.hpp); here the results of the checks become dicts that show themselves
(the verdict in its colour, what was read typeset, the findings), the answers and a variant
tables, and Problem.derivation() the derivation as a document. Every result stays what it
was (a dict, a list; the same items, JSON as before): only its display is added.

Math is written as \\( \\) and \\[ \\] for the notebook's MathJax, as the C++ half writes it."""
import functools
import html as _html

__all__ = ["CheckResult", "FbdGrade", "SolutionGrade", "AnswerList", "Variant", "Derivation"]

# The verdicts' colours, as on the step page (src/report/step_page.cpp); grey for the others.
_COLOURS = {"correct": "#2e7d32", "incorrect": "#c62828", "invalid": "#ef6c00"}
_GREY = "#757575"
# How a force of a free body diagram stands (the words of `tackle check --fbd`).
_FORCE_STATUS = {"drawn": "drawn", "wrong_direction": "drawn the wrong way", "wrong_point": "drawn at the wrong point",
                 "off_line": "drawn off its line", "zero": "nothing at this position (not needed)", "missing": "missing"}
_BOX = "font-family:system-ui,'DejaVu Sans',sans-serif;border-left:6px solid {};padding:.35em .8em;margin:.3em 0"
_BADGE = ("display:inline-block;min-width:6em;text-align:center;border-radius:3px;padding:0 .4em;"
          "color:#fff;background:{};font-weight:600;margin-right:.6em")
_TABLE = "border-collapse:collapse;margin:.3em 0"
_CELL = "padding:.15em .7em;border-bottom:1px solid #ddd;text-align:left"
_NUMBER = "padding:.15em .7em;border-bottom:1px solid #ddd;text-align:right;font-variant-numeric:tabular-nums"


def _e(text):
    return _html.escape(str(text), quote=True)


def _math(tex, display=False):
    return ("\\[" if display else "\\(") + _e(tex) + ("\\]" if display else "\\)")


def _quantity(number, unit):
    """A number with its unit, typeset (20.7634 and m/s^2: 20.7634 m/s², the unit upright)."""
    return _math(number + ("\\," + _unit_latex(unit) if unit else ""))  # noqa: F821 (put in, as Problem)


def _name(name, names):
    """A name typeset when the problem knows its LaTeX, else as code."""
    tex = names.get(name) if names else None
    return _math(tex) if tex else "<code>" + _e(name) + "</code>"


def _badge(verdict):
    colour = _COLOURS.get(verdict, _GREY)
    return '<span class="verdict" data-verdict="{}" style="{}">{}</span>'.format(_e(verdict), _BADGE.format(colour), _e(verdict))


def _findings(result, shown):
    """The findings not already said by the summary, as a list."""
    items = [f for f in result.get("findings", []) if f.get("message") and f["message"] not in shown]
    if not items:
        return ""
    return "<ul style=\"margin:.2em 0 0 1.2em;padding:0\">" + "".join(
        "<li>{} <span style=\"color:#777\">({})</span></li>".format(_e(f["message"]), _e(f["code"])) for f in items) + "</ul>"


def _verdict_html(result, head, more=""):
    """One verdict: its badge, `head` (HTML: what was checked), the summary and findings, and
    `more` (HTML) below."""
    verdict = result.get("verdict", "")
    summary = result.get("summary", "")
    return ('<div class="tackle-verdict" style="{}">{}{}<div style="margin-top:.2em">{}</div>{}{}</div>'.format(
        _BOX.format(_COLOURS.get(verdict, _GREY)), _badge(verdict), head, _e(summary), _findings(result, {summary}), more))


def _checked(result, written, name_latex=None):
    """What a check of an answer or an equation checked, as HTML: `unknown = answer` or the
    equation, typeset as tackle read it (as typed when it could not be read)."""
    latex, unknown = result.get("latex"), result.get("unknown")
    typed = "<code>" + _e(written) + "</code>"
    shown = "\\displaystyle " + latex if latex else ""  # a fraction as in a display, in its line
    if not unknown:  # an equation
        return _math(shown) if latex else typed
    if name_latex and latex:
        return _math("\\displaystyle " + name_latex + " = " + latex)
    return (_math(name_latex) if name_latex else "<code>" + _e(unknown) + "</code>") + " = " + (_math(shown) if latex else typed)


class CheckResult(dict):
    """The result of Problem.check (an answer) or Problem.check_equation: a dict (verdict,
    score, summary, findings, ...) that shows its verdict in a notebook."""

    def __init__(self, result, written="", name_latex=None):
        super().__init__(result)
        self._written = written        # what the student typed
        self._name_latex = name_latex  # the unknown's LaTeX (an answer's check)

    def _repr_html_(self):
        return _verdict_html(self, _checked(self, self._written, self._name_latex))


class FbdGrade(dict):
    """The grade of Problem.check_fbd: a dict (verdict, summary, forces, extras, findings,
    score, max_score) that shows, in a notebook, each force the body bears and how it was drawn."""

    def _repr_html_(self):
        rows = []
        for f in self.get("forces", []):
            status = _FORCE_STATUS.get(f.get("status"), f.get("status", ""))
            drawn = [n or "(no name)" for n in f.get("drawn_as", [])]
            if drawn:
                status += " as your " + ", ".join(drawn)
            colour = _COLOURS["correct"] if f.get("status") == "drawn" else _COLOURS["incorrect"]
            rows.append('<tr><td style="{0}">{1}</td><td style="{0}"><code>{2}</code></td><td style="{0};color:{3}">{4}</td></tr>'.format(
                _CELL, _e(f.get("phrase") or f.get("source", "")), _e(f.get("label", "")), colour, _e(status)))
        for x in self.get("extras", []):
            rows.append('<tr><td style="{0}">extra</td><td style="{0}"><code>{1}</code></td><td style="{0};color:{2}">{3}</td></tr>'.format(
                _CELL, _e(x.get("name", "")), _COLOURS["incorrect"], _e(x.get("message", ""))))
        score = "{:g} of {:g}".format(self.get("score", 0), self.get("max_score", 0)) if "max_score" in self else ""
        head = "free body diagram of <b>{}</b>{}".format(_e(self.get("of", "")), " &middot; " + score if score else "")
        table = '<table style="{}"><tr><th style="{c}">force</th><th style="{c}">label</th><th style="{c}">drawn</th></tr>{}</table>'.format(
            _TABLE, "".join(rows), c=_CELL) if rows else ""
        return _verdict_html(self, head, table)


class SolutionGrade(dict):
    """The grade of Problem.check_solution: a dict (steps, parts, score, ...) that shows, in a
    notebook, each step's verdict and the rubric's parts."""

    def __init__(self, grade, names=None):
        super().__init__(grade)
        self._names = names or {}

    def _repr_html_(self):
        out = '<div class="tackle-solution" style="font-family:system-ui,\'DejaVu Sans\',sans-serif">'
        if "max_score" in self:
            out += "<p><b>Score: {:g} of {:g}</b>".format(self.get("score", 0), self.get("max_score", 0))
            if self.get("penalty"):
                wrong = self.get("wrong", 0)
                out += " (a penalty of {:g} for {} wrong step{})".format(self["penalty"], wrong, "" if wrong == 1 else "s")
            out += "</p>"
        for step in self.get("steps", []):
            fbd = step.get("method") == "fbd" or step.get("unknown", "").startswith("free body diagram")
            what = _e(step.get("unknown", "")) if fbd else _checked(step, step.get("answer", ""), self._names.get(step.get("unknown", "")))
            out += _verdict_html(step, "<b>{}</b>: {}".format(_e(step.get("id", "")), what))
        parts = self.get("parts", [])
        if parts:
            out += '<table style="{}"><tr><th style="{c}">part</th><th style="{c}">done</th><th style="{c}">score</th></tr>'.format(_TABLE, c=_CELL)
            for p in parts:
                out += '<tr><td style="{0}">{1}</td><td style="{2}">{3} of {4}</td><td style="{2}">{5:g} of {6:g}</td></tr>'.format(
                    _CELL, _e(p.get("name", "")), _NUMBER, p.get("done", 0), p.get("of", 0), p.get("score", 0), p.get("max_score", 0))
            out += "</table>"
        return out + "</div>"


class AnswerList(list):
    """Problem.answers(): a list of dicts (name, closed_form, latex, value, unit) that shows, in
    a notebook, as a table of the answers typeset with their numbers."""

    def __init__(self, answers, names=None):
        super().__init__(answers)
        self._names = names or {}

    def _repr_html_(self):
        rows = ""
        for a in self:
            closed = _math("\\displaystyle " + a["latex"]) if a.get("latex") else "<i>not determined</i>"
            value = "" if a.get("value") is None else _quantity("{:.6g}".format(a["value"]), a.get("unit"))
            rows += '<tr><td style="{0}">{1}</td><td style="{0}">{2}</td><td style="{3}">{4}</td></tr>'.format(
                _CELL, _name(a["name"], self._names), closed, _NUMBER, value)
        return '<table class="tackle-answers" style="{}"><tr><th style="{c}">answer</th><th style="{c}">closed form</th>' \
               '<th style="{c}">value</th></tr>{}</table>'.format(_TABLE, rows, c=_CELL)


def _drawn(q):
    """A variant's quantity ({value, unit, text: "20.7634 N"}) typeset, to the digits of its text."""
    text, unit = q.get("text", ""), q.get("unit") or ""
    number = text[:-len(unit)].strip() if unit and text.endswith(unit) else text
    return _quantity(number, unit) if number else ""


class Variant(dict):
    """Problem.variant(seed): a dict (parameters, answers: each a value, unit and text) that
    shows, in a notebook, as a table of the drawn parameters and the answers there."""

    def __init__(self, variant, seed=None, names=None):
        super().__init__(variant)
        self._seed = seed
        self._names = names or {}

    def _repr_html_(self):
        def rows(kind):
            return "".join('<tr><td style="{0}">{1}</td><td style="{0}">{2}</td><td style="{3}">{4}</td></tr>'.format(
                _CELL, kind if i == 0 else "", _name(name, self._names), _NUMBER, _drawn(q))
                for i, (name, q) in enumerate(self.get(kind, {}).items()))
        caption = "" if self._seed is None else '<caption style="text-align:left">variant of seed {}</caption>'.format(_e(self._seed))
        return '<table class="tackle-variant" style="{}">{}{}{}</table>'.format(_TABLE, caption, rows("parameters"), rows("answers"))


class Derivation:
    """Problem.derivation(full): the derivation as a document. A notebook shows it whole (its
    figures and equations as `derive --format html` shows them, or the answers only); its
    LaTeX is its equations; str() and repr() are its text (Problem.derive())."""

    def __init__(self, problem, full=True):
        self.problem = problem
        self.full = full

    def _repr_html_(self):
        return self.problem._notebook_html("derivation" if self.full else "answers")

    def _repr_latex_(self):
        return self.problem._notebook_latex(self.full)

    def __str__(self):
        return self.problem.derive("text", self.full)

    __repr__ = __str__


def _wrap(method, make):
    """`method` of Problem, its result made by `make(problem, result, *args, **kwargs)`."""
    @functools.wraps(method)
    def wrapped(self, *args, **kwargs):
        return make(self, method(self, *args, **kwargs), *args, **kwargs)
    return wrapped


def _argument(name, position, args, kwargs):
    return kwargs[name] if name in kwargs else args[position] if len(args) > position else ""


def _install(Problem):
    Problem.check = _wrap(Problem.check, lambda p, r, *a, **k: CheckResult(
        r, _argument("answer", 1, a, k), p._names_latex().get(r.get("unknown", ""))))
    Problem.check_equation = _wrap(Problem.check_equation, lambda p, r, *a, **k: CheckResult(r, _argument("equation", 0, a, k)))
    Problem.check_fbd = _wrap(Problem.check_fbd, lambda p, r, *a, **k: FbdGrade(r))
    Problem.check_solution = _wrap(Problem.check_solution, lambda p, r, *a, **k: (SolutionGrade(r[0], p._names_latex()), r[1]))
    Problem.answers = _wrap(Problem.answers, lambda p, r, *a, **k: AnswerList(r, p._names_latex()))
    Problem.variant = _wrap(Problem.variant, lambda p, r, *a, **k: None if r is None else Variant(
        r, _argument("seed", 0, a, k), p._names_latex()))

    def derivation(self, full=True):
        """The derivation as a document (tackle.Derivation): shown whole in a notebook, its text
        as str(); full=False: the answers only."""
        return Derivation(self, full)

    Problem.derivation = derivation
    Problem.__repr__ = lambda self: "<tackle.Problem: {}>".format(self.title)


_install(Problem)  # noqa: F821 (the module's class, put in the namespace this runs in)
