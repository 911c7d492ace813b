"""A PrairieLearn question graded by tackle in process (the `tackle` Python module must be
importable in the course's grading image: install tackle there, see the README).

generate(): draws a variant from the problem's parameter ranges (tackle's own variants).
parse():    an answer tackle cannot read (a syntax error, a number without its unit) is a
            format error: the submission is invalid and costs no attempt.
grade():    tackle checks the answer against the closed form at this variant's numbers; the
            feedback never names the correct value."""
import os
import random

import tackle

PROBLEM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "problem.yaml")
ANSWERS = ["T"]


def _problem():
    return tackle.Problem(PROBLEM)


def generate(data):
    variant = _problem().variant(seed=random.randrange(2**32))
    for name, value in variant["parameters"].items():
        data["params"][name] = value["value"]
    for name in ANSWERS:
        data["correct_answers"][name] = variant["answers"][name]["text"]


def _checks(data):
    problem = _problem()
    params = {name: data["params"][name] for name in ("F", "m_A", "m_B")}
    for name in ANSWERS:
        answer = data["submitted_answers"].get(name)
        if answer is None:
            continue
        yield name, problem.check(name, str(answer), params=params)


def parse(data):
    for name, result in _checks(data):
        if result["verdict"] == "invalid":
            data["format_errors"][name] = result["summary"]


def grade(data):
    total = 0.0
    for name, result in _checks(data):
        data["partial_scores"][name] = {"score": result["score"], "weight": 1, "feedback": result["summary"]}
        data["feedback"][name] = result["summary"]
        total += result["score"]
    data["score"] = total / len(ANSWERS)
