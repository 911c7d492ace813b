// The state every stage of building a Model works on: the description and the rules it is
// built from, the problems found so far, the symbol table, the Model being filled and the
// names claimed in it, with the small helpers the stages share (claiming a name, parsing,
// checking a dimension, reading a vector). Each stage (stages.hpp) fills its own part of
// the Model and reads what the stages before it made; build_model runs them in order.
#pragma once

#include <map>
#include <unordered_set>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "core/diagnostics.hpp"
#include "expr/parse.hpp"
#include "model/model.hpp"
#include "model/path.hpp"

namespace tackle::build {

// Local names of a rule instance (its expression arguments and unknowns) in front of the
// problem's symbol table.
class Scope : public NameResolver {
 public:
  explicit Scope(const SymbolTable& table) : table_(table) {}
  void bind(const std::string& name, GiNaC::ex value) { locals_[name] = std::move(value); }
  std::optional<GiNaC::ex> resolve(std::string_view name) const override {
    if (auto it = locals_.find(std::string(name)); it != locals_.end()) return it->second;
    return table_.resolve(name);
  }
  std::vector<std::string> known_names() const override {
    auto n = table_.known_names();
    for (const auto& [k, v] : locals_) n.push_back(k);
    return n;
  }

 private:
  const SymbolTable& table_;
  std::map<std::string, GiNaC::ex> locals_;
};

// Numbers only: parameter values and layout values may not use names.
inline const NameResolver& none = numbers_only();

// One connection being instantiated from its rule: its arguments resolved, its local
// names bound, its label. The connections stage fills the model from it (its paths are
// made by paths.cpp).
struct Instance {
  const ConnectionDesc& c;
  const Rule& rule;
  std::string what;   // "'string' connection 's'" for messages
  std::string label;  // "string s", "pulley at C", "force on A" for reports
  Scope scope;
  std::map<std::string, int> point_args;              // point / body arguments: the point
  std::map<std::string, int> body_args;               // body arguments: the body
  std::map<std::string, std::vector<int>> path_args;  // points arguments
  std::map<std::string, std::pair<GiNaC::ex, Location>> expr_args;
  std::map<std::string, Vec> vector_args;
  std::map<std::string, std::optional<Path>> paths;  // points arguments as paths, made once
};

// A rule's check that needs every connection, run after all of them.
struct PendingCheck {
  const CheckSpec* check;
  int point;
  Location at;
  std::string what;
};

struct BuildContext {
  BuildContext(const Description& desc, const RuleSet& rs) : d(desc), rules(rs) {}
  const Description& d;
  const RuleSet& rules;
  Diagnostics diags;
  std::shared_ptr<SymbolTable> table = std::make_shared<SymbolTable>();
  Model m;
  std::map<std::string, Location> names_in_use;   // symbol names: parameters, coordinates, unknowns
  std::map<std::string, Location> places_in_use;  // body and point names
  std::map<std::string, int> body_index;
  std::map<std::string, int> point_index;  // bodies are points too
  GiNaC::exmap layout;                     // values for telling strand directions

  // The paths stage's turning strands: their length symbols, one per pair of points
  // (whichever way round), and where they end.
  std::map<std::pair<std::string, std::string>, GiNaC::ex> turning_lengths;
  std::map<int, std::string> turning_at;  // a point at an end of a turning strand: the strand
  // The lengths in m.strand_lengths, expanded: a strand's length is looked up here (comparing
  // it with every one before it was quadratic: 3 G instructions of a chain of 1024 blocks).
  std::unordered_set<GiNaC::ex, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> strand_lengths_expanded;

  // The connections stage's checks that need every connection.
  std::vector<PendingCheck> pending_checks;
  // Points some path runs over (neither end): the first connection to do so, for messages.
  std::map<int, std::pair<std::string, Location>> interior_points;
  bool connection_failed = false;  // some connection's arguments could not be read
  // Every body's coordinate mapped to 0 (made once for all connections, and again if bodies
  // were added since: a map per connection was quadratic in the bodies).
  const GiNaC::exmap& coordinates_at_zero();
  GiNaC::exmap coordinates_at_zero_;
  std::size_t coordinates_at_zero_bodies_ = 0;

  bool claim(const Text& name, const std::string& what) { return claim_in(names_in_use, name, what); }
  bool claim_place(const Text& name, const std::string& what) { return claim_in(places_in_use, name, what); }
  bool claim_in(std::map<std::string, Location>& names_in_use, const Text& name, const std::string& what);

  std::optional<GiNaC::ex> parse(const Text& t, const NameResolver& names, const std::string& what);

  // A number, or an expression in parameters that have values (L/2, 3*T_0): its exact value,
  // or nothing with the problem reported. An expression is checked against `expected`.
  std::optional<GiNaC::ex> number_in_parameters(const Text& t, const std::string& what,
                                                std::optional<Dimension> expected);

  // Reports when `e` does not have dimension `expected`; silent when it cannot tell.
  void check_dimension(const GiNaC::ex& e, const Dimension& expected, const Location& at, const std::string& what);

  // A vector as written: one expression per axis (a bare expression in 1-D). Each entry is
  // checked against `expected` when given (plain numbers are taken in SI).
  std::optional<Vec> vector(const VectorDesc& v, const NameResolver& names, const std::string& what,
                            std::optional<Dimension> expected);

  std::vector<std::string> body_names() const;
  std::vector<std::string> point_names() const;
  // Reports an unknown name of a body, point, ... with the nearest known one.
  void unknown_name(const Text& t, const std::string& kind, const std::vector<std::string>& known);
};

}  // namespace tackle::build
