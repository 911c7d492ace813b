// The Model: a problem with its symbols made, its rules instantiated and every load and
// constraint expressed in GiNaC. Built from a Description and a RuleSet; immutable after.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "description/description.hpp"
#include "model/symbols.hpp"
#include "ruleset/ruleset.hpp"

namespace tackle {

struct Body {
  std::string name;
  GiNaC::ex mass;      // 0 for an ideal pulley block
  bool has_mass = false;
  GiNaC::ex coord;     // x_A
  GiNaC::ex rate;      // dot(x_A)
  GiNaC::ex accel;     // ddot(x_A)
  Location at;
};

struct Point {
  std::string name;
  GiNaC::ex position;  // along the axis
  int body = -1;       // -1: fixed to the ground
  Location at;
};

/// A force on a body, with where it comes from (a small immutable value).
struct Load {
  int body = -1;
  GiNaC::ex force;
  std::string source;  // "force F on A", "string s: strand pB-C", "gravity"
};

/// A quantity held constant in time (a string's length sum, a still body's coordinate); its
/// first and second time derivatives vanish.
struct Constraint {
  std::string label;    // "string s", "support of C"
  std::string connection;  // the connection's name, for `derive: [{constraint: ...}]`
  GiNaC::ex quantity;   // e.g. 3*x_B - 2*x_A
  std::string meaning;  // "length of string s", "position of C"
};

/// A condition under which the model holds, from a rule's `validity`.
struct Condition {
  GiNaC::ex lhs, rhs;
  std::string op;  // >=, <=, >, <, =
  std::string meaning, otherwise, source;
};

/// A quantity to report: an unknown, a given, or an expression defined from them.
struct Wanted {
  std::string name;
  std::string tex;
  GiNaC::ex expr;  // the symbol itself, or the defining expression
  bool defined = false;
  std::optional<Dimension> dimension;
};

/// A balance or constraint the user asked for (`derive`).
struct Selection {
  enum class Kind { lmb, constraint } kind;
  std::vector<int> bodies;  // lmb: one body, or a system
  bool system = false;
  std::string constraint;   // constraint: the connection name
};

struct Model {
  std::string file;
  std::string title;
  std::string axis = "x";
  std::shared_ptr<const SymbolTable> symbols;
  std::vector<Body> bodies;
  std::vector<Point> points;
  std::vector<Load> loads;
  std::vector<Constraint> constraints;
  std::vector<Condition> conditions;
  std::vector<std::string> assumptions;
  std::vector<std::string> connections;  // one line per connection: "string s: <summary>"
  std::optional<GiNaC::ex> gravity;
  std::vector<GiNaC::ex> candidates;  // possible unknowns: accelerations, then rule unknowns
  std::vector<GiNaC::ex> given;       // kinematic quantities given as known
  std::vector<Wanted> wanted;
  std::vector<Selection> derive;      // empty: a complete set
};

/// Builds the model; every problem in the description is reported at once (InputError).
[[nodiscard]] Model build_model(const Description& d, const RuleSet& rules);

}  // namespace tackle
