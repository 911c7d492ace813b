// The last pass over a figure's labels (figure/labels.hpp), on figures drawn by hand: where a
// label is crossed, where it goes, and that a clear label stays.
#include <catch2/catch.hpp>

#include "figure/labels.hpp"

using namespace tackle;
using namespace tackle::fig;

namespace {

FigureLabel label_at(double x, double y, const std::string& tex) {
  FigureLabel l;
  l.at = {x, y};
  l.tex = tex;
  l.width = 0.5;
  l.height = 0.4;
  return l;
}

}  // namespace

TEST_CASE("Labels: a label a line runs through moves just clear of it, and no farther", "[figure]") {
  Figure f;
  f.lines.push_back({{{-3, 0}, {3, 0}}, false});  // along y = 0
  FigureDot d;
  d.at = {2, 2};
  d.label = label_at(0, 0.1, "P");  // its box spans y from -0.1 to 0.3: the line crosses it
  f.dots.push_back(d);
  const auto drawn = strokes(f);
  auto labels = labels_of(f);
  REQUIRE(crossings({vp(f.dots[0].label->at), 0.5, 0.4}, drawn, labels, 0) == 1);
  settle_labels(f);
  const V at = vp(f.dots[0].label->at);
  CHECK(crossings({at, 0.5, 0.4}, drawn, labels, 0) == 0);
  // Clear of the line by half its height: 0.2 from y = 0, up (0.1 away) rather than down (0.3).
  CHECK(at.y >= 0.2);
  CHECK(len(at - V{0, 0.1}) <= 0.2 + 1e-9);
}

TEST_CASE("Labels: a label nothing crosses stays where the layout put it", "[figure]") {
  Figure f;
  f.lines.push_back({{{-3, 0}, {3, 0}}, false});
  FigureArrow a;
  a.from = {0, 1};
  a.to = {1.2, 1};
  a.label = label_at(0.6, 1.5, "F");  // 0.3 above the shaft, whose head reaches 0.175 off it
  f.arrows.push_back(a);
  settle_labels(f);
  CHECK(f.arrows[0].label.at.x == 0.6);
  CHECK(f.arrows[0].label.at.y == 1.5);
}

TEST_CASE("Labels: an arrow's head as drawn, 0.35 long and wide, crosses a label beside its tip", "[figure]") {
  Figure f;
  FigureArrow a;
  a.from = {0, 0};
  a.to = {1.2, 0};
  a.label = label_at(0.9, 0.3, "N");  // box from y = 0.1 to 0.5: clear of the shaft, not of the head
  f.arrows.push_back(a);
  const auto drawn = strokes(f);
  auto labels = labels_of(f);
  CHECK(crossings({vp(f.arrows[0].label.at), 0.5, 0.4}, drawn, labels, 0) > 0);
  settle_labels(f);
  CHECK(crossings({vp(f.arrows[0].label.at), 0.5, 0.4}, drawn, labels, 0) == 0);
}

TEST_CASE("Labels: two labels on one place are set apart, the first drawn staying", "[figure]") {
  Figure f;
  FigureDot p, q;
  p.at = {0, 0};
  p.label = label_at(0.5, 0.5, "A");
  q.at = {1, 0};
  q.label = label_at(0.5, 0.5, "B");
  f.dots = {p, q};
  settle_labels(f);
  CHECK(f.dots[0].label->at.x == 0.5);
  CHECK(f.dots[0].label->at.y == 0.5);
  const Box a{vp(f.dots[0].label->at), 0.5 + label_spacing, 0.4 + label_spacing};
  const Box b{vp(f.dots[1].label->at), 0.5, 0.4};
  CHECK_FALSE(overlaps(a, b));
}
