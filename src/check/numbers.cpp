// Answers that are numbers with units ("6.8 N"): read, converted to SI, compared within the
// tolerance or to significant figures, and the usual slips named; and a student's own values
// of the parameters (a variant) read for the closed forms.
#include <cmath>

#include <fmt/format.h>

#include "check/check.hpp"
#include "check/internal.hpp"
#include "core/units.hpp"
#include "core/utf8.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "numeric/evaluate.hpp"

namespace tackle {

using namespace GiNaC;
using check_detail::trim;

namespace check_detail {

// "6.8 N" -> ("6.8", "N"); "6.8" -> ("6.8", ""); nullopt when the text is not a number,
// optionally followed by something that starts like a unit (a letter).
std::optional<std::pair<std::string, std::string>> number_and_unit(const std::string& t) {
  const std::size_t sign = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  const std::size_t i = scan_number(t, sign);
  if (i == sign) return std::nullopt;
  std::string number = t.substr(0, i);
  std::size_t k = i;
  while (k < t.size() && t[k] == ' ') ++k;
  if (k == t.size()) return std::make_pair(number, std::string());
  if (!std::isalpha(static_cast<unsigned char>(t[k]))) return std::nullopt;  // "2*m", "3/4": an expression
  // The rest must look like a unit: letters, digits, / ^ * . - and spaces.
  for (std::size_t j = k; j < t.size(); ++j) {
    const char c = t[j];
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '^' || c == '*' || c == '.' || c == '-' ||
          c == ' '))
      return std::nullopt;
  }
  return std::make_pair(number, trim(t.substr(k)));
}

}  // namespace check_detail

namespace {

std::string fmt_percent(double fraction) { return fmt::format("{:g} %", fraction * 100); }

// Whether a number agrees with the correct one, to the significant figures asked or within
// the relative tolerance, and how that was judged ("within 1%").
std::pair<bool, std::string> number_agrees(double got, double want, const CheckOptions& options) {
  if (options.significant_figures) {
    const int n = *options.significant_figures;
    auto round_to = [n](double x) {
      if (x == 0) return 0.0;
      const double scale = std::pow(10.0, n - 1 - static_cast<int>(std::floor(std::log10(std::abs(x)))));
      return std::round(x * scale) / scale;
    };
    return {round_to(got) == round_to(want), "to " + std::to_string(n) + " significant figures"};
  }
  return {std::abs(got - want) <= options.relative_tolerance * std::abs(want) + 1e-300,
          "within " + fmt_percent(options.relative_tolerance)};
}

// Why a number is wrong, when a usual slip explains it: the sign, a factor of ten (a unit
// prefix), a simple factor, or g (mass for weight).
std::optional<Finding> why_number_differs(double got, double want) {
  const double ratio = want != 0 ? got / want : 0;
  auto near = [](double x, double y) { return std::abs(x - y) <= 0.01 * std::abs(y); };
  if (near(ratio, -1)) return Finding{"sign", "the sign is wrong"};
  if (ratio == 0) return std::nullopt;
  const double l10 = std::log10(std::abs(ratio));
  const double k = std::round(l10);
  if (k != 0 && std::abs(l10 - k) < 0.005)
    return Finding{"factor", "off by a factor of 10^" + std::to_string(static_cast<int>(k)) +
                                 ": check the unit prefix or the conversion"};
  if (near(std::abs(ratio), 9.81) || near(std::abs(ratio), 1 / 9.81))
    return Finding{"factor", "off by a factor of g: a mass where a weight belongs, or the reverse?"};
  const std::pair<double, const char*> simple[] = {{2.0, "2"},       {0.5, "1/2"}, {3.0, "3"},
                                                   {1.0 / 3, "1/3"}, {4.0, "4"},   {0.25, "1/4"}};
  for (const auto& [f, name] : simple)
    if (near(std::abs(ratio), f)) return Finding{"factor", std::string("off by a factor of ") + name};
  return std::nullopt;
}

}  // namespace

std::optional<exmap> Checker::values_for(const std::vector<std::pair<std::string, std::string>>& set,
                                         std::string& problem, bool* out_of_domain) const {
  if (out_of_domain) *out_of_domain = false;
  exmap values = symbols_->values();
  for (const auto& [name, text] : set) {
    const SymbolInfo* s = symbols_->find(name);
    if (!s || s->role != SymbolRole::parameter || s->definition || !s->value) {
      std::vector<std::string> settable;
      for (const auto& x : symbols_->all())
        if (x->role == SymbolRole::parameter && !x->definition && x->value) settable.push_back(x->name);
      problem = "'" + printable(name) + "' is not a parameter with a value (expected one of: " + join(settable) + ")";
      return std::nullopt;
    }
    const auto parsed = parse_expression(text, numbers_only(), answer_limits());
    const ex v = parsed.value ? evalf(*parsed.value) : ex(0);
    if (!parsed.value || !is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) {
      problem = "the value of '" + name + "' is '" + printable(text) + "' (expected a number in " +
                (s->unit.empty() ? "SI" : s->unit) + ")";
      return std::nullopt;
    }
    // A mass, a length, a stiffness... is a positive symbol: every closed form was simplified
    // with that, so a value it does not hold for would be graded against a wrong answer.
    if (s->positive && !ex_to<numeric>(v).is_positive()) {
      problem =
          "the value of '" + name + "' is " + printable(trim(text)) + (s->unit.empty() ? "" : " " + s->unit) +
          ", but '" + name + "' is assumed positive" +
          (s->dimension && !(*s->dimension == Dimension::none()) ? " (" + with_article(s->dimension->describe()) + ")"
                                                                 : "");
      if (out_of_domain) *out_of_domain = true;
      return std::nullopt;
    }
    values[s->sym] = (is_a<numeric>(*parsed.value) ? *parsed.value : v) * s->unit_to_si;
  }
  for (const auto& s : symbols_->all())
    if (s->definition && !s->geometric) {
      if (auto v = tackle::value_at(*s->definition, values))
        values[s->sym] = *v;
      else
        values.erase(s->sym);
    }
  return values;
}

CheckResult Checker::check_number(const Reference& ref, std::string_view number, std::string_view unit_text,
                                  CheckResult r, const exmap* values) const {
  r.method = "number";
  auto finish = [&](Verdict v, std::string code, std::string message) {
    r.verdict = v;
    r.summary = message;
    r.findings.push_back({std::move(code), std::move(message)});
    r.score = v == Verdict::correct ? 1.0 : 0.0;
    return r;
  };
  const auto parsed = parse_expression(number, numbers_only(), options_.limits);
  if (!parsed.value || !is_a<numeric>(*parsed.value))
    return finish(Verdict::invalid, "syntax", "the number could not be read");
  numeric value = ex_to<numeric>(*parsed.value);
  const Dimension expected = ref.dimension.value_or(Dimension::none());
  std::string unit_shown = std::string(unit_text);
  if (unit_text.empty()) {
    // (Zero is zero in every unit: 0 for a force that vanishes needs none.)
    if (!(expected == Dimension::none()) && !value.is_zero())
      return finish(Verdict::invalid, "no_unit",
                    "give the unit: the answer is " + with_article(expected.describe()) + " (in SI, " +
                        si_unit_name(expected) + ")");
  } else {
    std::string err;
    int col = 0;
    auto unit = parse_unit(unit_text, err, col);
    if (!unit)
      return finish(Verdict::invalid, "unit", err + " (expected a unit such as " + si_unit_name(expected) + ")");
    if (!(unit->dimension == expected))
      return finish(Verdict::incorrect, "dimension",
                    "the unit " + std::string(unit_text) + " is " + with_article(unit->dimension.describe()) + "; " +
                        with_article(expected.describe()) + " was expected");
    const ex si = value * unit->to_si;  // exact for rational factors; degrees go through pi
    value = ex_to<numeric>(is_a<numeric>(si) ? si : evalf(si));
  }
  r.echo_text = std::string(number) + (unit_text.empty() ? "" : " " + std::string(unit_text));
  if (options_.echo_latex)
    r.echo_latex = std::string(number) + (unit_text.empty() ? "" : "\\," + unit_latex(unit_text));
  // The student's own numbers, when given: the closed form evaluated there (exactly, then
  // to the comparison's precision).
  std::optional<numeric> at_values = ref.value;
  if (values) {
    at_values.reset();
    if (auto v = tackle::value_at(substituted(substituted(ref.closed_form, lengths_), lengths_), *values))
      if (const ex f = evalf(*v); is_a<numeric>(f) && ex_to<numeric>(f).is_real()) at_values = ex_to<numeric>(f);
  }
  if (!at_values)
    return finish(Verdict::invalid, "not_an_answer",
                  "this problem gives no numbers for every parameter: answer with a closed form in its symbols");
  const numeric expect = *at_values;
  const double got = value.to_double(), want = expect.to_double();
  const auto [ok, how] = number_agrees(got, want, options_);
  const std::string unit = si_unit_name(expected);
  if (ok) {
    r.verdict = Verdict::correct;
    r.score = 1.0;
    r.summary =
        "correct " + how +
        (options_.reveal ? " (the answer is " + decimal_string(expect, 6) + (unit.empty() ? "" : " " + unit) + ")"
                         : "");
    return r;
  }
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  if (auto why = why_number_differs(got, want)) r.findings.push_back(std::move(*why));
  const std::string got_text = decimal_string(value, 6) + (unit.empty() ? "" : " " + unit);
  r.findings.push_back({"tolerance", options_.reveal
                                         ? "expected " + decimal_string(expect, 6) + (unit.empty() ? "" : " " + unit) +
                                               " " + how + "; got " + got_text
                                         : "not " + how + " of the correct value (got " + got_text + ")"});
  r.summary = r.findings.front().message;
  return r;
}

}  // namespace tackle
