#include "crosscheck/claims.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "expr/print.hpp"
#include "solve/answers.hpp"

namespace crosscheck {

namespace {

std::set<std::string> unknowns_in(const GiNaC::ex& e, const tackle::SymbolTable& table) {
  std::set<std::string> out;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::symbol>(*it))
      if (const auto* s = table.find(*it); s && s->role == tackle::SymbolRole::unknown) out.insert(s->name);
  return out;
}

bool relation(double v, const std::string& op) {
  if (op == ">=") return v >= 0;
  if (op == ">") return v > 0;
  if (op == "<=") return v <= 0;
  if (op == "<") return v < 0;
  return v == 0;
}

std::string inverted(const std::string& op) {
  if (op == ">=") return "<";
  if (op == ">") return "<=";
  if (op == "<=") return ">";
  if (op == "<") return ">=";
  return op;
}

// A text in the description's or tackle's names evaluated with the model's values; nothing
// when it names what the model has no value for, or what it leaves undetermined.
std::optional<double> model_value(const std::string& text, const ClaimState& s) {
  return evaluate_text(text, s.values, [&](const std::string& n) {
    const Quantity* q = s.instant->find(n);
    return !q || q->determined;
  });
}

void disagree(Outcome& out, const ClaimState& s, std::string what, double tackle, double model) {
  out.disagreements.push_back({std::move(what), tackle, model, s.where});
}

// Every quantity asked for: tackle answers it, and with the model's value, wherever the model
// determines it.
void compare_asked(const Claims& c, const ClaimState& s, Outcome& out, std::set<std::string>& notes) {
  for (const auto& a : c.asked) {
    const auto model = model_value(a.expr ? *a.expr : a.name, s);
    if (!model) {
      notes.insert("the answer for " + a.name + " (the model does not determine it)");
      continue;
    }
    if (!a.answered) {
      disagree(out, s, "the answer for " + a.name + ": tackle gives none (" + a.status + "), the model determines it",
               0, *model);
      continue;
    }
    const auto tk = s.tackle_value(a.value);
    if (!tk) {
      disagree(out, s, "the answer for " + a.name + ": tackle's closed form is no number here (an unknown inside)", 0,
               *model);
      continue;
    }
    const double scale = std::max(s.force_scale, s.accel_scale);
    if (std::abs(*tk - *model) > 1e-9 * std::max(std::abs(*tk), std::abs(*model)) + 1e-10 * scale)
      disagree(out, s, "the answer for " + a.name, *tk, *model);
    ++out.compared;
  }
}

// Which of tackle's conditions speak of a requirement of the model: those about the same
// forces (a string's T, a contact's N, a grip's F and N); an elastic cord's, about no force,
// by their order among the cords.
std::vector<std::vector<std::size_t>> matched(const Claims& c, const Model& m) {
  std::vector<std::vector<std::size_t>> out(m.requirements().size());
  std::vector<std::size_t> cords;
  for (std::size_t i = 0; i < c.conditions.size(); ++i)
    if (c.conditions[i].forces.empty() && c.conditions[i].source.rfind("elastic cord", 0) == 0) cords.push_back(i);
  std::size_t next_cord = 0;
  for (std::size_t r = 0; r < m.requirements().size(); ++r) {
    const Requirement& q = m.requirements()[r];
    if (q.kind == Requirement::taut) {
      if (next_cord < cords.size()) out[r].push_back(cords[next_cord++]);
      continue;
    }
    std::set<std::string> forces =
        q.kind == Requirement::cone ? std::set<std::string>{q.force, q.normal} : std::set<std::string>{q.force};
    if (!q.force_too.empty()) forces.insert(q.force_too);  // (a 3-D grip: sqrt(F_1^2 + F_2^2) <= mu N)
    for (std::size_t i = 0; i < c.conditions.size(); ++i)
      if (c.conditions[i].forces == forces) out[r].push_back(i);
  }
  return out;
}

// The model's requirements against tackle's conditions on the same forces: where the model
// clearly meets one (or clearly fails it), tackle's conditions must all hold (or one fail);
// a requirement tackle states no condition for is a disagreement.
void compare_conditions(const Claims& c, const Model& m, const ClaimState& s, Outcome& out,
                        std::set<std::string>& notes) {
  const auto margins = m.margins(*s.state, *s.instant);
  const auto groups = matched(c, m);
  for (std::size_t r = 0; r < margins.size(); ++r) {
    const Margin& mg = margins[r];
    if (groups[r].empty()) {
      // (a force tackle does not solve for, internal to the system its `derive:` balances, has
      // no condition either)
      if (!mg.determined || (mg.requirement->kind != Requirement::taut && !c.solved.count(mg.requirement->force)))
        notes.insert("whether " + mg.requirement->what + " (tackle does not solve for its force)");
      else
        disagree(out, s, "tackle states no condition for what the model requires: " + mg.requirement->what, 0,
                 mg.value);
      continue;
    }
    if (!mg.determined || std::abs(mg.value) <= 1e-6 * s.force_scale) continue;  // (not clear either way)
    bool all = true, known = true;
    std::string said;
    for (std::size_t i : groups[r]) {
      const auto& cond = c.conditions[i];
      const auto v = s.tackle_value(cond.value);
      if (!v)
        known = false;
      else
        all = all && relation(*v, cond.op);
      said += (said.empty() ? "" : ", ") + cond.lhs + " " + cond.op + " " + cond.rhs;
      // what tackle states of the given numbers, and of every value of the parameters (of a
      // pair, a grip's F <= mu N and -F <= mu N, one fails where the requirement is not met:
      // the other may hold, even always; the pair as a whole is compared below)
      const bool alone = groups[r].size() == 1 || mg.value > 0;
      if (alone && s.base && cond.holds && *cond.holds != (mg.value > 0))
        disagree(out, s,
                 fmt::format("condition {} at the given numbers: tackle says it {}, the model: {} {}",
                             cond.lhs + " " + cond.op + " " + cond.rhs, *cond.holds ? "holds" : "fails",
                             mg.requirement->what, mg.value > 0 ? "(met)" : "(not met)"),
                 *cond.holds ? 1 : 0, mg.value);
      if (alone && cond.always && *cond.always != (mg.value > 0))
        disagree(out, s,
                 fmt::format("condition {}: tackle says it {} holds, the model: {} {}",
                             cond.lhs + " " + cond.op + " " + cond.rhs, *cond.always ? "always" : "never",
                             mg.requirement->what, mg.value > 0 ? "(met)" : "(not met)"),
                 *cond.always ? 1 : 0, mg.value);
    }
    if (groups[r].size() > 1 && mg.value < 0) {
      bool every = true;
      for (std::size_t i : groups[r]) every = every && c.conditions[i].always && *c.conditions[i].always;
      if (every)
        disagree(out, s,
                 fmt::format("conditions {}: tackle says they always hold, the model: {} (not met)", said,
                             mg.requirement->what),
                 1, mg.value);
    }
    if (!known) {
      notes.insert("the conditions on " + mg.requirement->what + " (tackle's is no number at some state)");
      continue;
    }
    ++out.compared;
    if (all != (mg.value > 0))
      disagree(out, s,
               fmt::format("conditions {} ({}): tackle says {}, the model: {} {}", said,
                           c.conditions[groups[r].front()].source, all ? "they hold" : "one fails",
                           mg.requirement->what, mg.value > 0 ? "(met)" : "(not met)"),
               all ? 1 : 0, mg.value);
  }
}

// Each condition as the rule states it, with the model's own values of its forces: it holds
// exactly where tackle's, with the solution put in, holds.
void compare_substituted(const Claims& c, const ClaimState& s, Outcome& out) {
  for (const auto& cond : c.conditions) {
    const auto l = model_value(cond.lhs, s), r = model_value(cond.rhs, s), v = s.tackle_value(cond.value);
    if (!l || !r || !v || std::abs(*l - *r) <= 1e-6 * s.force_scale) continue;
    if (relation(*l - *r, cond.op) != relation(*v, cond.op))
      disagree(
          out, s,
          fmt::format("condition {} {} {} ({}) with the solution put in", cond.lhs, cond.op, cond.rhs, cond.source), *v,
          *l - *r);
  }
}

// A sliding contact on a turning body: which way it slips, so which way its friction acts.
void compare_slips(const Claims& c, const Model& m, const ClaimState& s, Outcome& out, std::set<std::string>& notes) {
  for (const auto& [source, speed] : c.slips) {
    const auto at = source.rfind(" at ");
    const auto model = at == std::string::npos ? std::nullopt : m.slip_speed("N_" + source.substr(at + 4), *s.state);
    const auto tk = s.tackle_value(speed);
    if (!model || !tk) {
      notes.insert("the slip speed of " + source);
      continue;
    }
    ++out.compared;
    if (std::abs(*tk - *model) > 1e-9 * std::max({std::abs(*tk), std::abs(*model), 1.0}))
      disagree(out, s, "the slip speed of " + source + " (the friction acts against it)", *tk, *model);
  }
}

}  // namespace

Claims claims_of(const tackle::Analysis& a, const tackle::Description& d) {
  Claims c;
  const auto& table = *a.model.symbols;
  const tackle::Answers answers = tackle::answer(a.model, a.system, a.solution, 10);
  // What is asked: the description's `find`, else every unknown (as tackle then answers)
  std::vector<std::pair<std::string, std::optional<std::string>>> asked;
  for (const auto& f : d.find)
    asked.emplace_back(f.name.text, f.expr ? std::optional<std::string>(f.expr->text) : std::nullopt);
  if (d.find.empty())
    for (const auto& u : a.model.candidates)
      if (const auto* s = table.find(u)) asked.emplace_back(s->name, std::nullopt);
  for (const auto& [name, expr] : asked) {
    Claims::Asked q{name, expr, false, 0, "left out"};
    for (const auto& an : answers.answers) {
      if (an.name != q.name) continue;
      q.answered = an.status == tackle::Answer::Status::determined && an.closed_form.has_value();
      if (q.answered) q.value = *an.closed_form;
      q.status = q.answered ? "" : an.reason.empty() ? "not determined" : an.reason;
    }
    c.asked.push_back(q);
  }
  for (std::size_t i = 0; i < a.solution.conditions.size(); ++i) {
    const auto& cc = a.solution.conditions[i];
    Claims::Condition k{cc.condition->source,
                        cc.condition->op,
                        tackle::to_text(cc.condition->lhs),
                        tackle::to_text(cc.condition->rhs),
                        unknowns_in(cc.condition->lhs - cc.condition->rhs, table),
                        cc.expr,
                        std::nullopt,
                        cc.always};
    if (i < answers.conditions.size()) k.holds = answers.conditions[i].holds;
    c.conditions.push_back(k);
  }
  for (const auto& s : a.model.slips) c.slips.emplace_back(s.source, s.speed);
  for (const auto& v : a.solution.values)
    if (const auto* s = table.find(v.unknown)) c.solved.insert(s->name);
  return c;
}

void plant(Claims& c, const Options& o) {
  if (o.perturb_drop_answer && !c.asked.empty()) {
    c.asked.front().answered = false;
    c.asked.front().status = "left out on purpose (--perturb-drop-answer)";
  }
  if (o.perturb_invert_condition && !c.conditions.empty()) {
    auto& k = c.conditions.front();
    k.op = inverted(k.op);
    if (k.holds) k.holds = !*k.holds;
    if (k.always) k.always = !*k.always;
  }
}

void compare_claims(const Claims& c, const Model& m, const ClaimState& s, Outcome& out, std::set<std::string>& notes) {
  compare_asked(c, s, out, notes);
  compare_conditions(c, m, s, out, notes);
  compare_substituted(c, s, out);
  compare_slips(c, m, s, out, notes);
}

}  // namespace crosscheck
