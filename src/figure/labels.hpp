// Labels settled once a figure is whole (internal to src/figure/). The Layout of
// figure/geometry.hpp places each label as it is made, clear of what is drawn by then; lines,
// arrows and labels drawn after it may still cross it. This last pass looks at everything
// drawn, as the writers draw it (an arrow's head as a triangle, a circle's rim, a couple's arc
// and head, a point's dot), and moves each crossed label to the nearest place around it that
// nothing crosses.
#pragma once

#include <vector>

#include "figure/geometry.hpp"

namespace tackle::fig {

/// A stroke of the figure as drawn: a straight piece of an outline, a line, an arrow's shaft or
/// head, an arc's chord.
struct Stroke {
  V p, q;
};

/// Everything `f` draws but its labels, as strokes: polygons' edges, circles' rims and couples'
/// arcs in chords of at most 15 degrees, lines, arrows with their heads (the SVG writer's
/// marker: as long as 7 stroke widths and as wide), and a 0.125-unit square for each dot.
[[nodiscard]] std::vector<Stroke> strokes(const Figure& f);

/// Every label of `f`, in the order the writers draw them: the names on bodies, the points',
/// the arrows', the couples'.
[[nodiscard]] std::vector<FigureLabel*> labels_of(Figure& f);

/// How many strokes, and labels among the first `before` of `labels` (with label_spacing
/// between boxes), `box` meets.
[[nodiscard]] int crossings(const Box& box, const std::vector<Stroke>& drawn, const std::vector<FigureLabel*>& labels,
                            std::size_t before);

/// Moves each label that something drawn or a label before it crosses to the nearest place
/// around it (rings 0.1 units apart, out to 1.6 units, 32 places each) where nothing does; a
/// label with no such place stays where it crosses least. Labels are taken in drawing order,
/// so a later label makes way for an earlier one.
void settle_labels(Figure& f);

}  // namespace tackle::fig
