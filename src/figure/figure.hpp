// Free body diagrams, drawn: a Figure is a picture in drawing units (about centimetres, y up)
// made from the model's geometry: each body's outline, the points, every force as an arrow at
// its point of application with its symbol, couples as arcs, the inertial terms m a and
// I alpha dashed beside them, and the axes. Writers turn it into TikZ (LaTeX) or SVG (Markdown, HTML).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tackle {

struct FigurePoint {
  double x = 0, y = 0;
};

struct FigureLabel {
  FigurePoint at;                // the centre of the label
  std::string tex;               // LaTeX math (no dollars)
  double width = 0, height = 0;  // the box the layout kept free for it
};

struct FigureArrow {
  FigurePoint from, to;  // tail, head
  FigureLabel label;
  bool dashed = false;  // the inertial term m a
  bool axis = false;    // a coordinate axis of the triad
};

struct FigureCouple {
  FigurePoint centre;
  double radius = 0.5;
  bool counterclockwise = true;
  bool dashed = false;  // the inertial term I alpha
  FigureLabel label;
};

struct FigureOutline {
  enum class Shape { polygon, circle } shape = Shape::polygon;
  std::vector<FigurePoint> corners;  // polygon, in order
  FigurePoint centre;                // circle
  double radius = 0;
  std::string name;  // the body's name
};

struct FigureDot {
  FigurePoint at;
  std::optional<FigureLabel> label;  // a named point
  bool pin = false;                  // a pin or a hinge (the sketch's): an open circle, not a filled dot
};

// A line drawn through points: a string, a spring's coils, a support, the hatching of the ground.
struct FigureLine {
  std::vector<FigurePoint> points;
  bool thin = false;  // hatching
};

struct Figure {
  std::string caption;      // "Free body diagram of the suitcase"
  bool sketch = false;      // the mechanism's sketch (a sheet shows it), not a free body diagram
  std::vector<int> bodies;  // a free body diagram's bodies, and whether as one system (to draw it again)
  bool system = false;
  std::vector<FigureOutline> outlines;
  std::vector<FigureLine> lines;   // drawn over the outlines
  std::vector<FigureLabel> texts;  // names written on the figure (a block's)
  std::vector<FigureDot> dots;
  std::vector<FigureArrow> arrows;  // forces, inertial terms and the axes
  std::vector<FigureCouple> couples;
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;  // everything drawn, labels included
};

/// Draws the free body diagrams of one model: the numbers its geometry is drawn at are made
/// once (for a chain of 256 bodies, not 256 times).
class FigureMaker {
 public:
  explicit FigureMaker(const Model& m);
  /// At other values of the parameters (SI, by symbol: a variant's): the layout's numbers
  /// with these over the parameters' own, the defined parameters made again from them.
  FigureMaker(const Model& m, const GiNaC::exmap& values);
  /// The same figure (the sketch, or a free body diagram of the same bodies) drawn by this
  /// maker, at its numbers; none where it cannot be drawn there.
  [[nodiscard]] std::optional<Figure> redraw(const Figure& f) const;
  /// The diagram of one body, or of a system of bodies (see free_body_diagram).
  [[nodiscard]] std::optional<Figure> draw(const std::vector<int>& bodies, bool system) const;
  /// The mechanism's sketch (see mechanism_sketch).
  [[nodiscard]] std::optional<Figure> sketch() const;

 private:
  [[nodiscard]] std::optional<Figure> sketch_line() const;   // 1-D
  [[nodiscard]] std::optional<Figure> sketch_plane() const;  // 2-D
  [[nodiscard]] std::optional<double> number(const GiNaC::ex& e) const;
  const Model& m_;
  GiNaC::exmap values_;
  std::set<GiNaC::ex, GiNaC::ex_is_less> unknowns_;
};

/// The free body diagram of one body, or of a system of bodies (only the forces from outside
/// it), from the model's geometry at the layout's numbers (a parameter without a value taken
/// as 1). None when the geometry cannot be evaluated (a position undefined there).
[[nodiscard]] std::optional<Figure> free_body_diagram(const Model& m, const std::vector<int>& bodies, bool system);

/// The sketch of a mechanism at the layout's numbers. 1-D: its blocks, its strings along
/// their paths (strands side by side, wrapped around sheaves where they turn), springs and
/// dampers, the ground where points are fixed, the applied forces and the axis; none for one
/// without a string, spring or damper. 2-D (turned so that gravity points down the page):
/// each body (its shape, a bar or plate through its points, or a block along the surface it
/// touches), the ground surfaces bodies touch (hatched, an incline at its angle), pins and
/// fixed points with their supports, pulleys, strings along their paths (wrapping pulleys
/// where they turn), cables and rods, springs and dampers, applied forces and couples, the
/// angles that parameters or coordinates give, the named points and the axes. None for 3-D
/// problems, and whenever a position cannot be evaluated at the layout's numbers.
[[nodiscard]] std::optional<Figure> mechanism_sketch(const Model& m);

/// The figure as a tikzpicture (needs \usepackage{tikz}).
[[nodiscard]] std::string to_tikz(const Figure& f);
/// The figure as a standalone <svg> element (labels as text with sub- and superscripts). Its
/// one id (the arrowhead's) begins with `ids`: distinct prefixes for figures that share a page
/// with other documents' figures of the same caption.
[[nodiscard]] std::string to_svg(const Figure& f, const std::string& ids = "");
/// A label's LaTeX as SVG text content (<tspan>s for sub- and superscripts, Greek letters as
/// characters), XML-escaped. Dots (\dot, \ddot) are not in it: svg_label places them, and
/// to_svg draws them as small circles (browsers draw combining dots over an italic serif
/// letter unevenly, Chromium not at all).
[[nodiscard]] std::string svg_text(const std::string& tex);
/// How to_svg writes a label (drawing units, y up): its text centred at x in the box the
/// layout kept, on a baseline that centres the text's ascent and descent in the box, held to
/// `width` (textLength): so the text fills [x - width/2, x + width/2] across and
/// [baseline - svg_descent * font_size, baseline + svg_ascent * font_size] up the page, inside
/// the label's box. `dots`: the dots of its dotted letters (\dot{\theta}, \ddot{x}_{A}), one
/// or two over each, centred over the letter's estimated advance (leaning as an italic letter
/// does) and above its top (x-height or capital), smaller over a sub- or superscript.
struct SvgDot {
  double x = 0, y = 0, r = 0;
};
struct SvgLabel {
  double x = 0, baseline = 0, width = 0, font_size = 0;
  std::vector<SvgDot> dots;
};
constexpr double svg_font_size = 0.35;  // as TikZ's \small (10 pt) in a 1 cm unit
constexpr double svg_ascent = 0.8,
                 svg_descent = 0.3;  // of the font size: capitals with a dot or a superscript, a subscript
constexpr double svg_margin = 0.04;  // between the text and its box's sides
[[nodiscard]] SvgLabel svg_label(const FigureLabel& l);
/// The number of characters a label shows (for its width).
[[nodiscard]] std::size_t shown_length(const std::string& tex);

}  // namespace tackle
