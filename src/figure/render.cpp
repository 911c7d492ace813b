// A Figure as TikZ and as SVG; labels' LaTeX as SVG text.
#include <cctype>
#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "figure/figure.hpp"

namespace tackle {

namespace {

std::string num(double v) {
  if (std::fabs(v) < 5e-4) v = 0;
  std::string s = fmt::format("{:.3f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string xml_escape(char c) {
  switch (c) {
    case '&': return "&amp;";
    case '<': return "&lt;";
    case '>': return "&gt;";
    case '"': return "&quot;";
    default: return std::string(1, c);
  }
}

const std::map<std::string, std::string>& greek() {
  static const std::map<std::string, std::string> g{
      {"alpha", "α"},  {"beta", "β"},  {"gamma", "γ"},   {"delta", "δ"},    {"epsilon", "ε"}, {"varepsilon", "ε"},
      {"zeta", "ζ"},   {"eta", "η"},   {"theta", "θ"},   {"vartheta", "ϑ"}, {"iota", "ι"},    {"kappa", "κ"},
      {"lambda", "λ"}, {"mu", "μ"},    {"nu", "ν"},      {"xi", "ξ"},       {"pi", "π"},      {"rho", "ρ"},
      {"sigma", "σ"},  {"tau", "τ"},   {"upsilon", "υ"}, {"phi", "φ"},      {"varphi", "φ"},  {"chi", "χ"},
      {"psi", "ψ"},    {"omega", "ω"}, {"Gamma", "Γ"},   {"Delta", "Δ"},    {"Theta", "Θ"},   {"Lambda", "Λ"},
      {"Xi", "Ξ"},     {"Pi", "Π"},    {"Sigma", "Σ"},   {"Phi", "Φ"},      {"Psi", "Ψ"},     {"Omega", "Ω"},
      {"cdot", "·"},   {"times", "×"}, {"infty", "∞"},   {"ell", "ℓ"}};
  return g;
}

// A small reader of the LaTeX that labels use: names with sub- and superscripts, Greek
// letters, \dot and \ddot, \frac, \sqrt, \left and \right, functions, spacing.
class SvgText {
 public:
  explicit SvgText(const std::string& s) : s_(s) {}
  std::string run() {
    std::string out;
    while (i_ < s_.size()) out += item();
    return out;
  }

 private:
  std::string group() {
    if (i_ < s_.size() && s_[i_] == '{') {
      ++i_;
      std::string out;
      while (i_ < s_.size() && s_[i_] != '}') out += item();
      if (i_ < s_.size()) ++i_;
      return out;
    }
    return i_ < s_.size() ? item() : "";
  }
  std::string item() {
    const char c = s_[i_];
    if (c == '\\') {
      ++i_;
      std::string name;
      while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) name += s_[i_++];
      if (name.empty()) {  // \, \; \! \  and escaped characters
        const char e = i_ < s_.size() ? s_[i_++] : ' ';
        if (e == ',' || e == ';' || e == ' ') return " ";
        if (e == '!') return "";
        return xml_escape(e);
      }
      if (name == "left" || name == "right") return i_ < s_.size() ? (s_[i_] == '.' ? (++i_, "") : item()) : "";
      if (auto g = greek().find(name); g != greek().end()) return g->second;
      // The dotted group between a mark (a private-use character) and its combining dot(s):
      // svg_shown takes both out and keeps where the dots go.
      if (name == "dot" || name == "ddot") return "\uE000" + group() + (name == "dot" ? "\u0307" : "\u0308");
      if (name == "frac") {
        // a/b, with parentheses only where they are needed (a sum above, a sum or product below).
        const std::string a = group(), b = group();
        auto sum = [](const std::string& t) {
          return t.find('+') != std::string::npos || t.find("\u2212") != std::string::npos;
        };
        const bool product = b.find("\u2009") != std::string::npos;
        return (sum(a) ? "(" + a + ")" : a) + "/" + (sum(b) || product ? "(" + b + ")" : b);
      }
      if (name == "sqrt") return "√(" + group() + ")";
      if (name == "mathrm" || name == "text" || name == "operatorname" || name == "mathit")
        return "<tspan font-style=\"normal\">" + group() + "</tspan>";
      if (name == "quad" || name == "qquad") return " ";
      return "<tspan font-style=\"normal\">" + name + "</tspan>";  // \sin, \cos, \log, ...
    }
    ++i_;
    if (c == '_' || c == '^') {
      return std::string("<tspan baseline-shift=\"") + (c == '_' ? "sub" : "super") + "\" font-size=\"70%\">" +
             group() + "</tspan>";
    }
    if (c == '{') {
      --i_;
      return group();
    }
    if (c == '-') return "−";
    if (c == ' ') return "\u2009";  // between factors: a thin space
    if (std::isdigit(static_cast<unsigned char>(c)))
      return "<tspan font-style=\"normal\">" + std::string(1, c) + "</tspan>";
    if (c == '+' || c == '=' || c == '(' || c == ')')
      return std::string(c == '+' || c == '=' ? " " : "") + c + (c == '+' || c == '=' ? " " : "");
    return xml_escape(c);
  }
  const std::string& s_;
  std::size_t i_ = 0;
};

// A dot accent as svg_shown finds it: over a letter whose advance runs from `from` to `to`
// (ems of the label's font, along its text), of `size` (1, or 0.7 in a sub- or superscript)
// on a baseline `rise` ems above the label's, italic or not, tall (a capital, a digit, an
// ascender: θ, d) or not (x-height: x, ω), with one dot or two.
struct ShownAccent {
  double from = 0, to = 0, size = 1, rise = 0;
  bool italic = true, tall = false;
  int dots = 1;
};
// A label's shown text (svg_text's output) with its accents taken out: the text, its advance
// in ems of its font, an italic serif (sub- and superscripts at 70 % of the size, shifted
// 0.4 ems of the text around them: Chromium's shift, half the small font's height), and
// where its dots go. An estimate, which the SVG then holds the text to (textLength), so that
// the box it fills is known.
struct Shown {
  std::string text;
  double ems = 0;
  std::vector<ShownAccent> accents;
};

bool tall_letter(const std::string& ch) {
  if (ch.size() == 1) {
    const auto c = static_cast<unsigned char>(ch[0]);
    return std::isupper(c) || std::isdigit(c) || std::string("bdfhklt").find(static_cast<char>(c)) != std::string::npos;
  }
  return std::string("ΓΔΘΛΞΠΣΦΨΩβδζθϑλξℓ").find(ch) != std::string::npos;
}

Shown svg_shown(const std::string& svg) {
  Shown out;
  struct Level {
    double size, rise;
    bool italic;
  };
  Level level{1, 0, true};
  std::vector<Level> levels;
  std::vector<std::size_t> open;  // accents whose group is still being read
  for (std::size_t i = 0; i < svg.size();) {
    const auto c = static_cast<unsigned char>(svg[i]);
    if (c == '<') {
      const std::size_t close = svg.find('>', i);
      const std::string tag = svg.substr(i, close - i + 1);
      out.text += tag;
      if (tag.rfind("</", 0) == 0) {
        level = levels.empty() ? Level{1, 0, true} : levels.back();
        if (!levels.empty()) levels.pop_back();
      } else {
        levels.push_back(level);
        if (tag.find("baseline-shift=\"sub\"") != std::string::npos) level.rise -= 0.4 * level.size;
        if (tag.find("baseline-shift=\"super\"") != std::string::npos) level.rise += 0.4 * level.size;
        if (tag.find("font-size=\"70%\"") != std::string::npos) level.size *= 0.7;
        if (tag.find("font-style=\"normal\"") != std::string::npos) level.italic = false;
      }
      i = close + 1;
      continue;
    }
    std::size_t n = 1;
    if (c == '&')
      n = svg.find(';', i) + 1 - i;  // an escaped character: &lt; &gt; &amp; &quot;
    else if (c >= 0xF0)
      n = 4;
    else if (c >= 0xE0)
      n = 3;
    else if (c >= 0xC0)
      n = 2;
    const std::string ch = svg.substr(i, n);
    i += n;
    if (ch == "\uE000") {  // a dotted group begins
      open.push_back(out.accents.size());
      out.accents.push_back({out.ems, out.ems, level.size, level.rise, level.italic, false, 1});
      continue;
    }
    if (ch == "\u0307" || ch == "\u0308") {  // and ends: its dots over what it shows
      if (!open.empty()) {
        out.accents[open.back()].dots = ch == "\u0307" ? 1 : 2;
        open.pop_back();
      }
      continue;
    }
    out.text += ch;
    // The first letter of a dotted group gives its dots' height.
    for (const std::size_t a : open)
      if (out.accents[a].to == out.accents[a].from)
        out.accents[a] = {out.ems, out.ems, level.size, level.rise, level.italic, tall_letter(ch), 1};
    double w = 0.52;
    if (c == '&')
      w = 0.6;
    else if (ch == "\u2009")
      w = 0.17;
    else if (ch == " ")
      w = 0.25;
    else if (n > 1)
      w = 0.6;  // Greek, minus, root, dot, times
    else if (std::string("mwMW").find(static_cast<char>(c)) != std::string::npos)
      w = 0.85;
    else if (std::string("ijltfr()/,.:;'|!").find(static_cast<char>(c)) != std::string::npos)
      w = 0.33;
    else if (std::isupper(c))
      w = 0.7;
    else if (std::isdigit(c))
      w = 0.5;
    else if (c == '+' || c == '=')
      w = 0.6;
    out.ems += w * level.size;
    for (const std::size_t a : open) out.accents[a].to = out.ems;  // the group so far
  }
  return out;
}

std::string svg_point(double x, double y, const Figure& f, double px) {
  return num((x - f.min_x) * px) + "," + num((f.max_y - y) * px);
}

}  // namespace

std::string svg_text(const std::string& tex) { return svg_shown(SvgText(tex).run()).text; }

SvgLabel svg_label(const FigureLabel& l) {
  SvgLabel b;
  const Shown shown = svg_shown(SvgText(l.tex).run());
  const double natural = shown.ems * svg_font_size;
  b.x = l.at.x;
  // The font as large as TikZ's \small where the box is as high as the layout makes it,
  // smaller in a lower box; the text as wide as it is, or the box's width less a margin.
  b.font_size = l.height > 0 ? std::min(svg_font_size, l.height / (svg_ascent + svg_descent)) : svg_font_size;
  b.width = l.width > 0 ? std::min(natural * b.font_size / svg_font_size, l.width - 2 * svg_margin) : natural;
  b.baseline = l.at.y - 0.5 * (svg_ascent - svg_descent) * b.font_size;
  // Each dot over its letter's advance as the text is held to its width (leaning with an
  // italic letter), clear of its top: x-height 0.52 ems and capitals 0.77 in DejaVu Serif,
  // less in Times.
  const double across = b.width / std::max(shown.ems, 1e-9);  // one em of the text, as it is held to its width
  for (const auto& a : shown.accents) {
    const double em = a.size * b.font_size;
    const double centre =
        b.x - b.width / 2 + (a.from + a.to) / 2 * across + (a.italic ? (a.tall ? 0.08 : 0.05) * em : 0);
    const double y = b.baseline + a.rise * b.font_size + (a.tall ? 0.9 : 0.7) * em;
    for (int k = 0; k < a.dots; ++k)
      b.dots.push_back({centre + (a.dots == 1 ? 0 : (k ? 0.13 : -0.13) * em), y, 0.075 * em});
  }
  return b;
}

std::size_t shown_length(const std::string& tex) {
  const std::string s = svg_text(tex);
  std::size_t n = 0;
  bool tag = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '<')
      tag = true;
    else if (c == '>')
      tag = false;
    else if (tag)
      continue;
    else if (c == '&') {
      ++n;
      i = s.find(';', i);
      if (i == std::string::npos) break;
    } else if ((c & 0xC0) != 0x80)
      ++n;  // dots are drawn apart: no combining characters
  }
  return n;
}

namespace {

// The brace group at `i` (its text without the braces; `i` moved past it), or the one
// character there.
std::string brace_group(const std::string& s, std::size_t& i) {
  if (i >= s.size()) return "";
  if (s[i] != '{') return std::string(1, s[i++]);
  int depth = 0;
  const std::size_t from = ++i;
  for (; i < s.size(); ++i) {
    if (s[i] == '{') ++depth;
    if (s[i] == '}' && depth-- == 0) break;
  }
  const std::string inner = s.substr(from, i - from);
  if (i < s.size()) ++i;
  return inner;
}

// A label's fractions written on one line, as the SVG shows them (m L \ddot{\theta}/2, not a
// stacked fraction too small to read in a figure): a/b, with parentheses only where needed
// (a sum above, a sum or product below).
std::string slashed(const std::string& tex) {
  std::string out;
  for (std::size_t i = 0; i < tex.size();) {
    if (tex.compare(i, 5, "\\frac") != 0 ||
        (i + 5 < tex.size() && std::isalpha(static_cast<unsigned char>(tex[i + 5])))) {
      out += tex[i++];
      continue;
    }
    i += 5;
    const std::string a = slashed(brace_group(tex, i)), b = slashed(brace_group(tex, i));
    auto sum = [](const std::string& t) { return t.find_first_of("+-") != std::string::npos; };
    out += (sum(a) ? "\\left(" + a + "\\right)" : a) + "/" +
           (sum(b) || b.find(' ') != std::string::npos ? "\\left(" + b + "\\right)" : "{" + b + "}");
  }
  return out;
}

// A label as a TikZ node: its text centred in the box the layout kept, scaled down where it
// would be wider or higher than the box (\tacklelabel, defined in each picture).
std::string tikz_label(const FigureLabel& l) {
  const std::string text = "$" + slashed(l.tex) + "$";
  const std::string body = l.width > 0 && l.height > 0
                               ? "\\tacklelabel{" + num(l.width) + "cm}{" + num(l.height) + "cm}{" + text + "}"
                               : text;
  return "  \\node[font=\\small, inner sep=0pt] at (" + num(l.at.x) + "," + num(l.at.y) + ") {" + body + "};\n";
}

}  // namespace

std::string to_tikz(const Figure& f) {
  std::string out =
      "\\begin{tikzpicture}[>=stealth, line cap=round, line join=round]\n"
      "  \\providecommand{\\tacklelabel}[3]{\\setbox0=\\hbox{#3}\\pgfmathsetmacro{\\tacklescale}{min(1, "
      "#1/max(\\the\\wd0, 0.01pt), "
      "#2/max(\\the\\dimexpr\\ht0+\\dp0\\relax, 0.01pt))}\\scalebox{\\tacklescale}{\\box0}}\n";
  for (const auto& o : f.outlines) {
    if (o.shape == FigureOutline::Shape::circle) {
      out += "  \\filldraw[fill=black!8, draw=black, thick] (" + num(o.centre.x) + "," + num(o.centre.y) +
             ") circle (" + num(o.radius) + ");\n";
    } else {
      out += "  \\filldraw[fill=black!8, draw=black, thick] ";
      for (const auto& c : o.corners) out += "(" + num(c.x) + "," + num(c.y) + ") -- ";
      out += "cycle;\n";
    }
  }
  for (const auto& l : f.lines) {
    out += std::string("  \\draw[") + (l.thin ? "thin" : "thick") + "] ";
    for (std::size_t i = 0; i < l.points.size(); ++i)
      out += (i ? " -- (" : "(") + num(l.points[i].x) + "," + num(l.points[i].y) + ")";
    out += ";\n";
  }
  for (const auto& t : f.texts) out += tikz_label(t);
  for (const auto& d : f.dots) {
    out += d.pin ? "  \\filldraw[fill=white, thick] (" + num(d.at.x) + "," + num(d.at.y) + ") circle (2.5pt);\n"
                 : "  \\fill (" + num(d.at.x) + "," + num(d.at.y) + ") circle (1.5pt);\n";
    if (d.label) out += tikz_label(*d.label);
  }
  for (const auto& a : f.arrows) {
    const std::string style = a.axis ? "->, thin" : a.dashed ? "->, thick, dashed" : "->, very thick";
    out += "  \\draw[" + style + "] (" + num(a.from.x) + "," + num(a.from.y) + ") -- (" + num(a.to.x) + "," +
           num(a.to.y) + ");\n";
    out += tikz_label(a.label);
  }
  for (const auto& c : f.couples) {
    const double start = c.counterclockwise ? -60 : 240, end = c.counterclockwise ? 240 : -60;
    const double sx = c.centre.x + c.radius * std::cos(start * M_PI / 180),
                 sy = c.centre.y + c.radius * std::sin(start * M_PI / 180);
    out += std::string("  \\draw[->, ") + (c.dashed ? "thick, dashed" : "very thick") + "] (" + num(sx) + "," +
           num(sy) + ") arc[start angle=" + num(start) + ", end angle=" + num(end) + ", radius=" + num(c.radius) +
           "];\n";
    out += tikz_label(c.label);
  }
  return out + "\\end{tikzpicture}\n";
}

std::string to_svg(const Figure& f, const std::string& ids) {
  const double px = 40;  // pixels per drawing unit
  const double w = (f.max_x - f.min_x) * px, h = (f.max_y - f.min_y) * px;
  std::string id = ids + "head";
  for (char c : f.caption) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"fbd\" width=\"" + num(w + 8) + "\" height=\"" +
                    num(h + 8) + "\" viewBox=\"-4 -4 " + num(w + 8) + " " + num(h + 8) +
                    "\" role=\"img\" aria-label=\"" + f.caption + "\">\n";
  out += "<title>" + f.caption + "</title>\n";
  out += "<defs><marker id=\"" + id +
         "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
         "orient=\"auto-start-reverse\">"
         "<path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"black\"/></marker></defs>\n";
  for (const auto& o : f.outlines) {
    if (o.shape == FigureOutline::Shape::circle) {
      out += "<circle cx=\"" + num((o.centre.x - f.min_x) * px) + "\" cy=\"" + num((f.max_y - o.centre.y) * px) +
             "\" r=\"" + num(o.radius * px) + "\" fill=\"#ebebeb\" stroke=\"black\" stroke-width=\"1.6\"/>\n";
    } else {
      out += "<polygon points=\"";
      for (std::size_t i = 0; i < o.corners.size(); ++i)
        out += (i ? " " : "") + svg_point(o.corners[i].x, o.corners[i].y, f, px);
      out += "\" fill=\"#ebebeb\" stroke=\"black\" stroke-width=\"1.6\" stroke-linejoin=\"round\"/>\n";
    }
  }
  // A label centred in the box the layout kept for it: its text held to the box's width.
  auto label = [&](const FigureLabel& l) {
    const SvgLabel b = svg_label(l);
    std::string dots;  // its accents' dots, drawn apart from the text
    for (const auto& d : b.dots)
      dots += "<circle cx=\"" + num((d.x - f.min_x) * px) + "\" cy=\"" + num((f.max_y - d.y) * px) + "\" r=\"" +
              num(d.r * px) + "\" fill=\"black\"/>\n";
    return "<text x=\"" + num((b.x - f.min_x) * px) + "\" y=\"" + num((f.max_y - b.baseline) * px) +
           "\" textLength=\"" + num(b.width * px) +
           "\" lengthAdjust=\"spacingAndGlyphs\" text-anchor=\"middle\" font-family=\"serif\" font-style=\"italic\" "
           "font-size=\"" +
           num(b.font_size * px) + "\">" + svg_text(l.tex) + "</text>\n" + dots;
  };
  for (const auto& l : f.lines) {
    out += "<polyline points=\"";
    for (std::size_t i = 0; i < l.points.size(); ++i)
      out += (i ? " " : "") + svg_point(l.points[i].x, l.points[i].y, f, px);
    out += std::string("\" fill=\"none\" stroke=\"black\" stroke-width=\"") + (l.thin ? "0.8" : "1.6") +
           "\" stroke-linejoin=\"round\"/>\n";
  }
  for (const auto& t : f.texts) out += label(t);
  for (const auto& d : f.dots) {
    out += "<circle cx=\"" + num((d.at.x - f.min_x) * px) + "\" cy=\"" + num((f.max_y - d.at.y) * px) +
           (d.pin ? "\" r=\"3.5\" fill=\"white\" stroke=\"black\" stroke-width=\"1.4\"/>\n"
                  : "\" r=\"2.5\" fill=\"black\"/>\n");
    if (d.label) out += label(*d.label);
  }
  for (const auto& a : f.arrows) {
    out += "<line x1=\"" + num((a.from.x - f.min_x) * px) + "\" y1=\"" + num((f.max_y - a.from.y) * px) + "\" x2=\"" +
           num((a.to.x - f.min_x) * px) + "\" y2=\"" + num((f.max_y - a.to.y) * px) +
           "\" stroke=\"black\" stroke-width=\"" + (a.axis ? "1" : "2") + "\"" +
           (a.dashed ? " stroke-dasharray=\"6 4\"" : "") + " marker-end=\"url(#" + id + ")\"/>\n";
    out += label(a.label);
  }
  for (const auto& c : f.couples) {
    const double start = (c.counterclockwise ? -60 : 240) * M_PI / 180,
                 end = (c.counterclockwise ? 240 : -60) * M_PI / 180;
    const double cx = (c.centre.x - f.min_x) * px, cy = (f.max_y - c.centre.y) * px, r = c.radius * px;
    out += "<path d=\"M " + num(cx + r * std::cos(start)) + " " + num(cy - r * std::sin(start)) + " A " + num(r) + " " +
           num(r) + " 0 1 " + (c.counterclockwise ? "0" : "1") + " " + num(cx + r * std::cos(end)) + " " +
           num(cy - r * std::sin(end)) + "\" fill=\"none\" stroke=\"black\" stroke-width=\"2\"" +
           (c.dashed ? " stroke-dasharray=\"6 4\"" : "") + " marker-end=\"url(#" + id + ")\"/>\n";
    out += label(c.label);
  }
  return out + "</svg>\n";
}

}  // namespace tackle
