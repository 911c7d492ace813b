"""A PrairieLearn question graded by tackle in process: the student's worked solution (one
equation a field, then T), graded as a whole with Problem.check_solution and rubric.yaml (the
`tackle` Python module must be importable in the course's grading image: install tackle there,
see the README). PrairieLearn grades on submission: there is no live checking here (for that,
`tackle page` with scripts/step-server, docs/checking.md "A page to try it").

generate(): the description's own numbers (the solution's answer is checked at them).
parse():    a step or an answer tackle cannot read (a syntax error, no `=`, an unknown name, a
            number without its unit) is a format error: the submission is invalid and costs no
            attempt.
grade():    each step's verdict and summary as its feedback (never the correct equation), the
            rubric's parts (balances, constraints, answers), what the incorrect steps took,
            and the score, in proportion."""
import json
import os

import tackle

HERE = os.path.dirname(os.path.abspath(__file__))
PROBLEM = os.path.join(HERE, "problem.yaml")
RUBRIC = os.path.join(HERE, "rubric.yaml")
STEPS = ["step%d" % k for k in range(1, 7)]
ANSWERS = ["T"]


def _problem():
    return tackle.Problem(PROBLEM)


def _submitted(data):
    """(field, step) for each field filled in, in the page's order."""
    out = []
    for name in STEPS:
        text = str(data["submitted_answers"].get(name) or "").strip()
        if text:
            out.append((name, {"equation": text}))
    for name in ANSWERS:
        text = str(data["submitted_answers"].get(name) or "").strip()
        if text:
            out.append((name, {"answer": text, "unknown": name}))
    return out


def generate(data):
    problem = _problem()
    # The description's numbers, in the units it states them in (F in N, masses in kg).
    for p in json.loads(problem.derive(format="json", full=False))["parameters"]:
        if p["kind"] == "parameter" and p["value"] is not None:
            value = p["stated"]["value"] if "stated" in p else p["value"]  # stated: a unit other than SI's
            data["params"][p["name"]] = int(value) if float(value).is_integer() else value
    for a in problem.answers():
        if a["name"] in ANSWERS:
            data["correct_answers"][a["name"]] = "%g %s" % (a["value"], a["unit"])


def parse(data):
    problem = _problem()
    for name, step in _submitted(data):
        if "equation" in step:
            result = problem.check_equation(step["equation"])
        else:
            result = problem.check(step["unknown"], step["answer"])
        if result["verdict"] == "invalid":
            data["format_errors"][name] = result["summary"]


def grade(data):
    submitted = _submitted(data)
    with open(RUBRIC, encoding="utf-8") as f:
        rubric = f.read()
    solution = json.dumps({"steps": [step for _, step in submitted]})
    g, _ = _problem().check_solution(solution, rubric=rubric, results_format="prairielearn")
    for (name, _), result in zip(submitted, g["steps"]):
        feedback = "%s: %s" % (result["verdict"], result["summary"])
        if result.get("note"):  # a correct step that earns nothing for the balances (derived from them)
            feedback += "; " + result["note"]
        data["partial_scores"][name] = {"score": 1.0 if result["verdict"] == "correct" else 0.0, "weight": 0, "feedback": feedback}
        data["feedback"][name] = feedback
    parts = "; ".join("%s %g of %g" % (p["name"], p["score"], p["max_score"]) if p["graded"]
                      else "%s not graded (%s)" % (p["name"], p["not_graded"]) for p in g["parts"])
    if g["wrong"] and g["penalty"]:
        parts += "; %d incorrect step%s: -%g" % (g["wrong"], "" if g["wrong"] == 1 else "s", g["penalty"])
    missing = ", ".join(g["missing"]) or "none"
    data["feedback"]["solution"] = "%s. Missing (needed for T): %s." % (parts, missing)
    data["score"] = g["score"] / g["max_score"] if g["max_score"] > 0 else 0.0
