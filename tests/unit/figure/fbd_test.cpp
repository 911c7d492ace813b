// Drawn free body diagrams: the arrows where a person draws them, labels that never sit on
// one another, every example drawn, and the description's own shape.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

#include "figure/figure.hpp"
#include "figure/geometry.hpp"
#include "report/key.hpp"
#include "report/writers/common.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {

// The free body diagrams of a derivation (its sketch too when `sketches`).
std::vector<Figure> figures_of(const Analysis& a, bool sketches = false) {
  std::vector<Figure> out;
  for (const auto& d : explain_phases(a))
    for (const auto& st : d.steps)
      if (st.kind == Step::Kind::figure && (sketches || !st.figure->sketch)) out.push_back(*st.figure);
  return out;
}

std::optional<Figure> sketch_of(const std::string& example) {
  return mechanism_sketch(analyze_file(TACKLE_SOURCE_DIR "/examples/" + example, test::rules())->model);
}

std::vector<FigureOutline> outlines_of(const Figure& f, FigureOutline::Shape shape) {
  std::vector<FigureOutline> out;
  for (const auto& o : f.outlines)
    if (o.shape == shape) out.push_back(o);
  return out;
}

bool is_horizontal(const FigureLine& l) {
  return l.points.size() == 2 && std::fabs(l.points[0].y - l.points[1].y) < 1e-9;
}
bool is_vertical(const FigureLine& l) {
  return l.points.size() == 2 && std::fabs(l.points[0].x - l.points[1].x) < 1e-9;
}

const FigureArrow* arrow(const Figure& f, const std::string& tex) {
  for (const auto& a : f.arrows)
    if (a.label.tex == tex) return &a;
  return nullptr;
}

bool near(FigurePoint a, FigurePoint b) { return std::hypot(a.x - b.x, a.y - b.y) < 1e-6; }

FigurePoint dot_named(const Figure& f, const std::string& name) {
  for (const auto& d : f.dots)
    if (d.label && d.label->tex == name) return d.at;
  FAIL("no point " << name);
  return {};
}

// A label's text as an SVG writes it: the box it fills (pixels, y down).
struct TextBox {
  std::string text;
  double x0, x1, y0, y1;
  [[nodiscard]] bool overlaps(const TextBox& o) const {
    constexpr double tol = 0.01;  // the SVG's numbers have three decimals
    return x0 < o.x1 - tol && o.x0 < x1 - tol && y0 < o.y1 - tol && o.y0 < y1 - tol;
  }
  // Whether the segment p-q passes through the box.
  [[nodiscard]] bool crossed_by(FigurePoint p, FigurePoint q) const {
    return fig::box_hits_segment({{(x0 + x1) / 2, (y0 + y1) / 2}, x1 - x0, y1 - y0}, fig::vp(p), fig::vp(q));
  }
};

struct SvgBoxes {
  std::vector<TextBox> texts;
  std::vector<std::pair<FigurePoint, FigurePoint>> shafts;  // the arrows' lines
};

// The text boxes and arrow shafts of an SVG that to_svg wrote, read back from its numbers.
SvgBoxes svg_boxes(const std::string& svg) {
  SvgBoxes out;
  const std::regex text(
      R"re(<text x="([-0-9.]+)" y="([-0-9.]+)" textLength="([0-9.]+)"[^>]*font-size="([0-9.]+)">(.*?)</text>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]), w = std::stod((*it)[3]), size = std::stod((*it)[4]);
    out.texts.push_back({(*it)[5], x - w / 2, x + w / 2, y - svg_ascent * size, y + svg_descent * size});
  }
  const std::regex line(R"re(<line x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it)
    out.shafts.push_back({{std::stod((*it)[1]), std::stod((*it)[2])}, {std::stod((*it)[3]), std::stod((*it)[4])}});
  return out;
}

}  // namespace

TEST_CASE("FBD: the suitcase's normal forces press on it from below, friction mu N apart", "[figure]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", test::rules());
  const auto figs = figures_of(*a);
  REQUIRE(figs.size() == 1);
  const Figure& f = figs[0];
  CHECK(f.caption == "Free body diagram of suitcase");
  REQUIRE(f.outlines.size() == 2);  // the body, and again in its mass-times-acceleration diagram
  const FigurePoint A = dot_named(f, "A"), B = dot_named(f, "B");
  // N_A points up with its head at A; mu N_A points left from A (away from the body); mu N_B
  // points left with its head at B (pressing on it); the weight m g points down; m a_C is dashed.
  const FigureArrow* na = arrow(f, "N_{A}");
  REQUIRE(na);
  CHECK(near(na->to, A));
  CHECK(na->from.y < na->to.y);
  CHECK(std::fabs(na->from.x - na->to.x) < 1e-9);
  const FigureArrow* fa = arrow(f, "\\mu N_{A}");
  REQUIRE(fa);
  CHECK(near(fa->from, A));
  CHECK(fa->to.x < fa->from.x);
  const FigureArrow* fb = arrow(f, "\\mu N_{B}");
  REQUIRE(fb);
  CHECK(near(fb->to, B));
  CHECK(fb->to.x < fb->from.x);
  const FigureArrow* w = arrow(f, "m g");
  REQUIRE(w);
  CHECK(w->to.y < w->from.y);
  CHECK(!w->dashed);
  const FigureArrow* ma = arrow(f, "m a_{C}");
  REQUIRE(ma);
  CHECK(ma->dashed);
  // m a_C on the right, beside the forces: from the center of the suitcase drawn again.
  CHECK(ma->from.x > std::max(fa->from.x, fb->from.x));
  // Two axes, x and y.
  CHECK(std::count_if(f.arrows.begin(), f.arrows.end(), [](const FigureArrow& x) { return x.axis; }) == 2);
}

TEST_CASE("FBD: without figures (text, JSON) none is drawn and the text and JSON are the same", "[figure]") {
  for (const char* example : {"sample-12.7-suitcase.yaml", "sample-12.3-two-mass-pulley.yaml"}) {
    const auto a = analyze_file(std::string(TACKLE_SOURCE_DIR "/examples/") + example, test::rules());
    const Derivation with = explain(*a), without = explain(*a, ReportOptions{.figures = false});
    const auto drawn = [](const Derivation& d) {
      return std::count_if(d.steps.begin(), d.steps.end(),
                           [](const Step& st) { return st.kind == Step::Kind::figure; });
    };
    CHECK(drawn(with) > 0);
    CHECK(drawn(without) == 0);
    CHECK(write(with, Format::text, true) == write(without, Format::text, true));
    CHECK(write(with, Format::json, true) == write(without, Format::json, true));
  }
}

TEST_CASE("FBD: a system's diagram leaves out the forces inside it", "[figure]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.1-towing-system.yaml", test::rules());
  const auto figs = figures_of(*a);
  REQUIRE(figs.size() == 1);
  CHECK(figs[0].caption == "Free body diagram of the system car1 and car2");
  CHECK(figs[0].outlines.size() == 4);  // the two cars, and again for m a
  std::vector<std::string> labels;
  for (const auto& x : figs[0].arrows)
    if (!x.axis) labels.push_back(x.label.tex);
  std::sort(labels.begin(), labels.end());
  CHECK(labels == std::vector<std::string>{"F", "m_{1} \\ddot{x}_{1}", "m_{2} \\ddot{x}_{2}"});
}

TEST_CASE("FBD: two strands under a pulley block sit to either side of its middle", "[figure]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/atwood-machine.yaml", test::rules());
  const auto figs = figures_of(*a);
  REQUIRE(figs.size() == 3);
  const Figure& c = figs[2];
  CHECK(c.caption == "Free body diagram of C");
  REQUIRE(c.outlines[0].shape == FigureOutline::Shape::circle);
  std::vector<double> xs;
  for (const auto& x : c.arrows)
    if (x.label.tex == "T") {
      CHECK(x.to.y < x.from.y);  // down: y points up in this problem
      xs.push_back((x.from.x + x.to.x) / 2);
    }
  REQUIRE(xs.size() == 2);
  CHECK(std::fabs(xs[0] + xs[1] - 2 * c.outlines[0].centre.x) < 1e-9);
  CHECK(std::fabs(xs[0] - xs[1]) > 0.3);
}

TEST_CASE(
    "FBD: in every example no label lies on another or on an arrow, in TikZ and in SVG, and no arrow lies on an "
    "outline's edge",
    "[figure]") {
  const std::vector<std::string> files = test::example_files();
  std::size_t drawn = 0;
  for (const auto& file : files) {
    const auto a = analyze_file(file, test::rules());
    for (const Figure& f : figures_of(*a, true)) {
      ++drawn;
      INFO(file << ": " << f.caption);
      std::vector<FigureLabel> labels = f.texts;
      for (const auto& x : f.arrows) labels.push_back(x.label);
      for (const auto& c : f.couples) labels.push_back(c.label);
      for (const auto& d : f.dots)
        if (d.label) labels.push_back(*d.label);
      for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t k = i + 1; k < labels.size(); ++k) {
          INFO(labels[i].tex << " and " << labels[k].tex);
          const bool apart =
              std::fabs(labels[i].at.x - labels[k].at.x) * 2 >= labels[i].width + labels[k].width - 1e-9 ||
              std::fabs(labels[i].at.y - labels[k].at.y) * 2 >= labels[i].height + labels[k].height - 1e-9;
          CHECK(apart);
        }
      // TikZ centres each label in its box: no arrow's shaft passes through a box.
      for (const auto& l : labels) {
        const TextBox box{l.tex, l.at.x - l.width / 2, l.at.x + l.width / 2, l.at.y - l.height / 2,
                          l.at.y + l.height / 2};
        for (const auto& x : f.arrows) {
          INFO(l.tex << " and the arrow of " << x.label.tex);
          CHECK(!box.crossed_by(x.from, x.to));
        }
      }
      // The SVG draws each label in its box, as the TikZ does: the text boxes it writes (from
      // its x, baseline, textLength and font size) lie on no other and on no arrow's shaft.
      const auto svg = svg_boxes(to_svg(f));
      CHECK(svg.texts.size() == labels.size());
      for (std::size_t i = 0; i < svg.texts.size(); ++i) {
        const TextBox& a = svg.texts[i];
        INFO("SVG text " << a.text);
        for (std::size_t k = i + 1; k < svg.texts.size(); ++k) {
          INFO("and " << svg.texts[k].text);
          CHECK(!a.overlaps(svg.texts[k]));
        }
        for (const auto& [p, q] : svg.shafts) {
          INFO("shaft " << p.x << "," << p.y << " to " << q.x << "," << q.y);
          CHECK(!a.crossed_by(p, q));
        }
      }
      // An arrow along an edge would hide it: no arrow runs on an edge's line over a length.
      for (const auto& o : f.outlines) {
        if (o.shape != FigureOutline::Shape::polygon) continue;
        for (std::size_t i = 0; i < o.corners.size(); ++i) {
          const FigurePoint p = o.corners[i], q = o.corners[(i + 1) % o.corners.size()];
          const double ex = q.x - p.x, ey = q.y - p.y, el = std::hypot(ex, ey);
          for (const auto& x : f.arrows) {
            const double ax = x.to.x - x.from.x, ay = x.to.y - x.from.y, al = std::hypot(ax, ay);
            if (std::fabs(ex * ay - ey * ax) > 0.02 * el * al) continue;                         // not parallel
            if (std::fabs((x.from.x - p.x) * ey - (x.from.y - p.y) * ex) > 0.02 * el) continue;  // not on its line
            const double t0 = ((x.from.x - p.x) * ex + (x.from.y - p.y) * ey) / el,
                         t1 = ((x.to.x - p.x) * ex + (x.to.y - p.y) * ey) / el;
            INFO(x.label.tex);
            CHECK((std::max(t0, t1) <= 0.05 || std::min(t0, t1) >= el - 0.05));
          }
        }
      }
    }
  }
  CHECK(drawn >= 50);
}

TEST_CASE("FBD: labels in SVG keep their subscripts, Greek letters and dots", "[figure]") {
  CHECK(svg_text("\\mu N_{A}") == "μ\u2009N<tspan baseline-shift=\"sub\" font-size=\"70%\">A</tspan>");
  // A dotted letter's text has no combining dot: the dots are drawn apart (below).
  CHECK(svg_text("m_{A} \\ddot{x}_{A}") ==
        "m<tspan baseline-shift=\"sub\" font-size=\"70%\">A</tspan>\u2009x<tspan baseline-shift=\"sub\" "
        "font-size=\"70%\">A</tspan>");
  CHECK(svg_text("a < b & c") == "a\u2009&lt;\u2009b\u2009&amp;\u2009c");
  CHECK(shown_length("m_{A} \\ddot{x}_{A}") == 5);
  // The SVG: the label's text, then a small filled circle for its dot, over the theta.
  Figure f;
  f.max_x = 2;
  f.max_y = 1;
  f.texts.push_back({{1, 0.5}, "\\dot{\\theta}^{2}"});
  const std::string svg = to_svg(f);
  CHECK(svg.find("<text x=\"40\" y=\"23.5\" textLength=\"13.3\" lengthAdjust=\"spacingAndGlyphs\" "
                 "text-anchor=\"middle\" font-family=\"serif\" "
                 "font-style=\"italic\" font-size=\"14\">θ<tspan baseline-shift=\"super\" font-size=\"70%\"><tspan "
                 "font-style=\"normal\">2</tspan></tspan></text>\n"
                 "<circle cx=\"38.67\" cy=\"10.9\" r=\"1.05\" fill=\"black\"/>\n</svg>\n") != std::string::npos);
  CHECK(svg.find("\u0307") == std::string::npos);
  CHECK(to_tikz(f).find("{$\\dot{\\theta}^{2}$}") != std::string::npos);
}

TEST_CASE("FBD: an SVG label's dots sit over their letters, above them, in the label's box", "[figure]") {
  // The estimate the label is held to: theta 0.6 ems, x 0.52, A 0.7, a digit 0.5, sub- and
  // superscripts at 70 %; the text spans [x - width/2, x + width/2].
  struct Case {
    std::string tex, plain;                // with its dots, and without
    double letter_from, letter_to, total;  // the dotted letter's advance, the text's (ems)
    double top;                            // the letter's top (ems of its size; DejaVu Serif)
    std::size_t dots;
    double size = 1, rise = 0;  // the letter's size and baseline (ems of the label)
  };
  const std::vector<Case> cases{
      {"\\dot{\\theta}^{2}", "\\theta^{2}", 0, 0.6, 0.6 + 0.7 * 0.5, 0.77, 1},
      {"\\ddot{x}_{A}", "x_{A}", 0, 0.52, 0.52 + 0.7 * 0.7, 0.55, 2},
      {"m \\ddot{\\theta}", "m \\theta", 0.85 + 0.17, 0.85 + 0.17 + 0.6, 0.85 + 0.17 + 0.6, 0.77, 2},
      {"v_{\\dot{s}}", "v_{s}", 0.52, 0.52 + 0.7 * 0.52, 0.52 + 0.7 * 0.52, 0.55, 1, 0.7, -0.4}};
  for (const auto& c : cases) {
    INFO(c.tex);
    FigureLabel l;
    l.at = {2, 3};
    l.tex = c.tex;
    const SvgLabel b = svg_label(l);
    const std::string text = svg_text(c.tex);
    CHECK(text.find("\u0307") == std::string::npos);
    CHECK(text.find("\u0308") == std::string::npos);
    CHECK(text == svg_text(c.plain));
    // The box is the one the letters without their dots fill.
    l.tex = c.plain;
    const SvgLabel plain = svg_label(l);
    CHECK(std::fabs(b.width - plain.width) < 1e-12);
    CHECK(std::fabs(b.baseline - plain.baseline) < 1e-12);
    CHECK(b.font_size == plain.font_size);
    CHECK(plain.dots.empty());
    REQUIRE(b.dots.size() == c.dots);
    const double across = b.width / c.total, left = b.x - b.width / 2, em = c.size * b.font_size;
    const double letter_centre = left + (c.letter_from + c.letter_to) / 2 * across;
    double mean = 0;
    for (const auto& d : b.dots) {
      mean += d.x / static_cast<double>(b.dots.size());
      CHECK(d.x - d.r > left + c.letter_from * across);  // over the letter
      CHECK(d.x + d.r < left + c.letter_to * across);
      CHECK(d.y - d.r > b.baseline + (c.rise + c.size * c.top) * b.font_size);  // above its top
      CHECK(d.y + d.r < b.baseline + (c.rise + c.size * 1.1) * b.font_size);    // and not far
      CHECK(std::fabs(d.r - 0.075 * em) < 1e-12);                               // smaller over a subscript
      CHECK(std::fabs(d.y - b.dots[0].y) < 1e-12);
    }
    // Centred over the letter, leaning right a little as the italic letter does.
    CHECK(mean >= letter_centre);
    CHECK(mean - letter_centre <= 0.1 * em);
    if (c.dots == 2) CHECK(std::fabs(b.dots[1].x - b.dots[0].x - 0.26 * em) < 1e-12);
  }
}

TEST_CASE(
    "FBD: an SVG label is centred in its box and no wider or higher than it, and TikZ scales its label into the box",
    "[figure]") {
  FigureLabel l;
  l.at = {2, 3};
  l.height = 0.42;
  l.tex = "m_{A} \\ddot{s}";
  l.width = 0.2 * static_cast<double>(shown_length(l.tex)) + 0.12;
  const SvgLabel b = svg_label(l);
  CHECK(b.x == 2);
  CHECK(b.width <= l.width - 2 * svg_margin + 1e-12);
  CHECK(b.width > 0.3);
  // Its ascent and descent, together no higher than the box, are centred in it.
  const double top = b.baseline + svg_ascent * b.font_size, bottom = b.baseline - svg_descent * b.font_size;
  CHECK(top - bottom <= l.height + 1e-12);
  CHECK(std::fabs((top + bottom) / 2 - 3) < 1e-12);
  // A long label in a narrow box is held to the box.
  l.tex = "\\frac{m L^{2} \\ddot{\\theta}}{12}";
  l.width = 0.5;
  CHECK(std::fabs(svg_label(l).width - (0.5 - 2 * svg_margin)) < 1e-12);
  // TikZ: the same centre, the box's size given to \tacklelabel.
  Figure f;
  f.texts.push_back(l);
  CHECK(to_tikz(f).find("at (2,3) {\\tacklelabel{0.5cm}{0.42cm}{$m L^{2} \\ddot{\\theta}/{12}$}}") !=
        std::string::npos);
}

TEST_CASE("FBD: a description draws a body as it says", "[figure]") {
  const std::string yaml = test::example_with("sample-12.7-suitcase.yaml", "center_of_mass: [l/2, h],",
                                              "center_of_mass: [l/2, h], draw: {shape: circle, size: [l]},");
  const auto a = test::run_text(yaml);
  const auto figs = figures_of(*a);
  REQUIRE(figs.size() == 1);
  REQUIRE(figs[0].outlines[0].shape == FigureOutline::Shape::circle);
  // The drawn circle's diameter is l, the distance from A to B.
  const double ab = std::hypot(dot_named(figs[0], "A").x - dot_named(figs[0], "B").x,
                               dot_named(figs[0], "A").y - dot_named(figs[0], "B").y);
  CHECK(std::fabs(2 * figs[0].outlines[0].radius - ab) < 1e-9);
}

TEST_CASE("FBD: a wrong 'draw' is located", "[figure][errors]") {
  auto errors = [](const std::string& draw) {
    return test::errors_of(test::example_with("sample-12.7-suitcase.yaml", "center_of_mass: [l/2, h],",
                                              "center_of_mass: [l/2, h], draw: " + draw + ","));
  };
  CHECK(errors("{shape: blob, size: [l]}") ==
        std::vector<std::string>{
            "t.yaml:24:63: 'draw' of body 'suitcase' has shape 'blob' (expected rectangle, circle, spool or wedge)"});
  CHECK(errors("{shape: rectangle, size: [l]}") ==
        std::vector<std::string>{
            "t.yaml:24:80: 'draw' of body 'suitcase': 'size' has 1 entries (expected 2: [width, height])"});
  CHECK(errors("{shape: circle, size: [-l]}") ==
        std::vector<std::string>{
            "t.yaml:24:78: 'draw' of body 'suitcase': size '-l' is not a positive length with the given values"});
  CHECK(errors("{shape: circle}") ==
        std::vector<std::string>{"t.yaml:24:63: 'draw' of body 'suitcase' has no 'size' (expected [diameter])"});
  CHECK(errors("{shape: wedge, size: [l, h], face: up}") ==
        std::vector<std::string>{"t.yaml:24:90: 'draw' of body 'suitcase' has face 'up' (expected left or right)"});
  CHECK(errors("{shape: circle, size: [l], face: left}") ==
        std::vector<std::string>{
            "t.yaml:24:88: 'draw' of body 'suitcase' has face 'left' (expected no 'face': only a wedge has one)"});
  CHECK(errors("{shape: spool, size: [h, l]}") ==
        std::vector<std::string>{"t.yaml:24:80: 'draw' of body 'suitcase': the hub's diameter 'l' is not less than the "
                                 "spool's 'h' (expected a hub inside the spool)"});
  CHECK(errors("{shape: wedge, size: [l]}") ==
        std::vector<std::string>{
            "t.yaml:24:76: 'draw' of body 'suitcase': 'size' has 1 entries (expected 2: [base, height])"});
}

TEST_CASE("FBD: a problem in symbols only is drawn, a couple as an arc with its moment", "[figure]") {
  const auto a = test::run_text(test::pinned_beam_with_couple);
  const auto figs = figures_of(*a);
  REQUIRE(figs.size() == 1);
  REQUIRE(figs[0].couples.size() == 1);
  CHECK(figs[0].couples[0].label.tex == "M");
  CHECK(figs[0].couples[0].counterclockwise);
  // The cable pulls B up, towards C.
  const FigureArrow* t = arrow(figs[0], "T_{BC}");
  REQUIRE(t);
  CHECK(near(t->from, dot_named(figs[0], "B")));
  CHECK(t->to.y > t->from.y);
}

TEST_CASE("Sketch: the Atwood machine hangs from the ceiling over one sheave, its strands tangent to it",
          "[figure][sketch]") {
  const auto f = sketch_of("atwood-machine.yaml");
  REQUIRE(f);
  CHECK(f->sketch);
  CHECK(f->caption == "Sketch of the mechanism");
  const auto sheaves = outlines_of(*f, FigureOutline::Shape::circle);
  const auto blocks = outlines_of(*f, FigureOutline::Shape::polygon);
  REQUIRE(sheaves.size() == 1);
  REQUIRE(blocks.size() == 2);
  const FigureOutline& c = sheaves[0];
  // Both blocks hang below the sheave (y points up), A (y_A = -2) above B (y_B = -3).
  auto centre_y = [](const FigureOutline& o) { return (o.corners[0].y + o.corners[2].y) / 2; };
  CHECK(blocks[0].name == "A");
  CHECK(centre_y(blocks[0]) < c.centre.y);
  CHECK(centre_y(blocks[1]) < centre_y(blocks[0]));
  // Two vertical strands leave the sheave's sides at its centre's height, one to each block.
  std::vector<double> xs;
  for (const auto& l : f->lines)
    if (!l.thin && is_vertical(l) && std::fabs(std::max(l.points[0].y, l.points[1].y) - c.centre.y) < 1e-9)
      xs.push_back(l.points[0].x);
  std::sort(xs.begin(), xs.end());
  REQUIRE(xs.size() == 2);
  CHECK(std::fabs(xs[0] - (c.centre.x - c.radius)) < 1e-9);
  CHECK(std::fabs(xs[1] - (c.centre.x + c.radius)) < 1e-9);
  // The ceiling: a horizontal line above the sheave, hatched.
  CHECK(std::any_of(f->lines.begin(), f->lines.end(), [&](const FigureLine& l) {
    return !l.thin && is_horizontal(l) && l.points[0].y > c.centre.y + c.radius;
  }));
  CHECK(std::count_if(f->lines.begin(), f->lines.end(), [](const FigureLine& l) { return l.thin; }) >= 3);
  // Gravity (y up, gravity -g) is an arrow down beside the mechanism, labelled g.
  const FigureArrow* g = arrow(*f, "g");
  REQUIRE(g);
  CHECK(g->to.y < g->from.y);
  CHECK(std::fabs(g->to.x - g->from.x) < 1e-9);
}

TEST_CASE("Sketch: sample 12.3's string turns around three sheaves, F pulls A to the left", "[figure][sketch]") {
  const auto f = sketch_of("sample-12.3-two-mass-pulley.yaml");
  REQUIRE(f);
  // Its path pB, C, pB, C, pA, C turns back at C, at pB and at pA: three sheaves, one a
  // fixed pulley and one in each block.
  CHECK(outlines_of(*f, FigureOutline::Shape::circle).size() == 3);
  const auto blocks = outlines_of(*f, FigureOutline::Shape::polygon);
  REQUIRE(blocks.size() == 2);
  const FigureArrow* F = arrow(*f, "F");
  REQUIRE(F);
  CHECK(F->to.x < F->from.x);
  double left = 1e300;
  for (const auto& p : blocks[0].corners) left = std::min(left, p.x);
  CHECK(std::fabs(F->from.x - left) < 1e-9);
  // The strands lie in four lanes, one above the other.
  std::set<long long> lanes;
  for (const auto& l : f->lines)
    if (!l.thin && is_horizontal(l)) lanes.insert(std::llround(l.points[0].y * 1000));
  CHECK(lanes.size() >= 4);
}

TEST_CASE("Sketch: springs are coiled, a damper is a dashpot, the walls are hatched", "[figure][sketch]") {
  const auto f = sketch_of("three-blocks-on-springs.yaml");
  REQUIRE(f);
  CHECK(outlines_of(*f, FigureOutline::Shape::polygon).size() == 3);
  CHECK(outlines_of(*f, FigureOutline::Shape::circle).empty());
  // Three springs as zigzags (many points each), the two walls as vertical lines at W and V.
  CHECK(std::count_if(f->lines.begin(), f->lines.end(), [](const FigureLine& l) { return l.points.size() > 6; }) == 3);
  CHECK(std::count_if(f->lines.begin(), f->lines.end(), [](const FigureLine& l) {
          return !l.thin && is_vertical(l) && std::fabs(l.points[0].y - l.points[1].y) > 1;
        }) == 2);
  // The dashpot's cylinder: four points, open towards the wall V.
  CHECK(std::count_if(f->lines.begin(), f->lines.end(), [](const FigureLine& l) { return l.points.size() == 4; }) == 1);
}

TEST_CASE("Sketch: 1-D mechanisms with a string, spring or damper are sketched, 2-D ones all, 3-D ones not",
          "[figure][sketch]") {
  CHECK(sketch_of("sample-12.7-suitcase.yaml"));     // 2-D
  CHECK(!sketch_of("sample-12.8-sign-board.yaml"));  // 3-D
  CHECK(!sketch_of("box-in-a-truck-system.yaml"));   // 1-D, nothing between the bodies to draw
  CHECK(sketch_of("sample-12.1-towing.yaml"));       // a tow rope
  // In a derivation it opens the model, before the free body diagrams.
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/atwood-machine.yaml", test::rules());
  const auto figs = figures_of(*a, true);
  REQUIRE(figs.size() == 4);
  CHECK(figs[0].sketch);
  CHECK(!figs[1].sketch);
}

TEST_CASE("Sketch: bodies in contact touch (sample 12.4's top block rests on the bottom one)", "[figure][sketch]") {
  const auto f = sketch_of("sample-12.4-stacked-blocks-on-spring.yaml");
  REQUIRE(f);
  const auto blocks = outlines_of(*f, FigureOutline::Shape::polygon);
  REQUIRE(blocks.size() == 2);
  auto span = [](const FigureOutline& o, bool vertical) {
    double lo = 1e300, hi = -1e300;
    for (const auto& c : o.corners) {
      lo = std::min(lo, vertical ? c.y : c.x);
      hi = std::max(hi, vertical ? c.y : c.x);
    }
    return std::pair{lo, hi};
  };
  // y points down (gravity g > 0 along it): top (y_m = -0.1) is drawn above bottom (y = 0).
  CHECK(blocks[0].name == "top");
  const auto [top_lo, top_hi] = span(blocks[0], true);
  const auto [bottom_lo, bottom_hi] = span(blocks[1], true);
  CHECK(top_lo > bottom_lo);
  CHECK(std::fabs(top_lo - bottom_hi) < 1e-9);  // the top's lower side on the bottom's upper side
  CHECK(top_hi - top_lo > 0.2);
  CHECK(bottom_hi - bottom_lo > 0.2);
  // Side by side across the axis: one stands on the other.
  const auto [top_left, top_right] = span(blocks[0], false);
  const auto [bottom_left, bottom_right] = span(blocks[1], false);
  CHECK(std::min(top_right, bottom_right) - std::max(top_left, bottom_left) > 0.5);
  // Farther apart in the layout, they still touch.
  const std::string apart = test::example_with("sample-12.4-stacked-blocks-on-spring.yaml", "layout: {y_m: -0.1, y: 0}",
                                               "layout: {y_m: -0.3, y: 0}");
  const auto g = mechanism_sketch(test::run_text(apart)->model);
  REQUIRE(g);
  const auto moved = outlines_of(*g, FigureOutline::Shape::polygon);
  REQUIRE(moved.size() == 2);
  CHECK(std::fabs(span(moved[0], true).first - span(moved[1], true).second) < 1e-9);
}

namespace {

const FigureOutline* outline_named(const Figure& f, const std::string& name) {
  for (const auto& o : f.outlines)
    if (o.name == name) return &o;
  return nullptr;
}

std::optional<FigurePoint> dot_at(const Figure& f, const std::string& tex) {
  for (const auto& d : f.dots)
    if (d.label && d.label->tex == tex) return d.at;
  return std::nullopt;
}

// Whether some drawn line (not hatching) ends at p.
bool a_line_ends_at(const Figure& f, FigurePoint p, double tol = 1e-6) {
  return std::any_of(f.lines.begin(), f.lines.end(), [&](const FigureLine& l) {
    return !l.thin && (std::hypot(l.points.front().x - p.x, l.points.front().y - p.y) < tol ||
                       std::hypot(l.points.back().x - p.x, l.points.back().y - p.y) < tol);
  });
}

// Whether some drawn line ends on the outline's edge.
bool a_line_ends_on(const Figure& f, const FigureOutline& o) {
  return std::any_of(f.lines.begin(), f.lines.end(), [&](const FigureLine& l) {
    return !l.thin && (fig::boundary_distance(o, fig::vp(l.points.front())) < 1e-3 ||
                       fig::boundary_distance(o, fig::vp(l.points.back())) < 1e-3);
  });
}

}  // namespace

TEST_CASE("Sketch: every 2-D example is sketched, of a sensible size, its strings ending at their points",
          "[figure][sketch]") {
  const std::vector<std::string> files = test::example_files();
  std::size_t plane = 0;
  for (const auto& file : files) {
    const auto a = analyze_file(file, test::rules());
    const Model& m = a->model;
    if (m.dims() != 2) continue;
    ++plane;
    INFO(file);
    const auto f = mechanism_sketch(m);
    REQUIRE(f);
    CHECK(f->sketch);
    CHECK(f->caption == "Sketch of the mechanism");
    // Finite, and about the size of a figure on a page (drawing units are about centimetres).
    for (double v : {f->min_x, f->min_y, f->max_x, f->max_y}) CHECK(std::isfinite(v));
    const double w = f->max_x - f->min_x, h = f->max_y - f->min_y;
    CHECK(std::max(w, h) > 3);
    CHECK(std::min(w, h) > 1);
    CHECK(std::max(w, h) < 16);
    // Every body with a position is drawn, by its name.
    for (const auto& b : m.bodies)
      if (b.has_cm) CHECK(outline_named(*f, b.name));
    // Each string ends at its end points: at a named point's dot, or on the edge of the body
    // the point is named after (a string tied to a block's side).
    for (const auto& d : m.drawings) {
      if (d.as != "line" || d.path.size() < 2) continue;
      for (int p : {d.path.front(), d.path.back()}) {
        const std::string& name = m.points[p].name;
        INFO(d.label << " at " << name);
        if (const auto at = dot_at(*f, default_tex(name))) {
          CHECK(a_line_ends_at(*f, *at));
        } else {
          const FigureOutline* o = outline_named(*f, name);
          REQUIRE(o);
          CHECK(a_line_ends_on(*f, *o));
        }
      }
    }
  }
  CHECK(plane >= 25);
}

TEST_CASE("Sketch: the incline at its angle, the pulley at its top, the hanging block below it", "[figure][sketch]") {
  const auto f = sketch_of("incline-and-hanging-block.yaml");
  REQUIRE(f);
  // The incline: a line at theta = 30 degrees to the horizontal, hatched, its angle marked.
  const bool incline = std::any_of(f->lines.begin(), f->lines.end(), [](const FigureLine& l) {
    if (l.thin || l.points.size() != 2) return false;
    const double dx = l.points[1].x - l.points[0].x, dy = l.points[1].y - l.points[0].y;
    return std::hypot(dx, dy) > 3 && std::fabs(std::atan2(std::fabs(dy), std::fabs(dx)) - M_PI / 6) < 1e-9;
  });
  CHECK(incline);
  CHECK(std::any_of(f->texts.begin(), f->texts.end(), [](const FigureLabel& l) { return l.tex == "\\theta"; }));
  // The pulley P: a circle at the point P, above and to the right of A; B hangs below it.
  const auto P = dot_at(*f, "P");
  REQUIRE(P);
  const auto sheaves = outlines_of(*f, FigureOutline::Shape::circle);
  REQUIRE(sheaves.size() == 1);
  CHECK(near(sheaves[0].centre, *P));
  const FigureOutline* A = outline_named(*f, "A");
  const FigureOutline* B = outline_named(*f, "B");
  REQUIRE(A);
  REQUIRE(B);
  double bx0 = 1e300, bx1 = -1e300, by1 = -1e300, ay0 = 1e300;
  for (const auto& c : B->corners) bx0 = std::min(bx0, c.x), bx1 = std::max(bx1, c.x), by1 = std::max(by1, c.y);
  for (const auto& c : A->corners) ay0 = std::min(ay0, c.y);
  CHECK(bx0 < P->x);
  CHECK(P->x < bx1);
  CHECK(by1 < P->y);
  CHECK(ay0 < P->y);
  // The strand from P down to B is vertical, tangent to the pulley's right side.
  const double x = P->x + sheaves[0].radius;
  CHECK(std::any_of(f->lines.begin(), f->lines.end(), [&](const FigureLine& l) {
    return !l.thin && is_vertical(l) && std::fabs(l.points[0].x - x) < 1e-9 &&
           std::fabs(std::max(l.points[0].y, l.points[1].y) - P->y) < 1e-9 &&
           std::fabs(std::min(l.points[0].y, l.points[1].y) - by1) < 1e-9;
  }));
}

TEST_CASE("Sketch: the ladder stands on the floor against the wall, its angle marked", "[figure][sketch]") {
  const auto f = sketch_of("rotation-ladder-sliding-on-smooth-wall-and-floor.yaml");
  REQUIRE(f);
  const auto A = dot_at(*f, "A"), B = dot_at(*f, "B");
  REQUIRE(A);
  REQUIRE(B);
  // theta = 60 degrees: B up and to the right of A, at 60 degrees.
  CHECK(std::fabs(std::atan2(B->y - A->y, B->x - A->x) - M_PI / 3) < 1e-9);
  // A floor through the ladder's foot (below A by its half thickness at most) and a wall at B.
  auto horizontal_below = [&](const FigureLine& l) {
    return !l.thin && is_horizontal(l) && l.points[0].y <= A->y + 1e-9 && l.points[0].y > A->y - 0.2;
  };
  auto vertical_beside = [&](const FigureLine& l) {
    return !l.thin && is_vertical(l) && l.points[0].x >= B->x - 1e-9 && l.points[0].x < B->x + 0.2;
  };
  CHECK(std::count_if(f->lines.begin(), f->lines.end(), horizontal_below) == 1);
  CHECK(std::count_if(f->lines.begin(), f->lines.end(), vertical_beside) == 1);
  CHECK(std::any_of(f->texts.begin(), f->texts.end(), [](const FigureLabel& l) { return l.tex == "\\theta"; }));
}

TEST_CASE("Sketch: a position that cannot be evaluated draws nothing", "[figure][sketch]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", test::rules());
  Model m = a->model;
  REQUIRE(mechanism_sketch(m));
  // B moved to l/(h - 0.4): a pole at the layout's numbers (h = 0.4).
  const GiNaC::ex l = m.symbols->find("l")->sym, h = m.symbols->find("h")->sym;
  const auto B = std::find_if(m.points.begin(), m.points.end(), [](const Point& p) { return p.name == "B"; });
  REQUIRE(B != m.points.end());
  B->position[0] = l / (h - GiNaC::numeric(2, 5));
  CHECK(!mechanism_sketch(m));
}

TEST_CASE("Sheet: each variant's figures are drawn at its own numbers", "[figure][sheet]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", test::rules());
  const Derivation d = explain(*a);
  const std::vector<Variant> variants = draw_variants(a->model, d, 2, 1, 6);
  REQUIRE(variants.size() == 2);
  auto value = [](const Variant& v, const std::string& name) {
    for (const auto& q : v.parameters)
      if (q.name == name) return q.value;
    FAIL("no " << name);
    return 0.0;
  };
  // The seed draws two suitcases of different proportions (l wide, 2 h high).
  const double r0 = value(variants[0], "l") / (2 * value(variants[0], "h")),
               r1 = value(variants[1], "l") / (2 * value(variants[1], "h"));
  REQUIRE(std::fabs(r0 - r1) > 0.01);
  const std::vector<SheetEntry> entries{{&d, &a->model, variants}};
  const auto problems = writers::sheet_problems(entries);
  REQUIRE(problems.size() == 2);
  std::vector<std::vector<Step>> figures{writers::sheet_figures(problems[0], true),
                                         writers::sheet_figures(problems[1], true)};
  for (std::size_t k = 0; k < 2; ++k) {
    INFO("variant " << k + 1);
    REQUIRE(figures[k].size() == 2);  // the sketch and the free body diagram
    CHECK(figures[k][0].figure->sketch);
    CHECK(figures[k][1].text == "Free body diagram of suitcase");
    // The sketch's suitcase has the variant's proportions.
    const FigureOutline* o = outline_named(*figures[k][0].figure, "suitcase");
    REQUIRE(o);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& c : o->corners)
      x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
    CHECK(std::fabs((x1 - x0) / (y1 - y0) - (k == 0 ? r0 : r1)) < 1e-9);
  }
  // So the two variants' figures differ, and the sheet shows each one's.
  CHECK(to_tikz(*figures[0][0].figure) != to_tikz(*figures[1][0].figure));
  CHECK(to_tikz(*figures[0][1].figure) != to_tikz(*figures[1][1].figure));
  const std::string tex = write_sheet(entries, Format::latex, true);
  for (const auto& fs : figures)
    for (const auto& st : fs) CHECK(tex.find(to_tikz(*st.figure)) != std::string::npos);
  // Without variants, the derivation's own figures (at the description's numbers).
  const auto own = writers::sheet_figures(writers::sheet_problems({{&d, &a->model, {}}})[0], true);
  REQUIRE(own.size() == 2);
  CHECK(own[0].figure == writers::figures_of(d, true)[0]->figure);
}

namespace {

// What lies between the last `open` before each `picture` in the text and the first `close`
// after it (empty where either is missing, or where the box before it closes after `open`).
std::vector<std::string> boxes_around(const std::string& text, const std::string& picture, const std::string& open,
                                      const std::string& close) {
  std::vector<std::string> out;
  for (std::size_t at = text.find(picture); at != std::string::npos; at = text.find(picture, at + 1)) {
    const std::size_t from = text.rfind(open, at), to = text.find(close, at), before = text.rfind(close, at);
    const bool whole =
        from != std::string::npos && to != std::string::npos && (before == std::string::npos || before < from);
    out.push_back(whole ? text.substr(from, to - from) : "");
  }
  return out;
}

}  // namespace

TEST_CASE(
    "Figures: a caption stays with its figure, in latex in one minipage that a page never splits, in html in one "
    "figure element",
    "[figure][sheet]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/incline-and-hanging-block.yaml", test::rules());
  const Derivation d = explain(*a);
  const auto captions = writers::figures_of(d, true);
  REQUIRE(captions.size() == 3);  // the sketch and the two free body diagrams
  const std::vector<SheetEntry> entries{{&d, &a->model, {}}};
  // Every figure, in the derivation and on the sheet, is in a minipage with its caption and
  // nothing else: \begin{minipage}, the picture, \\[2pt]{\small caption}, \end{minipage}.
  for (const std::string& tex : {write(d, Format::latex, true), write_sheet(entries, Format::latex, true)}) {
    const auto boxes = boxes_around(tex, "\\begin{tikzpicture}", "\\begin{minipage}", "\\end{minipage}");
    REQUIRE(boxes.size() == captions.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const std::string caption = "\\end{tikzpicture}\n}\\\\[2pt]{\\small " + captions[k]->text + "}\n";
      INFO(boxes[k]);
      CHECK(boxes[k].size() > caption.size());
      CHECK(boxes[k].rfind(caption) == boxes[k].size() - caption.size());  // the caption ends the box
    }
  }
  // HTML: each drawing and its caption in one <figure>.
  for (const std::string& html : {write(d, Format::html, true), write_sheet(entries, Format::html, true)}) {
    const auto boxes =
        boxes_around(html, "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"fbd\"", "<figure>", "</figure>");
    REQUIRE(boxes.size() == captions.size());
    for (std::size_t k = 0; k < boxes.size(); ++k)
      CHECK(boxes[k].find("<figcaption>" + captions[k]->text + "</figcaption>") != std::string::npos);
  }
}

// By the description: B (center h/2 above the floor) under A (center 3h/2): blocks of height h,
// A's bottom on B's top and B's on the floor, whatever the scale.
TEST_CASE("Sketch: a block resting on a block is drawn on it, and the lower one on the floor", "[figure][sketch]") {
  const auto f = sketch_of("friction-block-on-block.yaml");
  REQUIRE(f);
  auto span = [&](const std::string& name) {
    const auto o = std::find_if(f->outlines.begin(), f->outlines.end(), [&](const auto& x) { return x.name == name; });
    REQUIRE(o != f->outlines.end());
    double lo = 1e300, hi = -1e300;
    for (const auto& c : o->corners) lo = std::min(lo, c.y), hi = std::max(hi, c.y);
    return std::make_pair(lo, hi);
  };
  const auto [a_bottom, a_top] = span("A");
  const auto [b_bottom, b_top] = span("B");
  CHECK(a_bottom == Approx(b_top).margin(1e-9));
  CHECK(a_top - a_bottom == Approx(b_top - b_bottom).margin(1e-9));
  // The floor: the ground line B stands on (the lowest thick line under it).
  double floor = -1e300;
  for (const auto& l : f->lines)
    if (!l.thin && l.points.size() == 2 && std::fabs(l.points[0].y - l.points[1].y) < 1e-9 &&
        l.points[0].y <= b_bottom + 1e-9)
      floor = std::max(floor, l.points[0].y);
  CHECK(b_bottom == Approx(floor).margin(1e-9));
}

namespace {

const Figure& figure_captioned(const std::vector<Figure>& figs, const std::string& caption) {
  const auto f = std::find_if(figs.begin(), figs.end(), [&](const Figure& x) { return x.caption == caption; });
  if (f == figs.end()) FAIL("no figure " << caption);
  return *f;
}

fig::V unit(fig::V a) { return (1 / std::hypot(a.x, a.y)) * a; }
fig::V direction(const FigureArrow& a) { return unit(fig::vp(a.to) - fig::vp(a.from)); }

// The body's outlines: its free body diagram's, then its mass-times-acceleration diagram's.
std::vector<const FigureOutline*> outlines_named(const Figure& f, const std::string& name) {
  std::vector<const FigureOutline*> out;
  for (const auto& o : f.outlines)
    if (o.name == name) out.push_back(&o);
  return out;
}

bool has_equals_sign(const Figure& f) {
  return std::any_of(f.texts.begin(), f.texts.end(), [](const FigureLabel& t) { return t.tex == "="; });
}

}  // namespace

TEST_CASE(
    "FBD: the ladder's mass-times-acceleration diagram: m L theta''/2 along G's path, m L theta'^2/2 to the "
    "corner",
    "[figure][kinetic]") {
  // By hand: the wall is x = 0, the floor y = 0; G = (-L cos(theta)/2, L sin(theta)/2) moves on
  // a circle of radius L/2 about the corner: a_G = (L/2) ddot(theta) (sin, cos) + (L/2)
  // dot(theta)^2 (cos, -sin), the second towards the corner. I alpha = m L^2 ddot(theta)/12.
  const auto a =
      analyze_file(TACKLE_SOURCE_DIR "/examples/rotation-ladder-sliding-on-smooth-wall-and-floor.yaml", test::rules());
  const auto figs = figures_of(*a);
  const Figure& f = figure_captioned(figs, "Free body diagram of ladder");
  const auto bars = outlines_named(f, "ladder");
  REQUIRE(bars.size() == 2);
  const fig::V A = fig::vp(dot_named(f, "A")), B = fig::vp(dot_named(f, "B"));
  const fig::V G = 0.5 * (A + B), corner{B.x, A.y};
  const FigureArrow* tangential = arrow(f, "\\frac{m L \\ddot{\\theta}}{2}");
  const FigureArrow* central = arrow(f, "\\frac{m L \\dot{\\theta}^{2}}{2}");
  REQUIRE(tangential);
  REQUIRE(central);
  CHECK(tangential->dashed);
  CHECK(central->dashed);
  // Both from G in the diagram on the right: the first drawn again, moved along x only.
  const fig::V moved = fig::vp(central->from) - G;
  CHECK(moved.y == Approx(0).margin(1e-9));
  CHECK(moved.x > 0);
  CHECK(fig::len(fig::vp(tangential->from) - fig::vp(central->from)) < 1e-9);
  CHECK(fig::len(direction(*central) - unit(corner - G)) < 1e-6);
  CHECK(std::fabs(fig::dot(direction(*tangential), unit(corner - G))) < 1e-6);
  // The tangent for a growing theta: (sin, cos), up and towards the wall (G's x grows).
  CHECK(direction(*tangential).x > 0);
  CHECK(direction(*tangential).y > 0);
  // The forces stay on the left, the inertial terms on the right, an equals sign between.
  double forces_reach = -1e300, inertial_from = 1e300;
  for (const auto& x : f.arrows) {
    if (x.axis) continue;
    if (x.dashed)
      inertial_from = std::min(inertial_from, x.from.x);
    else
      forces_reach = std::max({forces_reach, x.from.x, x.to.x});
  }
  CHECK(inertial_from > forces_reach);
  REQUIRE(has_equals_sign(f));
  const auto eq = std::find_if(f.texts.begin(), f.texts.end(), [](const FigureLabel& t) { return t.tex == "="; });
  CHECK(eq->at.x > arrow(f, "N_{B}")->from.x);
  CHECK(eq->at.x < central->from.x);
  REQUIRE(f.couples.size() == 1);
  CHECK(f.couples[0].dashed);
  CHECK(f.couples[0].label.tex == "\\frac{m L^{2} \\ddot{\\theta}}{12}");
  CHECK(fig::len(fig::vp(f.couples[0].centre) - fig::vp(central->from)) < 1e-9);
}

TEST_CASE("FBD: a bob's centripetal term is one arrow, m l theta'^2 towards its pin", "[figure][kinetic]") {
  // By hand: the bob at l (sin(theta), -cos(theta)) from O, theta = 30 deg: towards O is
  // (-sin(30 deg), cos(30 deg)) = (-1/2, 0.866).
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/rotation-pendulum.yaml", test::rules());
  const auto figs = figures_of(*a);
  const Figure& f = figure_captioned(figs, "Free body diagram of bob");
  const FigureArrow* central = arrow(f, "m l \\dot{\\theta}^{2}");
  REQUIRE(central);
  CHECK(central->dashed);
  CHECK(direction(*central).x == Approx(-0.5).margin(1e-9));
  CHECK(direction(*central).y == Approx(std::sqrt(3.0) / 2).margin(1e-9));
  REQUIRE(arrow(f, "m l \\ddot{\\theta}"));
  CHECK(std::none_of(f.arrows.begin(), f.arrows.end(),
                     [](const FigureArrow& x) { return x.label.tex.find("\\sin") != std::string::npos; }));
}

TEST_CASE("FBD: a body that does not accelerate has no mass-times-acceleration diagram", "[figure][kinetic]") {
  // The Atwood machine's sheave C is massless: m a = 0, nothing to draw beside its forces.
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/atwood-machine.yaml", test::rules());
  const auto figs = figures_of(*a);
  const Figure& f = figure_captioned(figs, "Free body diagram of C");
  CHECK(f.outlines.size() == 1);
  CHECK(!has_equals_sign(f));
  CHECK(std::none_of(f.arrows.begin(), f.arrows.end(), [](const FigureArrow& x) { return x.dashed; }));
}

TEST_CASE("FBD: a wedge is drawn as its triangle, the block on it turned along its face", "[figure][shape]") {
  // The description: a right triangle of base b and height b tan(30 deg), its centroid at the
  // center of mass, the right angle at the lower left; the block slides on the face, which
  // falls to the right at 30 deg.
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/block-on-a-moving-wedge.yaml", test::rules());
  const auto figs = figures_of(*a);
  const Figure& w = figure_captioned(figs, "Free body diagram of wedge");
  const auto wedges = outlines_named(w, "wedge");
  REQUIRE(wedges.size() == 2);
  const auto& c = wedges[0]->corners;
  REQUIRE(c.size() == 3);
  const fig::V base = fig::vp(c[1]) - fig::vp(c[0]), side = fig::vp(c[2]) - fig::vp(c[0]);
  CHECK(base.y == Approx(0).margin(1e-9));
  CHECK(base.x > 0);
  CHECK(side.x == Approx(0).margin(1e-9));
  CHECK(side.y / base.x == Approx(std::tan(M_PI / 6)).epsilon(1e-9));
  const fig::V centroid = (1.0 / 3) * (fig::vp(c[0]) + fig::vp(c[1]) + fig::vp(c[2]));
  CHECK(std::any_of(w.dots.begin(), w.dots.end(),
                    [&](const FigureDot& d) { return !d.label && fig::len(fig::vp(d.at) - centroid) < 1e-9; }));
  // The block's sides along the face (30 deg down to the right) and across it.
  const Figure& b = figure_captioned(figs, "Free body diagram of block");
  const auto& k = outlines_named(b, "block")[0]->corners;
  REQUIRE(k.size() == 4);
  const fig::V edge = unit(fig::vp(k[1]) - fig::vp(k[0]));
  CHECK(std::fabs(fig::cross(edge, fig::V{std::cos(M_PI / 6), -std::sin(M_PI / 6)})) < 1e-9);
}

TEST_CASE("Sketch: the block rests on the wedge's face, turned along it", "[figure][sketch][shape]") {
  const auto f = sketch_of("block-on-a-moving-wedge.yaml");
  REQUIRE(f);
  const FigureOutline* wedge = outline_named(*f, "wedge");
  const FigureOutline* block = outline_named(*f, "block");
  REQUIRE(wedge);
  REQUIRE(block);
  REQUIRE(wedge->corners.size() == 3);
  REQUIRE(block->corners.size() == 4);
  // The face from the top to the foot; each of the block's corners is on it or above it, two
  // of them on it (its bottom side lies on the face), the other two a block's height away.
  const fig::V top = fig::vp(wedge->corners[2]), foot = fig::vp(wedge->corners[1]);
  const fig::V along = unit(foot - top), out{-along.y, along.x};  // outward: up and to the right
  CHECK(out.y > 0);
  std::vector<double> heights;
  for (const auto& p : block->corners) heights.push_back(fig::dot(fig::vp(p) - top, out));
  std::sort(heights.begin(), heights.end());
  CHECK(heights[0] == Approx(0).margin(1e-9));
  CHECK(heights[1] == Approx(0).margin(1e-9));
  CHECK(heights[2] > 0.2);
  CHECK(heights[3] == Approx(heights[2]).margin(1e-9));
}

TEST_CASE("Sketch: the pendulum on a cart hangs on its rod from the pin P, drawn open", "[figure][sketch][shape]") {
  const auto f = sketch_of("rotation-pendulum-on-a-cart.yaml");
  REQUIRE(f);
  const auto p =
      std::find_if(f->dots.begin(), f->dots.end(), [](const FigureDot& d) { return d.label && d.label->tex == "P"; });
  REQUIRE(p != f->dots.end());
  CHECK(p->pin);
  const FigureOutline* bob = outline_named(*f, "bob");
  REQUIRE(bob);
  REQUIRE(bob->shape == FigureOutline::Shape::circle);
  // The rod: from P to the bob's rim, towards its center.
  CHECK(std::any_of(f->lines.begin(), f->lines.end(), [&](const FigureLine& l) {
    return l.points.size() == 2 && fig::len(fig::vp(l.points[0]) - fig::vp(p->at)) < 1e-9 &&
           std::fabs(fig::len(fig::vp(l.points[1]) - fig::vp(bob->centre)) - bob->radius) < 1e-9;
  }));
  // In the SVG the pin is an open circle.
  CHECK(to_svg(*f).find("fill=\"white\" stroke=\"black\"") != std::string::npos);
}

TEST_CASE("FBD: a wedge facing left is the mirror image", "[figure][shape]") {
  const std::string yaml =
      test::example_with("block-on-a-moving-wedge.yaml", R"y(draw: {shape: wedge, size: [b, "b*tan(theta)"]})y",
                         R"y(draw: {shape: wedge, size: [b, "b*tan(theta)"], face: left})y");
  const auto a = test::run_text(yaml);
  const auto figs = figures_of(*a);
  const Figure& w = figure_captioned(figs, "Free body diagram of wedge");
  const auto& c = outlines_named(w, "wedge")[0]->corners;
  REQUIRE(c.size() == 3);
  // The right angle at the lower right, the top above it: the face looks up and to the left.
  double lo = 1e300, hi = -1e300;
  for (const auto& p : c) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  const auto top = std::max_element(c.begin(), c.end(), [](const auto& p, const auto& q) { return p.y < q.y; });
  CHECK(top->x == Approx(hi).margin(1e-9));
  CHECK(hi > lo);
  // Counterclockwise still (the outline's inside is on the left of each edge).
  double area = 0;
  for (std::size_t i = 0; i < 3; ++i) area += c[i].x * c[(i + 1) % 3].y - c[(i + 1) % 3].x * c[i].y;
  CHECK(area > 0);
}

namespace {

// The sketch's outlines of `corners` corners without a body's name (the ground's shapes).
std::vector<const FigureOutline*> unnamed_polygons(const Figure& f, std::size_t corners) {
  std::vector<const FigureOutline*> out;
  for (const auto& o : f.outlines)
    if (o.name.empty() && o.shape == FigureOutline::Shape::polygon && o.corners.size() == corners) out.push_back(&o);
  return out;
}

}  // namespace

TEST_CASE("Sketch: an incline is a triangle at its angle, the cylinder rolling on its slope",
          "[figure][sketch][shape]") {
  // The description: the slope falls to the right at theta = 30 deg; the cylinder (radius r)
  // touches it at C.
  const auto f = sketch_of("rotation-cylinder-rolling-down-incline.yaml");
  REQUIRE(f);
  const auto triangles = unnamed_polygons(*f, 3);
  REQUIRE(triangles.size() == 1);
  const auto& c = triangles[0]->corners;
  // One side horizontal (the base), one vertical (the back), the third at 30 deg.
  int horizontal = 0, vertical = 0, slope = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const fig::V e = fig::vp(c[(i + 1) % 3]) - fig::vp(c[i]);
    if (std::fabs(e.y) < 1e-9) ++horizontal;
    if (std::fabs(e.x) < 1e-9) ++vertical;
    if (std::fabs(std::fabs(e.y / e.x) - std::tan(M_PI / 6)) < 1e-9) ++slope;
  }
  CHECK(horizontal == 1);
  CHECK(vertical == 1);
  CHECK(slope == 1);
  // The cylinder touches the slope: its center a radius from the slope's line.
  const FigureOutline* cylinder = outline_named(*f, "cylinder");
  REQUIRE(cylinder);
  CHECK(fig::boundary_distance(*triangles[0], fig::vp(cylinder->centre)) == Approx(cylinder->radius).margin(1e-6));
}

TEST_CASE("Sketch: the incline's triangle stops short of the block hanging beside its top", "[figure][sketch][shape]") {
  const auto f = sketch_of("incline-and-hanging-block.yaml");
  REQUIRE(f);
  const auto triangles = unnamed_polygons(*f, 3);
  REQUIRE(triangles.size() == 1);
  const FigureOutline* b = outline_named(*f, "B");
  REQUIRE(b);
  double right = -1e300;
  for (const auto& p : triangles[0]->corners) right = std::max(right, p.x);
  double left = 1e300;
  for (const auto& p : b->corners) left = std::min(left, p.x);
  CHECK(right < left);
}

TEST_CASE("Sketch: a spool shows its hub, its string leaving the hub at H", "[figure][sketch][shape]") {
  // The description: R = 0.2 m, its hub r = 0.1 m; H is the bottom of the hub, where the
  // string pulls to the right.
  const auto f = sketch_of("rotation-spool-pulled-by-its-string.yaml");
  REQUIRE(f);
  const FigureOutline* spool = outline_named(*f, "spool");
  REQUIRE(spool);
  const fig::V o = fig::vp(spool->centre);
  const auto hub = std::find_if(f->lines.begin(), f->lines.end(), [&](const FigureLine& l) {
    return l.points.size() > 8 && std::all_of(l.points.begin(), l.points.end(), [&](const FigurePoint& p) {
             return std::fabs(fig::len(fig::vp(p) - o) - spool->radius / 2) < 1e-6;
           });
  });
  CHECK(hub != f->lines.end());
  const fig::V h = o + fig::V{0, -spool->radius / 2};
  CHECK(std::any_of(f->lines.begin(), f->lines.end(), [&](const FigureLine& l) {
    return l.points.size() == 2 && fig::len(fig::vp(l.points[0]) - h) < 1e-6 &&
           std::fabs(fig::boundary_distance(*spool, fig::vp(l.points[1]))) < 1e-6;
  }));
}

TEST_CASE("Sketch: a car stands on its wheels, one on the ground at each wheel's point", "[figure][sketch][shape]") {
  const auto f = sketch_of("car-braking-all.yaml");
  REQUIRE(f);
  std::vector<const FigureOutline*> wheels;
  for (const auto& o : f->outlines)
    if (o.name.empty() && o.shape == FigureOutline::Shape::circle) wheels.push_back(&o);
  REQUIRE(wheels.size() == 2);
  for (const auto* w : wheels) {
    // Its lowest point on the ground line, which the hatching hangs from.
    const double bottom = w->centre.y - w->radius;
    CHECK(std::any_of(f->lines.begin(), f->lines.end(), [&](const FigureLine& l) {
      return !l.thin && l.points.size() == 2 && std::fabs(l.points[0].y - bottom) < 1e-9 &&
             std::fabs(l.points[1].y - bottom) < 1e-9;
    }));
  }
}

TEST_CASE("FBD: a label's fractions are written on one line in TikZ, as in the SVG", "[figure]") {
  Figure f;
  FigureArrow a;
  a.from = {0, 0};
  a.to = {1, 0};
  a.label.tex = "\\frac{m L \\ddot{\\theta}}{2}";
  f.arrows.push_back(a);
  FigureLabel sum;
  sum.tex = "\\frac{a + b}{c d}";
  f.texts.push_back(sum);
  const std::string tikz = to_tikz(f);
  CHECK(tikz.find("$m L \\ddot{\\theta}/{2}$") != std::string::npos);
  CHECK(tikz.find("$\\left(a + b\\right)/\\left(c d\\right)$") != std::string::npos);
  CHECK(tikz.find("\\frac") == std::string::npos);
  // The SVG says the same: m L θ̈/2.
  CHECK(svg_text("\\frac{a + b}{c d}").find("(a") != std::string::npos);
}
