// The oracle's raw material (issue 41, item 2): students' equations and answers made from
// tackle's own derivation equations and closed forms (GiNaC expressions, printed with tackle's
// to_text), changed the ways students change them: rescaled, combined, moved across `=`,
// rewritten with trig identities, substituted, squared, solved for a parameter (meant to be
// true), or with a sign, a term, a mass, a factor or a function wrong (meant to be false).
// What each one is meant to be is only a label: the model (worlds.hpp) decides its truth.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "pipeline/pipeline.hpp"

namespace crosscheck {

struct Diagram;  // diagram.hpp

struct Variant {
  std::string text;                        // the equation ("lhs = rhs"), the answer, or the diagram (YAML)
  std::string family;                      // how it was made ("trig-tan", "sign", ...)
  bool meant = true;                       // made to be true
  std::string unknown;                     // an answer: the unknown it answers
  std::shared_ptr<const Diagram> diagram;  // a diagram: its arrows and the model's forces
};

class Variants {
 public:
  explicit Variants(const tackle::Analysis& a);
  /// One equation of a family drawn at random (nothing when no family applies).
  [[nodiscard]] std::optional<Variant> equation(std::mt19937_64& rng) const;
  /// One answer for a determined unknown, of a family drawn at random.
  [[nodiscard]] std::optional<Variant> answer(std::mt19937_64& rng) const;

  struct Eq {
    GiNaC::ex lhs, rhs;
  };

 private:
  using Maker = std::function<std::optional<Variant>(std::mt19937_64&)>;
  struct Family {
    std::string name;
    bool meant;
    Maker make;
  };
  std::vector<Family> equation_families() const;
  std::vector<Family> answer_families() const;
  static std::optional<Variant> draw(const std::vector<Family>& families, std::mt19937_64& rng);

  // Equations
  std::optional<Eq> balance(std::mt19937_64& rng) const;  // one of the acceleration-level equations
  std::optional<Eq> combined(std::mt19937_64& rng) const;
  std::optional<Eq> substituted(std::mt19937_64& rng) const;
  std::optional<Eq> closed_form(std::mt19937_64& rng) const;
  std::optional<Eq> nonlinear(std::mt19937_64& rng) const;
  std::optional<Eq> solved_for_parameter(std::mt19937_64& rng) const;
  std::optional<Eq> length_sum(std::mt19937_64& rng, bool wrong) const;
  std::optional<Eq> extra_term(std::mt19937_64& rng) const;
  // Answers: an unknown and its closed form
  std::optional<std::pair<std::size_t, GiNaC::ex>> closed(std::mt19937_64& rng) const;
  std::optional<Variant> answer_of(
      std::mt19937_64& rng,
      const std::function<std::optional<GiNaC::ex>(const GiNaC::ex&, std::mt19937_64&)>& change) const;

  /// The dimension of `e` (tackle's table of the symbols' dimensions: raw material only).
  [[nodiscard]] std::optional<tackle::Dimension> dimension(const GiNaC::ex& e) const;
  /// A coefficient that turns an equation of dimension `from` into one of dimension `to`: a
  /// number, or a parameter (times a number) of the ratio's dimension; nothing when none has it.
  [[nodiscard]] std::optional<GiNaC::ex> coefficient(const tackle::Dimension& from, const tackle::Dimension& to,
                                                     std::mt19937_64& rng) const;

  std::shared_ptr<const tackle::SymbolTable> table_;
  std::vector<Eq> balances_, rates_, positions_;
  // Balances the derivation need not print (its `derive:` chooses): each body's and some
  // systems' LMB along each axis, a 2-D body's AMB about its center and about fixed points
  // (tackle's lmb_along and amb_along, raw material like the rest).
  std::vector<Eq> others_;
  void add_other_balances(const tackle::Model& m);
  [[nodiscard]] bool fixed_point(const tackle::Vec& at) const;  // a point no state moves
  std::vector<std::optional<tackle::Dimension>> balance_dimensions_;
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> closed_;  // unknown -> closed form
  std::vector<std::string> closed_names_;
  std::vector<GiNaC::ex> parameters_, masses_, angles_;
  GiNaC::exmap roots_;  // turning strands' lengths -> their definitions (roots)
  GiNaC::ex const_;     // a length sum's constant, written `const`
};

}  // namespace crosscheck
