// Connection and element types as data (rules/*.yaml). A rule declares the arguments a
// connection gives, the unknowns it introduces, the loads it applies, the constraints it
// imposes, the conditions under which it holds and the assumptions it stands for. The model
// instantiates rules through a handful of primitives (a force on a body, tension along a
// path, a length held constant, a body held still); no C++ code names a connection type.
#pragma once

#include <array>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/units.hpp"

namespace tackle {

enum class ArgKind {
  body,
  point,
  points,
  expr,
  name,
  vector,
  moment
};  // moment: a number in 2-D (about z), a vector in 3-D

struct ArgSpec {
  std::string key;
  ArgKind kind = ArgKind::expr;
  std::optional<Dimension> dimension;  // for expr arguments
  bool required = true;
  bool kind_known = true;  // false when the rule file named an unknown kind (already reported)
  friend bool operator==(const ArgSpec&, const ArgSpec&) = default;
};

/// `when:` of a rule entry (an unknown, a load, a validity condition, a check, an
/// assumption): empty (always), an optional argument (only when the connection gives it), or
/// "1-D", "2-D", "3-D" (only in a problem with that many axes: a contact's friction is along
/// one tangent in 2-D and anywhere in its tangent plane in 3-D). The number of axes of such a
/// `when`, or nothing for an argument's name.
[[nodiscard]] std::optional<int> when_axes(const std::string& when);

struct UnknownSpec {
  std::string local;                      // name inside the rule's expressions, e.g. T
  std::string name_template;              // e.g. "T_{name}": {key} is replaced by the argument's text
  std::optional<std::string> rename_arg;  // a `name` argument that overrides the template
  Dimension dimension;
  std::string when;  // see when_axes()
  friend bool operator==(const UnknownSpec&, const UnknownSpec&) = default;
};

/// Loads: `on` applies the force `expr` (and the couple `couple`) to a body, at the point
/// argument `at` (or at the `on` point itself); `along` pulls every point of a path towards
/// its neighbours with tension `expr`; `from_length` applies the generalized force
/// -expr * d(length)/dq to every coordinate q of a hand-written length sum.
struct LoadSpec {
  enum class Kind { on, along, from_length } kind;
  std::string arg;
  std::string expr;    // force (on) or tension (along, from_length); may be empty for a pure couple
  std::string at_arg;  // on: the point of application
  std::string couple;  // on: a couple, as an expression
  std::string when;    // an optional argument; the load applies only when it is given
  Location at;
  friend bool operator==(const LoadSpec&, const LoadSpec&) = default;
};

/// Constraints: `length` holds a path's length constant, `length_sum` a hand-written length
/// sum, `still` a body's acceleration at zero, `together` (with `with`) the position of one
/// body relative to another (they share a translation), `rolls` (with `at`, `along`) a body
/// rolling without slipping at a contact point along a straight surface, `keeps` (with
/// `with`, `along`) the position of one body relative to another along a direction (two
/// bodies that stay in contact, or do not slip on each other).
struct ConstraintSpec {
  enum class Kind { length, length_sum, still, together, rolls, keeps } kind;
  std::string arg;
  std::string with;   // together, keeps: the second body argument; rolls: the rolling direction (a vector)
  std::string point;  // rolls: the contact point
  Location at;
  std::string along;  // keeps: the direction (a vector argument)
  friend bool operator==(const ConstraintSpec&, const ConstraintSpec&) = default;
};

/// One regime of a connection that is decided at the given numbers (`regimes:`, tried in
/// order: the first whose validity holds there is the model): the rule the connection becomes
/// and its arguments, each the one of the same name, or as `args` map it (`mu: mu_s`), or a
/// vector argument turned against the sign of an unknown of the regime before (`sliding:
/// {against: F, of: tangent}`: the way friction F could not hold).
struct RegimeSpec {
  std::string type;
  std::vector<std::pair<std::string, std::string>> args;  // the regime's argument -> this rule's
  std::string turned, against, of;                        // turned: the regime's vector argument
  Location at;
  friend bool operator==(const RegimeSpec&, const RegimeSpec&) = default;
};

struct ValiditySpec {
  std::string holds;  // relation over the rule's local names, e.g. "T >= 0"
  std::string meaning;
  std::string otherwise;
  std::string when;  // an optional argument; the condition applies only when it is given
  Location at;
  friend bool operator==(const ValiditySpec&, const ValiditySpec&) = default;
};

/// Checks on the description: `passes_over` requires a string path to run over the point;
/// `positive` requires an expression argument to be positive where its value is known;
/// `steady_at` requires every strand at the point to keep its direction (a pulley with a
/// radius: the wrapped arc keeps its length only then); `across` (with `to`) requires a vector
/// argument at right angles to another, neither zero (a contact's tangent to its normal).
/// `when`: only when that optional argument is given, or in that many axes (`3-D`).
struct CheckSpec {
  enum class Kind { passes_over, positive, steady_at, across } kind;
  std::string arg;
  Location at;
  std::string when;
  std::string to;  // across: the vector argument `arg` must be at right angles to (both not zero)
  friend bool operator==(const CheckSpec&, const CheckSpec&) = default;
};

/// An assumption the rule stands for, printed in the derivation; `when`: only when that
/// optional argument is given.
struct Assumption {
  std::string text;
  std::string when;
  friend bool operator==(const Assumption&, const Assumption&) = default;
};

struct Rule {
  std::string type;
  std::string summary;
  // `summary: {1-D: ..., 2-D: ..., 3-D: ...}`: the text for a problem with that many axes
  // (index 0..2); empty entries fall back to `summary`.
  std::array<std::string, 3> summary_in;
  [[nodiscard]] const std::string& summary_for(int dims) const {
    return dims >= 1 && dims <= 3 && !summary_in[dims - 1].empty() ? summary_in[dims - 1] : summary;
  }
  // The rule's loads assume the direction the body moves in (sliding friction opposite it):
  // past a turn the model no longer holds (a simulation ends there).
  bool assumes_direction = false;
  // `two_bodies: TYPE`: the rule for the same connection between two moving bodies (a
  // one-body contact placed at a point of another moving body is refused, naming it).
  std::string two_bodies;
  std::vector<RegimeSpec> regimes;  // a connection decided at the numbers (it has no loads of its own)
  // How a mechanism's sketch draws it (`sketch:`): "line" (a string along its path, or a
  // cable between its points), "spring", "damper", "pulley" (a sheave at its point),
  // "support" (its body held by the ground), "arrow" (a force on its body), "contact" (the
  // bodies at its two points drawn touching); in 2-D also "surface" (the ground its body
  // touches at its point, across its first vector, the normal), "pin" (its body pinned to
  // the ground at its point), "joint" (two bodies pinned together), "rod" (a link between
  // its two points), "couple" (an arc on its body); "" when it is not drawn.
  std::string sketch;
  std::vector<ArgSpec> args;
  std::vector<std::vector<std::string>> one_of;  // exactly one argument of each group
  std::vector<UnknownSpec> unknowns;
  std::vector<LoadSpec> loads;
  std::vector<ConstraintSpec> constraints;
  std::vector<ValiditySpec> validity;
  std::vector<CheckSpec> checks;
  std::vector<Assumption> assumptions;
  std::vector<int> dimensions{1, 2, 3};  // numbers of axes the rule is for
  Location at;

  [[nodiscard]] const ArgSpec* arg(const std::string& key) const;
  friend bool operator==(const Rule&, const Rule&) = default;
};

/// A rule file compiled into the program (src/ruleset/embed_rules.cpp writes them at build
/// time from rules/): its name and text, and the rule parse_rule() makes of that text, its
/// locations naming no file. A file with that name and that very text is not read again;
/// any other text (an edited rule, another directory's) is.
struct BuiltinRule {
  std::string_view name;  // the file's name, e.g. "hinge.yaml"
  std::string_view text;
  Rule (*make)();
};

/// The rules by type. A rule file whose type is plain to see (a top-level `type: name` line)
/// is read when a description first uses it: most descriptions use three or four of the 31,
/// and reading YAML was half of a whole run. find() then throws the rule file's problems
/// (InputError). Safe to use from several threads.
class RuleSet {
 public:
  RuleSet() = default;
  RuleSet(const RuleSet& other);
  RuleSet& operator=(const RuleSet& other);
  void add(Rule r);
  /// A rule read when it is first asked for: `text` of `file`, whose type is `type`; made by
  /// `builtin` instead of read when that is the same file compiled in.
  void add_pending(const std::string& type, std::string text, std::string file, const BuiltinRule* builtin = nullptr);
  [[nodiscard]] const Rule* find(const std::string& type) const;
  [[nodiscard]] std::vector<std::string> names() const;
  /// Reads every rule not yet read; all their problems at once (InputError).
  void read_all() const;

 private:
  struct Pending {
    std::string text, file;
    const BuiltinRule* builtin = nullptr;
  };
  mutable std::map<std::string, Rule> rules_;
  mutable std::map<std::string, Pending> pending_;
  mutable std::mutex mutex_;
};

enum class RuleLoading { when_used, all };

/// Reads the `*.yaml` in `dir` (sorted by name): each rule's type at once, the rest when it
/// is used (`when_used`), or everything now (`all`: every problem of every file at once).
/// Two files with one type are an error either way. A file that is one of `builtins` (the
/// same name and text) is made from it when used, not parsed (reading the YAML of three rules
/// was a fifth of a small problem's run).
[[nodiscard]] RuleSet load_rules(const std::string& dir, RuleLoading how = RuleLoading::when_used,
                                 std::span<const BuiltinRule> builtins = {});
/// The rule of a builtin, its locations naming `file`.
[[nodiscard]] Rule made_from(const BuiltinRule& builtin, const std::string& file);
/// One rule from text (tests).
[[nodiscard]] Rule parse_rule(const std::string& text, const std::string& file);

/// The built-in rules directory (set at build time), or $TACKLE_RULES when set.
[[nodiscard]] std::string default_rules_dir();

}  // namespace tackle
