#include "model/path.hpp"

#include <set>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"
#include "expr/trig.hpp"
#include "model/model.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// The value of `e` in the layout, or nothing (with the symbols still missing named).
std::optional<numeric> in_layout(const ex& e, const exmap& layout, std::string& missing) {
  // Most positions are rational in the layout's numbers (x_2 - x_1): their value exactly,
  // without a normal form (a chain of 256 spent a twentieth of its run making them). A pole
  // on the way may be removable, and the normal form below decides it.
  if (const RationalAt r = rational_at(e, layout); r.kind == RationalAt::Kind::value)
    return ex_to<numeric>(r.value.evalf());
  // The normal form's denominator first: a pole at the layout has no value (and GiNaC would
  // throw from inside a node it is making, which leaks).
  const NormalForm form(e);
  if (form.undefined_at(layout)) return std::nullopt;
  const ex v = evalf(substituted(form.num, layout) / substituted(form.den, layout));
  if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v);
  std::set<std::string> names;
  for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
    if (is_a<symbol>(*it)) names.insert(to_text(*it));
  missing = join(std::vector<std::string>(names.begin(), names.end()));
  return std::nullopt;
}

// True when no root of an expression in the coordinates is left (the segment's direction
// is then fixed while it changes length).
bool is_polynomial_root(const ex& length) {
  for (const_preorder_iterator it = length.preorder_begin(); it != length.preorder_end(); ++it)
    if (is_a<power>(*it) && !(is_a<numeric>(it->op(1)) && ex_to<numeric>(it->op(1)).is_integer()) &&
        !is_a<numeric>(it->op(0)))
      return false;
  return true;
}

// |v| simplified: a perfect square's root (sign chosen so it is positive in `layout`), else
// sqrt(v.v). Nothing when the layout cannot tell the sign; `missing` then names what to give.
std::optional<ex> simplified_norm(const Vec& v, const exmap& layout, std::string& missing) {
  const ex squared = inner(v, v).expand();
  std::optional<ex> root;
  for (const ex& form : {squared, pythagoras(squared, true), pythagoras(squared, false)})
    if ((root = square_root_of(form))) break;
  if (!root) root = sqrt(pythagoras(squared, true));
  const auto value = in_layout(*root, layout, missing);
  if (!value) return std::nullopt;
  return value->is_negative() ? ex(-*root) : *root;
}

}  // namespace

std::optional<ex> square_root_of(const ex& squared) {
  exmap repl;
  const ex poly = squared.to_polynomial(repl);
  lst syms;
  std::set<ex, ex_is_less> seen;
  for (const_preorder_iterator it = poly.preorder_begin(); it != poly.preorder_end(); ++it)
    if (is_a<symbol>(*it) && seen.insert(*it).second) syms.append(*it);
  const ex f = syms.nops() == 0 ? poly : sqrfree(poly, syms);
  ex root = 1;
  // Each factor as it was (to_polynomial stands a symbol for a numeric's inverse, 1/4, too).
  auto take = [&](const ex& stood) {
    const ex factor = substituted(stood, repl);
    if (is_a<numeric>(factor)) {
      if (!ex_to<numeric>(factor).is_positive()) return false;
      root *= sqrt(factor);
      return true;
    }
    if (is_a<power>(factor) && is_a<numeric>(factor.op(1)) && ex_to<numeric>(factor.op(1)).is_even()) {
      root *= pow(factor.op(0), ex_to<numeric>(factor.op(1)) / 2);
      return true;
    }
    return false;
  };
  if (is_a<mul>(f)) {
    for (const auto& factor : f)
      if (!take(factor)) return std::nullopt;
  } else if (!take(f)) {
    return std::nullopt;
  }
  return root.expand();
}

std::optional<Path> make_path(const std::vector<int>& indices, const std::vector<Point>& points, int dims,
                              const exmap& layout, Diagnostics& diags, const Location& at, const std::string& label,
                              const NameTurningLength& turning) {
  Path p;
  p.points = indices;
  bool ok = true;
  for (std::size_t i = 0; i + 1 < indices.size(); ++i) {
    const Point& a = points[indices[i]];
    const Point& b = points[indices[i + 1]];
    PathSegment s;
    s.from = indices[i];
    s.to = indices[i + 1];
    s.constant = a.body == b.body;  // one body, or both fixed (-1)
    const std::string name = a.name + "-" + b.name + " of " + label;
    Vec v = b.position - a.position;
    for (int k = dims; k < 3; ++k) v[k] = 0;
    std::string missing;
    std::optional<ex> length;
    if (dims == 1) {
      const auto value = in_layout(v[0], layout, missing);
      if (value && !value->is_zero())
        length = value->is_negative() ? ex(-v[0]) : v[0];
      else if (value)
        missing.clear();
    } else {
      length = simplified_norm(v, layout, missing);
    }
    if (!length && !missing.empty()) {
      if (!s.constant) {
        diags.error(at, "cannot tell the direction of strand " + name + " (give 'layout' values for " + missing + ")");
        ok = false;
      }
      continue;
    }
    if (length) {
      std::string unused;
      if (const auto value = in_layout(*length, layout, unused); value && value->is_zero()) length.reset();
    }
    if (!length) {
      if (!s.constant) {
        diags.error(at, "strand " + name + " has zero length in the layout (expected its ends apart)");
        ok = false;
      }
      continue;
    }
    // A root left in the coordinates: the strand turns as the bodies move. Its length is a
    // symbol from here on (l^2 = the squared length), so that GiNaC's normal() never has to
    // cancel roots (it does so in some runs and not in others).
    if (!s.constant && !is_polynomial_root(*length)) length = turning(a, b, pow(*length, 2).expand());
    s.length = *length;
    for (int k = 0; k < 3; ++k) s.direction[k] = normal(v[k] / *length);
    if (dims == 1) s.direction = {(v[0] / *length).normal(), 0, 0};
    p.length += s.length;
    if (!s.constant) p.varying_length += s.length;
    p.segments.push_back(s);
  }
  if (!ok) return std::nullopt;
  return p;
}

std::vector<Load> tension_loads(const Path& p, const std::vector<Point>& points, const ex& tension,
                                const LoadOrigin& of) {
  std::vector<Load> out;
  for (const auto& s : p.segments) {
    if (s.constant) continue;  // internal to one body, or between fixed points
    const Point& a = points[s.from];
    const Point& b = points[s.to];
    const std::string strand = a.name + "-" + b.name;
    for (const auto& [end, sign] : {std::pair{&a, 1}, std::pair{&b, -1}}) {
      if (end->body < 0) continue;
      Load load;
      load.body = end->body;
      for (int k = 0; k < 3; ++k) load.force[k] = sign * tension * s.direction[k];
      load.at = end->position;
      load.at_name = end->name;
      load.origin = strand_origin(of, strand, end->name);
      out.push_back(load);
    }
  }
  return out;
}

}  // namespace tackle
