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
    for (std::size_t p; (p = rest.find(':')) != std::string::npos; rest = rest.substr(p + 1))
      parts.push_back(rest.substr(0, p));
    parts.push_back(rest);
  }
  if (eq == std::string::npos || parts.size() != 3) {
    diags.error(where, "'" + spec.vary + "' is not a range to vary (expected name=start:end:count, e.g. h=0:2:41)");
    diags.throw_if_any();
  }
  const SymbolInfo* x = parameter(trim(spec.vary.substr(0, eq)), "the range to vary");
  const auto start = number(parts[0], "the start"), end = number(parts[1], "the end"),
             count = number(parts[2], "the count");
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
    if (!dim || (common && !(*common == *dim)))
      same = false;
    else
      common = dim;
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
      diags.error(where, "against '" + trim(spec.against) + "' does not change with " + x->name +
                             " (expected an expression in it, e.g. " + x->name + "/l)");
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
  // The values at one point of the varied parameter: the definitions (undefined points, a
  // denominator that vanishes there, have no value: a gap in the curve).
  auto values_at = [&](const numeric& xv) {
    exmap values = base;
    values[x->sym] = xv * factor;
    for (const auto& s : table.all())
      if (s->definition)
        if (auto v = value_at(*s->definition, values)) values[s->sym] = *v;
    return values;
  };
  // Every validity condition holds: exact at rational points (N_A is exactly 0 at h/l = 1),
  // else a high-precision float; undefined there: not valid. With roots in it (a tilted
  // normal), a double: normal() of radicals is slow and no exact zero test anyway.
  auto holds = [&](const exmap& values, bool exact) {
    for (std::size_t k = 0; k < d.conditions.size(); ++k) {
      const auto& cond = d.conditions[k];
      if (!exact || !is_rational_number(substituted(condition_forms[k].num, values)) ||
          !is_rational_number(substituted(condition_forms[k].den, values))) {
        const auto a = condition_forms[k].approx_at(values);
        if (!a || !relation_holds(numeric(*a), cond.op)) return false;
        continue;
      }
      const auto at = condition_forms[k].at(values);
      ex v = at ? *at : ex(0);
      if (!is_a<numeric>(v)) v = evalf(v);
      if (!at || !is_a<numeric>(v) || !ex_to<numeric>(v).is_real() || !relation_holds(ex_to<numeric>(v), cond.op))
        return false;
    }
    return true;
  };
  struct Point {
    double x, varied;
    std::vector<std::optional<double>> y;
    bool valid, boundary = false, inserted = false;
  };
  auto point = [&](const numeric& xv, bool exact) {
    const exmap values = values_at(xv);
    Point p{against ? against->approx_at(values).value_or(std::nan("")) : xv.to_double(),
            xv.to_double(),
            {},
            holds(values, exact)};
    for (const auto& f : curve_forms) p.y.push_back(f.approx_at(values));
    return p;
  };
  auto sample = [&](int i) { return *start + (*end - *start) * numeric(i, n - 1); };
  std::vector<Point> points;
  for (int i = 0; i < n; ++i) {
    Point p = point(sample(i), true);
    // Where the validity changes, the bound between the two samples, found by bisection: the
    // dashed part begins where the condition fails, not at the next sample.
    if (i > 0 && p.valid != points.back().valid) {
      const bool from = points.back().valid;
      const double a = sample(i - 1).to_double(), b = sample(i).to_double();
      double lo = a, hi = b;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (holds(values_at(numeric(mid)), false) == from ? lo : hi) = mid;
      }
      const double at = from ? lo : hi;  // on the valid side
      const double tol = 1e-9 * std::abs(b - a);
      if (std::abs(at - a) <= tol) {
        points.back().boundary = true;
      } else if (std::abs(at - b) <= tol) {
        p.boundary = true;
      } else {
        Point q = point(numeric(at), false);
        q.valid = q.boundary = q.inserted = true;
        points.push_back(std::move(q));
      }
    }
    points.push_back(std::move(p));
  }
  const bool any_boundary = std::any_of(points.begin(), points.end(), [](const Point& p) { return p.boundary; });
  for (const Point& p : points) {
    r.x.push_back(p.x);
    if (against) r.varied.push_back(p.varied);
    for (std::size_t c = 0; c < curves.size(); ++c) r.y[c].push_back(p.y[c]);
    r.valid.push_back(p.valid);
    if (any_boundary) r.boundary.push_back(p.boundary), r.inserted.push_back(p.inserted);
  }
  // Where the axis' expression is undefined, no curve has a point.
  bool any = false;
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    if (std::isfinite(r.x[i]))
      any = true;
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
    if (r.is_inserted(i)) continue;  // the samples only
    if (!r.varied.empty()) out += num(r.varied[i]) + ",";
    out += std::isfinite(r.x[i]) ? num(r.x[i]) : std::string();  // undefined there: empty
    for (const auto& curve : r.y) out += "," + (curve[i] ? num(*curve[i]) : std::string());
    out += std::string(",") + (r.valid[i] ? "true" : "false") + "\n";
  }
  return out;
}

namespace {

// The runs of a curve's points with one validity each: [begin, end) of defined points. A run
// ends at a boundary point (where the failing condition reaches its bound) and the next one
// begins there; without one, the next run's first point is included so that runs join (solid
// where valid, dashed where not).
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
    // A run starting at a boundary has the validity of the point after it.
    const bool valid = r.is_boundary(i) && i + 1 < r.x.size() && r.y[c][i + 1] ? r.valid[i + 1] : r.valid[i];
    std::size_t j = i + 1;
    while (j < r.x.size() && r.y[c][j] && r.valid[j] == valid && !r.is_boundary(j)) ++j;
    if (j < r.x.size() && r.y[c][j] && r.is_boundary(j) && r.valid[j] == valid) {
      out.push_back({i, j + 1, valid});  // up to the boundary, which begins the next run
      i = j;
      continue;
    }
    out.push_back({i, j < r.x.size() && r.y[c][j] ? j + 1 : j, valid});
    i = j;
  }
  return out;
}

}  // namespace

namespace {

// The curves in panels, one per unit: metres and newtons are not drawn against one axis. One
// panel when every curve has the same unit (or there is one curve).
std::vector<std::vector<std::size_t>> panels_of(const SweepResult& r) {
  std::vector<std::string> units;
  std::vector<std::vector<std::size_t>> out;
  for (std::size_t c = 0; c < r.y.size(); ++c) {
    const std::string u = r.y_unit.empty() && c < r.units.size() ? r.units[c] : r.y_unit;
    const auto it = std::find(units.begin(), units.end(), u);
    if (it == units.end()) {
      units.push_back(u);
      out.push_back({c});
    } else {
      out[static_cast<std::size_t>(it - units.begin())].push_back(c);
    }
  }
  return out;
}

// A panel's unit: its curves' (all the same).
std::string panel_unit(const SweepResult& r, const std::vector<std::size_t>& panel) {
  if (!r.y_unit.empty()) return r.y_unit;
  return panel.front() < r.units.size() ? r.units[panel.front()] : "";
}

bool any_invalid(const SweepResult& r) { return std::find(r.valid.begin(), r.valid.end(), false) != r.valid.end(); }

}  // namespace

std::string sweep_svg(const SweepResult& r) {
  // A plain line chart: axes with ticks, one polyline per curve (dashed where a validity
  // condition fails), a legend; one panel per unit, one above the other, sharing the
  // horizontal axis. Written by hand: it is a few dozen lines of SVG.
  const auto panels = panels_of(r);
  const std::size_t k = panels.size();
  const double W = 640, left = 70, right = 170, top = 40, bottom = 60, gap = 30;
  const double pw = W - left - right, ph = k == 1 ? 320 : 200;
  const double H = top + static_cast<double>(k) * ph + static_cast<double>(k - 1) * gap + bottom;
  // The axis runs over the finite values (an expression against may fall, or be undefined somewhere).
  double xmin = 1e300, xmax = -1e300;
  for (const double v : r.x)
    if (std::isfinite(v)) {
      xmin = std::min(xmin, v);
      xmax = std::max(xmax, v);
    }
  if (xmax - xmin < 1e-12) xmax = xmin + 1;
  auto sx = [&](double x) { return left + (x - xmin) / (xmax - xmin) * pw; };
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      W, H, W, H);
  out += fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, html_escape(r.title));
  // Ticks at multiples of 1, 2 or 5 times a power of ten, about five per axis.
  auto ticks = [](double lo, double hi) {
    const double raw = (hi - lo) / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / p < 1.5 ? p : raw / p < 3.5 ? 2 * p : raw / p < 7.5 ? 5 * p : 10 * p;
    std::vector<double> t;
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
      t.push_back(std::abs(v) < 1e-12 ? 0 : v);
    return t;
  };
  for (std::size_t p = 0; p < k; ++p) {
    const auto& panel = panels[p];
    const double ptop = top + static_cast<double>(p) * (ph + gap);
    double ymin = 0, ymax = 0;
    bool any = false;
    for (const std::size_t c : panel)
      for (const auto& v : r.y[c])
        if (v) {
          ymin = any ? std::min(ymin, *v) : *v;
          ymax = any ? std::max(ymax, *v) : *v;
          any = true;
        }
    if (ymax - ymin < 1e-12) ymax = ymin + 1;
    const double pad = 0.05 * (ymax - ymin);
    ymin -= pad;
    ymax += pad;
    auto sy = [&](double y) { return ptop + (ymax - y) / (ymax - ymin) * ph; };
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", left,
                       ptop, pw, ph);
    // The horizontal axis' numbers under the lowest panel only.
    for (const double xv : ticks(xmin, xmax)) {
      out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"black\"/>", sx(xv),
                         ptop + ph, ptop + ph + 5);
      if (p + 1 == k)
        out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>", sx(xv), ptop + ph + 20,
                           num(xv));
      out += "\n";
    }
    for (const double yv : ticks(ymin, ymax))
      out += fmt::format(
          "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"black\"/>"
          "<text x=\"{3:.2f}\" y=\"{4:.2f}\" text-anchor=\"end\">{5}</text>\n",
          left - 5, sy(yv), left, left - 8, sy(yv) + 4, num(yv));
    if (ymin < 0 && ymax > 0)
      out += fmt::format(
          "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#999\" "
          "stroke-dasharray=\"2,3\"/>\n",
          left, sy(0), left + pw);
    {
      // The y axis says what it shows and in which unit: "y [m]", "N_A, N_B [N]"; curves
      // whose units are unknown say so.
      std::string names;
      for (const std::size_t c : panel) names += (names.empty() ? "" : ", ") + r.names[c];
      const std::string unit = panel_unit(r, panel);
      const std::string title = unit.empty() ? names : names + " [" + unit + "]";
      out +=
          fmt::format("<text x=\"18\" y=\"{0}\" transform=\"rotate(-90 18 {0})\" text-anchor=\"middle\">{1}</text>\n",
                      ptop + ph / 2, html_escape(title));
    }
    for (std::size_t n = 0; n < panel.size(); ++n) {
      const std::size_t c = panel[n];
      const char* colour = colours[c % 6];
      // Runs of points with the same validity: solid where valid, dashed where not.
      for (const Run& run : validity_runs(r, c)) {
        std::string points;
        for (std::size_t j = run.begin; j < run.end; ++j)
          points += fmt::format("{:.2f},{:.2f} ", sx(r.x[j]), sy(*r.y[c][j]));
        out += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} points=\"{}\"/>\n", colour,
                           run.valid ? "" : " stroke-dasharray=\"6,4\"", points);
      }
      const double ly = ptop + 10 + 20 * static_cast<double>(n);
      out += fmt::format(
          "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2\"/>"
          "<text x=\"{}\" y=\"{}\">{}</text>\n",
          left + pw + 15, ly, left + pw + 40, ly, colour, left + pw + 45, ly + 4, html_escape(r.names[c]));
    }
    if (p + 1 == k && any_invalid(r))
      out += fmt::format(
          "<text x=\"{}\" y=\"{}\" font-size=\"11\">dashed: a validity</text>"
          "<text x=\"{}\" y=\"{}\" font-size=\"11\">condition fails</text>\n",
          left + pw + 15, ptop + 30 + 20 * static_cast<double>(panel.size()), left + pw + 15,
          ptop + 44 + 20 * static_cast<double>(panel.size()));
  }
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", left + pw / 2, H - 15,
                     html_escape(r.x_name + (r.x_unit.empty() ? "" : " [" + r.x_unit + "]")));
  return out + "</svg>\n";
}

std::string sweep_pgfplots(const SweepResult& r) {
  // One axis per unit, one under the other, the horizontal axis' label under the lowest.
  const auto panels = panels_of(r);
  const std::size_t k = panels.size();
  const std::string xlabel = "$" + r.x_latex + "$" + (r.x_unit.empty() ? "" : " [$" + unit_latex(r.x_unit) + "$]");
  // As the SVG: each curve in its colour, solid where every validity condition holds and
  // dashed where one fails (runs of points with the same validity, joined at their ends).
  static const char* const colours[] = {"blue", "red", "brown!70!black", "teal", "violet", "black"};
  std::string out = "\\begin{tikzpicture}\n";
  for (std::size_t p = 0; p < k; ++p) {
    const auto& panel = panels[p];
    std::string names;
    for (const std::size_t c : panel) names += std::string(names.empty() ? "" : ", ") + "$" + r.latex[c] + "$";
    const std::string unit = panel_unit(r, panel);
    const std::string ylabel = unit.empty() ? names : names + " [$" + unit_latex(unit) + "$]";
    out +=
        "\\begin{axis}[name=panel" + std::to_string(p) + ", width=0.8\\textwidth, height=" + (k == 1 ? "0.5" : "0.32") +
        "\\textwidth, " +
        (p == 0 ? std::string()
                : "at={(panel" + std::to_string(p - 1) + ".south west)}, anchor=north west, yshift=-0.6cm, ") +
        (p + 1 == k ? "xlabel={" + xlabel + "}, " : std::string("xticklabels={}, ")) + "ylabel={" + ylabel + "}, " +
        "legend pos=outer north east, grid=major, scaled x ticks=false, xticklabel style={/pgf/number format/fixed}]\n";
    for (const std::size_t c : panel) {
      const std::string colour = colours[c % 6];
      out += "\\addlegendimage{color=" + colour + ", thick}\n\\addlegendentry{$" + r.latex[c] + "$}\n";
      for (const Run& run : validity_runs(r, c)) {
        std::string points;
        for (std::size_t j = run.begin; j < run.end; ++j) points += "(" + num(r.x[j]) + "," + num(*r.y[c][j]) + ") ";
        out += "\\addplot[color=" + colour + ", thick, forget plot" + (run.valid ? "" : ", dashed") +
               "] coordinates {" + points + "};\n";
      }
    }
    if (p + 1 == k && any_invalid(r)) out += "\\addlegendimage{empty legend}\n\\addlegendentry{dashed: invalid}\n";
    out += "\\end{axis}\n";
  }
  return out + "\\end{tikzpicture}\n";
}

std::string simulation_text(const Simulation& s) {
  std::string out = s.table.title + "\n";
  out += "Simulated to t = " + decimal_string(numeric(s.reached), 6) + " s (" + std::to_string(s.steps) +
         " steps, Dormand-Prince 5(4))";
  if (s.complete && s.not_followed.empty())
    out += "; the model holds throughout.\n";
  else if (s.complete)
    out += "; what it follows holds throughout.\n";
  else
    out += ".\n";
  for (const auto& [source, why] : s.not_followed) out += "Not followed: " + source + " (" + why + ").\n";
  if (!s.stopped.empty()) out += "Stopped: " + s.stopped + ".\n";
  for (const auto& e : s.events)
    out +=
        "Event at t = " + decimal_string(numeric(e.t), 6) + " s: " + e.what + (e.ends ? " (the run ends)" : "") + "\n";
  out += "\n" + sweep_csv(s.table);
  return out;
}

}  // namespace tackle
