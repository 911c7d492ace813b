#include "report/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "report/html.hpp"
#include "solve/solve.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// Answers by their closed forms, parameters by their symbols.
class SweepNames : public NameResolver {
 public:
  SweepNames(const SymbolTable& table, const Derivation& d) : table_(table) {
    for (const auto& a : d.answers)
      if (a.closed_form) answers_[a.name] = *a.closed_form;
  }
  std::optional<ex> resolve(std::string_view name) const override {
    if (auto it = answers_.find(std::string(name)); it != answers_.end()) return it->second;
    if (const SymbolInfo* s = table_.find(name); s && s->role == SymbolRole::parameter) return s->sym;
    return std::nullopt;
  }
  std::vector<std::string> known_names() const override {
    std::vector<std::string> out;
    for (const auto& [k, v] : answers_) out.push_back(k);
    for (const auto& s : table_.all())
      if (s->role == SymbolRole::parameter) out.push_back(s->name);
    return out;
  }

 private:
  const SymbolTable& table_;
  std::map<std::string, ex> answers_;
};

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::string num(double v) { return fmt::format("{:.6g}", v); }

}  // namespace

SweepResult run_sweep(const Model& m, const Derivation& d, const SweepSpec& spec, const Location& where) {
  const SymbolTable& table = *m.symbols;
  Diagnostics diags;
  auto number = [&](const std::string& text, const std::string& what) -> std::optional<numeric> {
    auto r = parse_expression(text, numbers_only());
    if (!r.value || !is_a<numeric>(*r.value)) {
      diags.error(where, what + " '" + text + "' is not a number");
      return std::nullopt;
    }
    return ex_to<numeric>(*r.value);
  };
  auto parameter = [&](const std::string& name, const std::string& what) -> const SymbolInfo* {
    const SymbolInfo* s = table.find(name);
    if (!s || s->role != SymbolRole::parameter || s->definition) {
      std::vector<std::string> known;
      for (const auto& p : table.all())
        if (p->role == SymbolRole::parameter && !p->definition) known.push_back(p->name);
      diags.error(where, what + " names '" + name + "', which is not a parameter (parameters: " + join(known) + ")");
      return nullptr;
    }
    return s;
  };
  SweepResult r;
  r.title = d.title;
  // name=start:end:count
  const auto eq = spec.vary.find('=');
  std::vector<std::string> parts;
  if (eq != std::string::npos) {
    std::string rest = spec.vary.substr(eq + 1);
    for (std::size_t p; (p = rest.find(':')) != std::string::npos; rest = rest.substr(p + 1)) parts.push_back(rest.substr(0, p));
    parts.push_back(rest);
  }
  if (eq == std::string::npos || parts.size() != 3) {
    diags.error(where, "'" + spec.vary + "' is not a range to vary (expected name=start:end:count, e.g. h=0:2:41)");
    diags.throw_if_any();
  }
  const SymbolInfo* x = parameter(trim(spec.vary.substr(0, eq)), "the range to vary");
  const auto start = number(parts[0], "the start"), end = number(parts[1], "the end"), count = number(parts[2], "the count");
  if (count && (!count->is_integer() || *count < 2 || *count > 100000))
    diags.error(where, "the count '" + parts[2] + "' is not a whole number from 2 to 100000");
  exmap base = table.values();
  for (const auto& f : spec.fix) {
    const auto e2 = f.find('=');
    if (e2 == std::string::npos) {
      diags.error(where, "'" + f + "' is not a fixed value (expected name=value, e.g. l=1)");
      continue;
    }
    const SymbolInfo* s = parameter(trim(f.substr(0, e2)), "'" + f + "'");
    const auto v = number(trim(f.substr(e2 + 1)), "the value");
    if (s && v) base[s->sym] = *v * s->unit_to_si;
  }
  SweepNames names(table, d);
  std::vector<ex> curves;
  for (const auto& p : spec.plot) {
    auto parsed = parse_expression(p, names);
    if (!parsed.value) {
      diags.error(where, "plot '" + p + "': " + parsed.problems.front().message);
      continue;
    }
    curves.push_back(*parsed.value);
    r.names.push_back(trim(p));
    // For the legend: the expression as written, answers as their own symbols (N_{A} - N_{B}).
    auto shown = parse_expression(p, table);
    r.latex.push_back(to_latex(shown.value ? *shown.value : fold_definitions(*parsed.value, table)));
  }
  if (spec.plot.empty()) diags.error(where, "nothing to plot (expected a list such as N_A,N_B,N_A-N_B)");
  diags.throw_if_any();
  // One unit for the y axis when every curve has the same dimension.
  std::optional<Dimension> common;
  bool same = true;
  for (const auto& c : curves) {
    std::string problem;
    auto dim = dimension_of(c, table, problem);
    r.units.push_back(dim ? si_unit_name(*dim) : "");
    if (!dim || (common && !(*common == *dim))) same = false;
    else common = dim;
  }
  if (same && common) r.y_unit = si_unit_name(*common);
  r.x_name = x->name;
  r.x_unit = x->unit;
  r.x_latex = x->tex;
  // Against an expression in the parameters (figure 12.28 plots against h/l): its value at
  // each point, in SI (or a pure number).
  std::optional<NormalForm> against;
  if (!spec.against.empty()) {
    auto parsed = parse_expression(spec.against, table);
    std::string problem;
    if (!parsed.value) {
      diags.error(where, "against '" + spec.against + "': " + parsed.problems.front().message);
    } else if (!parsed.value->has(x->sym)) {
      diags.error(where, "against '" + trim(spec.against) + "' does not change with " + x->name + " (expected an expression in it, e.g. " + x->name + "/l)");
    } else if (auto dim = dimension_of(*parsed.value, table, problem); !dim) {
      diags.error(where, "against '" + trim(spec.against) + "': " + problem);
    } else {
      for (const auto& s : table.all())
        if (s->role != SymbolRole::parameter && parsed.value->has(s->sym))
          diags.error(where, "against '" + trim(spec.against) + "' uses '" + s->name + "', which is not a parameter");
      against.emplace(*parsed.value);
      r.varied_name = r.x_name;
      r.varied_unit = r.x_unit;
      r.x_name = trim(spec.against);
      r.x_unit = dim->exp == Dimension::none().exp ? "" : si_unit_name(*dim);
      // Inline, as an axis is labelled: h/l, not a built-up fraction.
      const ex nd = numer_denom(*parsed.value);
      auto part = [](const ex& e) { return is_a<add>(e) ? "\\left(" + to_latex(e) + "\\right)" : to_latex(e); };
      r.x_latex = nd.op(1).is_equal(1) ? to_latex(*parsed.value) : part(nd.op(0)) + "/" + part(nd.op(1));
    }
    diags.throw_if_any();
  }
  const ex factor = x->unit_to_si;
  const int n = count->to_int();
  r.y.assign(curves.size(), {});
  // Each curve's and condition's normal form once; each point only substitutes into it.
  std::vector<NormalForm> curve_forms, condition_forms;
  for (const auto& c : curves) curve_forms.emplace_back(c);
  for (const auto& cond : d.conditions) condition_forms.emplace_back(cond.simplified);
  for (int i = 0; i < n; ++i) {
    const numeric xv = *start + (*end - *start) * numeric(i, n - 1);
    exmap values = base;
    values[x->sym] = xv * factor;
    // Undefined points (a denominator that vanishes there) have no value: a gap in the curve.
    for (const auto& s : table.all())
      if (s->definition)
        if (auto v = value_at(*s->definition, values)) values[s->sym] = *v;
    if (against) {
      r.varied.push_back(xv.to_double());
      r.x.push_back(against->approx_at(values).value_or(std::nan("")));
    } else {
      r.x.push_back(xv.to_double());
    }
    for (std::size_t c = 0; c < curves.size(); ++c) {
      r.y[c].push_back(curve_forms[c].approx_at(values));
    }
    bool valid = true;
    for (std::size_t k = 0; k < d.conditions.size(); ++k) {
      const auto& cond = d.conditions[k];
      // Exact at rational points (N_A is exactly 0 at h/l = 1), else a high-precision float;
      // undefined there: not valid.
      // With roots in it (a tilted normal), a double: normal() of radicals is slow and no
      // exact zero test anyway.
      if (!is_rational_number(substituted(condition_forms[k].num, values)) || !is_rational_number(substituted(condition_forms[k].den, values))) {
        const auto a = condition_forms[k].approx_at(values);
        valid = valid && a && relation_holds(numeric(*a), cond.op);
        continue;
      }
      const auto exact = condition_forms[k].at(values);
      ex v = exact ? *exact : ex(0);
      if (!is_a<numeric>(v)) v = evalf(v);
      valid = valid && exact && is_a<numeric>(v) && ex_to<numeric>(v).is_real() && relation_holds(ex_to<numeric>(v), cond.op);
    }
    r.valid.push_back(valid);
  }
  // Where the axis' expression is undefined, no curve has a point.
  bool any = false;
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    if (std::isfinite(r.x[i])) any = true;
    else
      for (auto& c : r.y) c[i].reset();
  }
  if (!any) {
    diags.error(where, "against '" + trim(spec.against) + "' is undefined over the whole range");
    diags.throw_if_any();
  }
  return r;
}

std::string sweep_csv(const SweepResult& r) {
  std::string out;
  if (!r.varied.empty()) out += r.varied_name + (r.varied_unit.empty() ? "" : " [" + r.varied_unit + "]") + ",";
  out += r.x_name + (r.x_unit.empty() ? "" : " [" + r.x_unit + "]");
  for (const auto& n : r.names) out += "," + n + (r.y_unit.empty() ? "" : " [" + r.y_unit + "]");
  out += ",valid\n";
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    if (!r.varied.empty()) out += num(r.varied[i]) + ",";
    out += std::isfinite(r.x[i]) ? num(r.x[i]) : std::string();  // undefined there: empty
    for (const auto& curve : r.y) out += "," + (curve[i] ? num(*curve[i]) : std::string());
    out += std::string(",") + (r.valid[i] ? "true" : "false") + "\n";
  }
  return out;
}

namespace {

// The runs of a curve's points with one validity each: [begin, end) of defined points, the
// next run's first point included so that runs join (solid where valid, dashed where not).
struct Run {
  std::size_t begin, end;
  bool valid;
};
std::vector<Run> validity_runs(const SweepResult& r, std::size_t c) {
  std::vector<Run> out;
  std::size_t i = 0;
  while (i < r.x.size()) {
    while (i < r.x.size() && !r.y[c][i]) ++i;
    if (i >= r.x.size()) break;
    const bool valid = r.valid[i];
    std::size_t j = i;
    while (j < r.x.size() && r.y[c][j] && r.valid[j] == valid) ++j;
    out.push_back({i, j < r.x.size() && r.y[c][j] ? j + 1 : j, valid});
    i = j;
  }
  return out;
}

}  // namespace

std::string sweep_svg(const SweepResult& r) {
  // A plain line chart: axes with ticks, one polyline per curve (dashed where a validity
  // condition fails), a legend. Written by hand: it is a few dozen lines of SVG.
  const double W = 640, H = 420, left = 70, right = 170, top = 40, bottom = 60;
  const double pw = W - left - right, ph = H - top - bottom;
  // The axis runs over the finite values (an expression against may fall, or be undefined somewhere).
  double xmin = 1e300, xmax = -1e300, ymin = 0, ymax = 0;
  for (const double v : r.x)
    if (std::isfinite(v)) {
      xmin = std::min(xmin, v);
      xmax = std::max(xmax, v);
    }
  if (xmax - xmin < 1e-12) xmax = xmin + 1;
  bool any = false;
  for (const auto& c : r.y)
    for (const auto& v : c)
      if (v) {
        ymin = any ? std::min(ymin, *v) : *v;
        ymax = any ? std::max(ymax, *v) : *v;
        any = true;
      }
  if (ymax - ymin < 1e-12) ymax = ymin + 1;
  const double pad = 0.05 * (ymax - ymin);
  ymin -= pad;
  ymax += pad;
  auto sx = [&](double x) { return left + (x - xmin) / (xmax - xmin) * pw; };
  auto sy = [&](double y) { return top + (ymax - y) / (ymax - ymin) * ph; };
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      W, H, W, H);
  out += fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, html_escape(r.title));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", left, top, pw, ph);
  // Ticks at multiples of 1, 2 or 5 times a power of ten, about five per axis.
  auto ticks = [](double lo, double hi) {
    const double raw = (hi - lo) / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / p < 1.5 ? p : raw / p < 3.5 ? 2 * p : raw / p < 7.5 ? 5 * p : 10 * p;
    std::vector<double> t;
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) t.push_back(std::abs(v) < 1e-12 ? 0 : v);
    return t;
  };
  for (const double xv : ticks(xmin, xmax))
    out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"black\"/>"
                       "<text x=\"{0:.2f}\" y=\"{3:.2f}\" text-anchor=\"middle\">{4}</text>\n",
                       sx(xv), top + ph, top + ph + 5, top + ph + 20, num(xv));
  for (const double yv : ticks(ymin, ymax))
    out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"black\"/>"
                       "<text x=\"{3:.2f}\" y=\"{4:.2f}\" text-anchor=\"end\">{5}</text>\n",
                       left - 5, sy(yv), left, left - 8, sy(yv) + 4, num(yv));
  if (ymin < 0 && ymax > 0)
    out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#999\" stroke-dasharray=\"2,3\"/>\n", left,
                       sy(0), left + pw);
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", left + pw / 2, H - 15,
                     r.x_name + (r.x_unit.empty() ? "" : " [" + r.x_unit + "]"));
  {
    // The y axis says what it shows and in which unit: "y [m]", "N_A, N_B [N]"; curves of
    // different units say theirs in the legend.
    std::string names;
    for (std::size_t c = 0; c < r.names.size(); ++c) names += (c ? ", " : "") + r.names[c];
    const std::string title = r.y_unit.empty() ? (r.names.size() > 1 ? std::string("(units in the legend)") : names) : names + " [" + r.y_unit + "]";
    out += fmt::format("<text x=\"18\" y=\"{}\" transform=\"rotate(-90 18 {})\" text-anchor=\"middle\">{}</text>\n",
                       top + ph / 2, top + ph / 2, title);
  }
  for (std::size_t c = 0; c < r.y.size(); ++c) {
    const char* colour = colours[c % 6];
    // Runs of points with the same validity: solid where valid, dashed where not.
    for (const Run& run : validity_runs(r, c)) {
      std::string points;
      for (std::size_t j = run.begin; j < run.end; ++j) points += fmt::format("{:.2f},{:.2f} ", sx(r.x[j]), sy(*r.y[c][j]));
      out += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} points=\"{}\"/>\n", colour,
                         run.valid ? "" : " stroke-dasharray=\"6,4\"", points);
    }
    const double ly = top + 10 + 20 * static_cast<double>(c);
    out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2\"/>"
                       "<text x=\"{}\" y=\"{}\">{}</text>\n",
                       left + pw + 15, ly, left + pw + 40, ly, colour, left + pw + 45, ly + 4,
                       r.names[c] + (r.y_unit.empty() && c < r.units.size() && !r.units[c].empty() ? " [" + r.units[c] + "]" : ""));
  }
  if (std::find(r.valid.begin(), r.valid.end(), false) != r.valid.end())
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"11\">dashed: a validity</text>"
                       "<text x=\"{}\" y=\"{}\" font-size=\"11\">condition fails</text>\n",
                       left + pw + 15, top + 30 + 20 * static_cast<double>(r.y.size()), left + pw + 15,
                       top + 44 + 20 * static_cast<double>(r.y.size()));
  return out + "</svg>\n";
}

std::string sweep_pgfplots(const SweepResult& r) {
  std::string out = "\\begin{tikzpicture}\n\\begin{axis}[width=0.8\\textwidth, height=0.5\\textwidth, xlabel={$" +
                    r.x_latex + "$" + (r.x_unit.empty() ? "" : " [$" + unit_latex(r.x_unit) + "$]") +
                    "}, ylabel={" + [&] {
                      std::string names;
                      for (std::size_t c = 0; c < r.latex.size(); ++c) names += std::string(c ? ", " : "") + "$" + r.latex[c] + "$";
                      if (!r.y_unit.empty()) return names + " [$" + unit_latex(r.y_unit) + "$]";
                      return r.latex.size() > 1 ? std::string("(units in the legend)") : names;
                    }() + "}, " +
                    "legend pos=outer north east, grid=major, scaled x ticks=false, xticklabel style={/pgf/number format/fixed}]\n";
  // As the SVG: each curve in its colour, solid where every validity condition holds and
  // dashed where one fails (runs of points with the same validity, joined at their ends).
  static const char* const colours[] = {"blue", "red", "brown!70!black", "teal", "violet", "black"};
  for (std::size_t c = 0; c < r.y.size(); ++c) {
    const std::string colour = colours[c % 6];
    const std::string unit = r.y_unit.empty() && c < r.units.size() && !r.units[c].empty() ? " [$" + unit_latex(r.units[c]) + "$]" : "";
    out += "\\addlegendimage{color=" + colour + ", thick}\n\\addlegendentry{$" + r.latex[c] + "$" + unit + "}\n";
    for (const Run& run : validity_runs(r, c)) {
      std::string points;
      for (std::size_t j = run.begin; j < run.end; ++j) points += "(" + num(r.x[j]) + "," + num(*r.y[c][j]) + ") ";
      out += "\\addplot[color=" + colour + ", thick, forget plot" + (run.valid ? "" : ", dashed") + "] coordinates {" + points + "};\n";
    }
  }
  if (std::find(r.valid.begin(), r.valid.end(), false) != r.valid.end())
    out += "\\addlegendimage{empty legend}\n\\addlegendentry{dashed: invalid}\n";
  return out + "\\end{axis}\n\\end{tikzpicture}\n";
}

}  // namespace tackle
