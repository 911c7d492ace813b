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

std::string num(double v) { return fmt::format("{:.6g}", v); }

}  // namespace

SweepResult run_sweep(const Model& m, const Derivation& d, const SweepSpec& spec, const Location& where) {
  SweepResult r = evaluate_sweep(m, d.answers, d.conditions, spec, where);
  r.title = d.title;
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

// Ticks at multiples of 1, 2 or 5 times a power of ten, about five per axis.
std::vector<double> ticks(double lo, double hi) {
  const double raw = (hi - lo) / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw / p < 1.5 ? p : raw / p < 3.5 ? 2 * p : raw / p < 7.5 ? 5 * p : 10 * p;
  std::vector<double> t;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
    t.push_back(std::abs(v) < 1e-12 ? 0 : v);
  return t;
}

// The steps of a sweep's SVG chart and what they share: the panels (one per unit, one above
// the other, sharing the horizontal axis), the page's measures, the horizontal scale, and the
// text written so far. A plain line chart: axes with ticks, one polyline per curve (dashed
// where a validity condition fails), a legend. Written by hand: it is a few dozen lines of SVG.
struct SvgChart {
  static constexpr double W = 640, left = 70, right = 170, top = 40, bottom = 60, gap = 30;
  static constexpr double pw = W - left - right;
  const SweepResult& r;
  std::vector<std::vector<std::size_t>> panels;
  std::size_t k;
  double ph, H;
  double xmin = 1e300, xmax = -1e300;
  std::string out;

  explicit SvgChart(const SweepResult& result)
      : r(result),
        panels(panels_of(result)),
        k(panels.size()),
        ph(k == 1 ? 320 : 200),
        H(top + static_cast<double>(k) * ph + static_cast<double>(k - 1) * gap + bottom) {
    // The axis runs over the finite values (an expression against may fall, or be undefined somewhere).
    for (const double v : r.x)
      if (std::isfinite(v)) {
        xmin = std::min(xmin, v);
        xmax = std::max(xmax, v);
      }
    if (xmax - xmin < 1e-12) xmax = xmin + 1;
  }

  // A horizontal value's place on the page.
  double sx(double x) const { return left + (x - xmin) / (xmax - xmin) * pw; }

  // The page, its background and the title.
  void header() {
    out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
        "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
        W, H, W, H);
    out += fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, html_escape(r.title));
  }

  // One panel of curves, `p` from the top: its box, axes, curves and legend.
  void panel(std::size_t p) {
    const auto& curves = panels[p];
    const double ptop = top + static_cast<double>(p) * (ph + gap);
    const auto [ymin, ymax] = y_range(curves);
    auto sy = [&, ymin = ymin, ymax = ymax](double y) { return ptop + (ymax - y) / (ymax - ymin) * ph; };
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", left,
                       ptop, pw, ph);
    x_ticks(ptop, p + 1 == k);
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
    y_title(curves, ptop);
    for (std::size_t n = 0; n < curves.size(); ++n) curve(curves[n], n, ptop, sy);
    if (p + 1 == k && any_invalid(r))
      out += fmt::format(
          "<text x=\"{}\" y=\"{}\" font-size=\"11\">dashed: a validity</text>"
          "<text x=\"{}\" y=\"{}\" font-size=\"11\">condition fails</text>\n",
          left + pw + 15, ptop + 30 + 20 * static_cast<double>(curves.size()), left + pw + 15,
          ptop + 44 + 20 * static_cast<double>(curves.size()));
  }

  // The vertical range of a panel's curves, padded by a twentieth each way.
  std::pair<double, double> y_range(const std::vector<std::size_t>& curves) const {
    double ymin = 0, ymax = 0;
    bool any = false;
    for (const std::size_t c : curves)
      for (const auto& v : r.y[c])
        if (v) {
          ymin = any ? std::min(ymin, *v) : *v;
          ymax = any ? std::max(ymax, *v) : *v;
          any = true;
        }
    if (ymax - ymin < 1e-12) ymax = ymin + 1;
    const double pad = 0.05 * (ymax - ymin);
    return {ymin - pad, ymax + pad};
  }

  // The horizontal ticks under a panel; their numbers under the lowest panel only.
  void x_ticks(double ptop, bool lowest) {
    for (const double xv : ticks(xmin, xmax)) {
      out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"black\"/>", sx(xv),
                         ptop + ph, ptop + ph + 5);
      if (lowest)
        out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>", sx(xv), ptop + ph + 20,
                           num(xv));
      out += "\n";
    }
  }

  // The y axis says what it shows and in which unit: "y [m]", "N_A, N_B [N]"; curves whose
  // units are unknown say so.
  void y_title(const std::vector<std::size_t>& curves, double ptop) {
    std::string names;
    for (const std::size_t c : curves) names += (names.empty() ? "" : ", ") + r.names[c];
    const std::string unit = panel_unit(r, curves);
    const std::string title = unit.empty() ? names : names + " [" + unit + "]";
    out += fmt::format("<text x=\"18\" y=\"{0}\" transform=\"rotate(-90 18 {0})\" text-anchor=\"middle\">{1}</text>\n",
                       ptop + ph / 2, html_escape(title));
  }

  // Curve c, the n-th of its panel: runs of points with the same validity (solid where valid,
  // dashed where not), and its line in the legend.
  template <class Sy>
  void curve(std::size_t c, std::size_t n, double ptop, const Sy& sy) {
    static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
    const char* colour = colours[c % 6];
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

  // The horizontal axis' label, and the end of the page.
  void footer() {
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", left + pw / 2, H - 15,
                       html_escape(r.x_name + (r.x_unit.empty() ? "" : " [" + r.x_unit + "]")));
    out += "</svg>\n";
  }
};

}  // namespace

std::string sweep_svg(const SweepResult& r) {
  SvgChart chart(r);
  chart.header();
  for (std::size_t p = 0; p < chart.k; ++p) chart.panel(p);
  chart.footer();
  return std::move(chart.out);
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
