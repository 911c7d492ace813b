// Checking answers: is a student's answer for an unknown right, and if not, why not, in
// terms a student can act on. Answers are hostile input: they are bounded (length, tokens,
// nesting, exponents, number sizes) before any GiNaC object exists, and every check runs
// within a size and time budget. A Checker is prepared once per problem and then checks any
// number of answers; it never changes after construction.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <ginac/ginac.h>

#include "algebra/program.hpp"
#include "algebra/states.hpp"
#include "core/limits.hpp"
#include "core/units.hpp"
#include "analysis/analysis.hpp"

namespace tackle {

/// Limits for a typed answer: tighter than for a description.
[[nodiscard]] ExprLimits answer_limits();

struct CheckOptions {
  ExprLimits limits = answer_limits();
  double relative_tolerance = 0.01;            // numbers with units
  std::optional<int> significant_figures;      // instead of the tolerance: match to N figures
  bool require_simplified = false;             // a correct but unsimplified answer is incorrect
  std::size_t exact_size_budget = 2000;        // largest expanded size normal() is given
  std::chrono::milliseconds time_budget{250};  // per answer
  int points = 4;                              // fixed random points: the first comparison and the diagnoses
  // Points a verdict of `correct` rests on when no proof decides it are drawn at random, from
  // a generator seeded from std::random_device once per process and drawn again every 64
  // checks of an unknown, so that no answer can be built to vanish at them; a seed makes them
  // reproducible (tests, `tackle check --seed`), and must never be used to grade.
  std::optional<std::uint64_t> seed;
  int digits = 40;         // precision of the numeric comparison (CLN)
  bool echo_latex = true;  // echo the answer as read in LaTeX too
  // Feedback names the correct value ("expected 35.316 N within 1 %") only when asked: a
  // grader's results go to students, who would see the answer after one try.
  bool reveal = false;
};

/// An upper bound on the number of terms `e` expands into (normal() or expand()).
[[nodiscard]] double expanded_size(const GiNaC::ex& e);

enum class Verdict { correct, incorrect, invalid, undecided };
[[nodiscard]] std::string verdict_name(Verdict v);

/// One thing found about an answer: a code for machines, a sentence for students.
/// Codes: unknown_name, syntax, too_large, not_an_answer, wrong_unknown, no_unit, unit,
/// dimension, sign, factor, other_unknown, swapped, special_case, extra_parameter,
/// missing_parameter, trig_swapped, term_sign, missing_term, extra_term, value, not_simplified,
/// tolerance, budget, evaluation, internal (an item that made tackle fail: undecided), time_limit
/// (a worked solution's step not checked: its time limit was past). Equations (check/equation.hpp)
/// also: not_an_equation, trivial, not_linear, model, points, missing_force, force_sign,
/// extra_force, missing_inertia, inertia_sign, wrong_mass, wrong_acceleration, length_sum. Free
/// body diagrams (check/fbd.hpp): missing_force,
/// force_direction, wrong_point, extra_force, other_body, internal_force.
struct Finding {
  std::string code;
  std::string message;
};

struct CheckResult {
  std::string unknown;
  Verdict verdict = Verdict::undecided;
  std::string summary;  // the first thing to tell the student
  std::vector<Finding> findings;
  std::string method;     // exact, numeric, number (with unit), or empty
  std::string echo_text;  // the answer as tackle read it
  std::string echo_latex;
  double score = 0.0;
  // An equation checked (check_equation): the derivation's equations it is (up to a non-zero
  // factor), or that it follows from; a correct one names them.
  bool equation = false;
  std::vector<std::string> identified_as, follows_from;
  // A correct equation as a combination of the model's equations (those of follows_from):
  // each one's label and whether its coefficient is a plain number, the same for every value
  // of the parameters (up to a factor common to all). All plain: the student wrote a sum of
  // those equations (a system's balance is its bodies' balances added); any not plain: the
  // equation was derived from them by eliminating unknowns (an answer restated).
  struct Part {
    std::string label;
    bool plain = false;
  };
  std::vector<Part> combination;

  /// Sets the verdict and its summary, the finding too when there is a code; the score follows
  /// the verdict (1 when correct, else 0).
  CheckResult& conclude(Verdict v, std::string code, std::string message);
};

/// What checks settled about answers' expressions, remembered by the expression (per unknown;
/// an equation's by its two sides, under "="): 2*m*g/4 and m*g/2 are one expression once read,
/// and a class types the same few answers in many spellings. An entry is the result as far as
/// the spelling does not matter (see Checker::settle) and, once made, the answer's simplest form.
/// Bounded: at `capacity`
/// entries it starts again empty. Safe from threads.
class SettledAnswers {
 public:
  struct Entry {
    CheckResult result;
    std::optional<std::string> simplest;
  };
  static constexpr std::size_t capacity = 4096;
  [[nodiscard]] std::optional<Entry> find(const std::string& unknown, const GiNaC::ex& e) const;
  void keep(const std::string& unknown, const GiNaC::ex& e, const Entry& entry);
  /// The kept simplest form of `e`, made by `make` (and kept, where `e` has an entry) when
  /// there is none.
  [[nodiscard]] std::string simplest(const std::string& unknown, const GiNaC::ex& e,
                                     const std::function<std::string()>& make);

 private:
  using Entries = std::unordered_map<GiNaC::ex, Entry, std::hash<GiNaC::ex>, GiNaC::ex_is_equal>;
  mutable std::mutex mutex_;
  std::map<std::string, Entries, std::less<>> by_unknown_;
  std::size_t size_ = 0;
};

class EquationChecker;

class Checker {
 public:
  Checker(const Analysis& analysis, CheckOptions options = {});

  /// Checks `answer` for the unknown `unknown` (a name such as `T_HI` or `ddot(x_A)`).
  /// `values`: the student's own numbers (a variant), from values_for(); a number answered
  /// is compared with the closed form there. Never throws for any text (but out of memory):
  /// what goes wrong inside is the verdict undecided, code `internal`, with the reason.
  [[nodiscard]] CheckResult check(const std::string& unknown, std::string_view answer,
                                  const GiNaC::exmap* values = nullptr) const;
  /// The parameters' values (SI) with `set` (name -> number in the parameter's stated unit)
  /// put in, the defined parameters following; nothing, and `problem` says why, for a name
  /// that is not a parameter with a value or a text that is not a number (a usage error), or
  /// for a value a positive parameter (a mass, a length...) cannot have (`out_of_domain` set:
  /// an input error).
  [[nodiscard]] std::optional<GiNaC::exmap> values_for(const std::vector<std::pair<std::string, std::string>>& set,
                                                       std::string& problem, bool* out_of_domain = nullptr) const;
  /// Checks an equation the student wrote ("2*T - F = m_A*ddot(x_A)"): correct when it holds in
  /// every state the model allows (see check/equation.hpp). Never throws, as check().
  [[nodiscard]] CheckResult check_equation(std::string_view equation) const;
  /// The unknowns the problem asks for (`find`) that can be checked, in its order.
  [[nodiscard]] const std::vector<std::string>& asked() const { return asked_; }
  /// The fewest of the derivation's equations that determine `unknown` (see
  /// EquationChecker::needed_for); empty for a name that is not an unknown of the equations.
  [[nodiscard]] std::vector<std::string> needed_for(const std::string& unknown) const;
  /// The derivation's equation with this label, or null.
  [[nodiscard]] const Equation* derivation_equation(const std::string& label) const;
  /// A length sum's equation differentiated twice ("string s: acceleration" for "length of
  /// string s"); empty for another label.
  [[nodiscard]] std::string differentiated(const std::string& label) const;
  /// The names that can be checked (determined unknowns and defined quantities).
  [[nodiscard]] std::vector<std::string> unknowns() const;
  [[nodiscard]] const CheckOptions& options() const { return options_; }

 private:
  // What deciding an equality with an expression needs to know of it.
  struct Shape {
    bool rational = false;              // a rational function of independent symbols
    double size = 0;                    // an upper bound on its expansion's terms
    std::optional<GiNaC::ex> expanded;  // a rational one's expansion, made once
  };
  struct Reference {
    std::string name;
    GiNaC::ex closed_form;
    Program program;  // the closed form, made once
    std::optional<Dimension> dimension;
    std::optional<GiNaC::numeric> value;    // SI, when every parameter has a value
    std::vector<GiNaC::numeric> at_points;  // the closed form at each random point
    std::size_t text_size = 0;              // length of its printed closed form
    Shape shape;
    std::vector<GiNaC::ex> kinks;  // its abs() and csgn()
    // What diagnosing a wrong answer needs of the reference alone, made when first wanted
    // (once per batch, not per answer).
    struct Diagnosis {
      GiNaC::ex expanded;                             // the closed form expanded
      std::set<GiNaC::ex, GiNaC::ex_is_less> needed;  // its parameters
      // As c times powers of coprime factors (see Factored in check.cpp), when it is one.
      std::optional<std::pair<GiNaC::numeric, std::map<GiNaC::ex, int, GiNaC::ex_is_less>>> factored;
      // At the first point with each of its parameters doubled in turn (in the points' order).
      std::vector<std::optional<GiNaC::numeric>> doubled;
      // The closed form with one term's sign turned, or one term left out: at each point.
      std::vector<std::vector<std::optional<GiNaC::numeric>>> term_turned, term_left_out;
      // At each point with a parameter at zero (by its place in parameters_), and with two
      // parameters of one dimension equal.
      std::map<std::size_t, std::vector<std::optional<GiNaC::numeric>>> zeroed;
      std::map<std::pair<std::size_t, std::size_t>, std::vector<std::optional<GiNaC::numeric>>> equalled;
    };
    // The points a verdict of `correct` rests on beyond the fixed ones (see FreshPoints):
    // drawn from the reference's own generator, where the reference is defined, with its
    // values there. With a seed, drawn once (every check had the same ones); without, drawn
    // again every `fresh_renewal` checks, the generator seeded once from std::random_device.
    struct Fresh {
      std::optional<std::mt19937> rng;
      std::vector<Sample> points;
      std::vector<GiNaC::numeric> values;  // the reference at each point
      int uses = 0;
    };
    struct Lazy {
      std::once_flag made;
      Diagnosis diagnosis;
      std::mutex fresh_mutex;
      Fresh fresh;
    };
    std::shared_ptr<Lazy> lazy = std::make_shared<Lazy>();
  };
  struct Parameter {
    std::string name;
    GiNaC::ex symbol;
    std::optional<Dimension> dimension;
  };

  // What a comparison beyond the fixed points found: a proof either way (normal()), the same
  // or different values at the points drawn for this check, or nothing to go on.
  enum class Agreement { proved, refuted, agrees, differs, unevaluable, budget };
  // The points for one check (unpredictable unless options_.seed is set), where the
  // reference is defined, and the reference's values there: the reference's pool (see
  // Reference::Fresh), taken when first wanted. Drawing them for each check (seeding a
  // generator from the device, the points, the reference at each) was 40 % of the check of a
  // correct answer.
  class FreshPoints {
   public:
    explicit FreshPoints(const Checker& checker, const Reference& ref) : checker_(checker), ref_(ref) {}
    const std::vector<Sample>& get();
    /// The reference's closed form at get()'s k-th point.
    [[nodiscard]] const GiNaC::numeric& reference_at(std::size_t k) const { return values_[k]; }
    [[nodiscard]] const Reference& reference() const { return ref_; }

   private:
    const Checker& checker_;
    const Reference& ref_;
    std::optional<std::vector<Sample>> points_;
    std::vector<GiNaC::numeric> values_;
  };
  // How many checks one unseeded pool of fresh points serves before it is drawn again.
  static constexpr int fresh_renewal = 64;
  // A verdict reached beyond the fixed points.
  struct Decision {
    Verdict verdict = Verdict::undecided;
    std::string method;
    std::string code, message;  // the finding (or the summary of a correct answer)
  };

  CheckResult check_answer(const std::string& unknown, std::string_view answer, const GiNaC::exmap* values) const;
  CheckResult check_number(const Reference& ref, std::string_view number, std::string_view unit_text, CheckResult r,
                           const GiNaC::exmap* values) const;
  CheckResult check_expression(const Reference& ref, std::string_view text, CheckResult r,
                               std::chrono::steady_clock::time_point start,
                               const std::function<int(int)>& column) const;
  /// What the answer's expression settles whatever its spelling (see SettledAnswers): its
  /// echo, dimension, values, then the decision or the diagnosis.
  CheckResult settle(const Reference& ref, const GiNaC::ex& answer, CheckResult r,
                     const std::function<bool()>& over_budget) const;
  /// A correct answer typed much longer than its simplest form: a finding (incorrect with
  /// require_simplified).
  void note_simplified(const Reference& ref, const GiNaC::ex& answer, std::string_view text, CheckResult& r) const;
  /// A wrong answer's findings, in terms a student can act on (see Diagnosing in diagnose.cpp).
  void diagnose(const Reference& ref, const GiNaC::ex& answer, const Program& answer_at,
                const std::vector<GiNaC::numeric>& values, CheckResult& r) const;
  struct Diagnosing;
  // The quotient answer/reference as the values show it: a product of powers of the
  // parameters (c p^e q^f..., exponents up to 4) when it is one, and how many parameters it
  // depends on. None when the values are not all exact.
  struct QuotientShape {
    std::optional<GiNaC::ex> monomial;
    int depends_on = 0;
  };
  [[nodiscard]] std::optional<QuotientShape> quotient_shape(const Reference& ref, const Program& answer_at,
                                                            const std::vector<GiNaC::numeric>& values) const;
  /// The reference's part of every diagnosis (made once, on first use; safe from threads).
  [[nodiscard]] const Reference::Diagnosis& diagnosis(const Reference& ref) const;
  /// The answer (its definitions put in), which agrees with the reference at every fixed
  /// point, decided: proved or refuted by normal() where GiNaC can, else at fresh points (and
  /// for abs(), on each side of every kink).
  [[nodiscard]] Decision decide(const Reference& ref, const GiNaC::ex& answer,
                                const std::function<bool()>& over_budget) const;
  /// A correct answer's decision: proved, or agreeing at the points (exactly or not).
  [[nodiscard]] Decision correct_decision(bool proved, bool exact_values) const;
  /// The decision for an answer or a reference with kinks (abs(), csgn(), step()).
  [[nodiscard]] Decision decide_across_kinks(const Reference& ref, const GiNaC::ex& answer,
                                             const std::vector<GiNaC::ex>& kinks, FreshPoints& fresh,
                                             const std::function<bool()>& over_budget) const;
  /// Incorrect where a state on a side of the kinks where they differ is found (see decide.cpp).
  [[nodiscard]] std::optional<Decision> differing_side(const Reference& ref, const GiNaC::ex& answer,
                                                       const std::vector<GiNaC::ex>& args,
                                                       const std::vector<std::size_t>& differing,
                                                       const std::function<bool()>& over_budget) const;
  [[nodiscard]] Agreement compare(const GiNaC::ex& answer, const GiNaC::ex& reference, const Program& reference_at,
                                  const Shape& shape, FreshPoints& fresh, const std::function<bool()>& over_budget,
                                  bool& exact_values) const;
  /// A point near the parameters' values drawn from `rng`, finer than the fixed points.
  [[nodiscard]] Sample draw_point(std::mt19937& rng) const;
  /// `e` made into code for the points, every defined parameter put in (the turning strands'
  /// lengths too).
  [[nodiscard]] Program program(const GiNaC::ex& e) const;
  void extend_points();
  /// The fixed points: the first of the states drawn with a fixed seed that the model's
  /// stated conditions allow (all the first ones when too few do).
  void choose_fixed_points(const Analysis& analysis);
  /// Whether the model's stated conditions (their closed forms) hold at `p`; true where one
  /// cannot be evaluated.
  [[nodiscard]] bool allowed(const Sample& p) const;
  /// Whether the conditions leave out every state where `argument` has this sign (negative or
  /// not): a condition that is `argument` times a number, and says the other sign.
  [[nodiscard]] bool excluded(const GiNaC::ex& argument, bool negative) const;
  /// Whether `e` is negative, where its sign is known whatever the point (a number times
  /// powers of parameters, which are positive); none where it is not.
  [[nodiscard]] std::optional<bool> negative_factor(const GiNaC::ex& e) const;
  bool same(const GiNaC::numeric& a, const GiNaC::numeric& b) const;
  std::string describe(const GiNaC::ex& parameter) const;

  CheckOptions options_;
  std::shared_ptr<const SymbolTable> symbols_;
  std::vector<Parameter> parameters_;                           // names an answer may use
  std::map<std::string, GiNaC::ex, std::less<>> answer_names_;  // the same, by name
  std::vector<std::string> problem_unknowns_;
  GiNaC::exmap definitions_;  // defined parameters, expanded before comparing
  GiNaC::exmap lengths_;      // the turning strands' lengths too: for numbers only
  // The states answers are compared at (algebra/states.hpp): each parameter, and the value
  // points are drawn near (an angle's: its tan(angle/2)); the fixed points.
  States states_;
  std::vector<Sample> points_;
  // The model's stated conditions in closed form (`expr op 0`, op's sign: +1 for >= and >,
  // -1 for <= and <): a state where one fails is not one the model allows, and no answer is
  // compared there. Empty when they fail at most fixed points (near the given numbers).
  struct StatedCondition {
    GiNaC::ex form;  // its closed form, definitions put in
    Program at;
    int sign;
  };
  std::vector<StatedCondition> conditions_;
  // The points with each defined parameter's value added (l = sqrt(b^2 + d^2 + e^2) at the
  // point), its layout's angles: a diagnosis swaps a defined parameter's value there rather
  // than substitute the answer anew for each pair. Empty when a definition has no value.
  std::vector<Sample> extended_points_;
  std::vector<std::vector<double>> point_doubles_, extended_doubles_;  // the same in doubles
  std::vector<bool> extended_angles_;
  GiNaC::numeric tolerance_;  // relative, for values that are not exact: 10^-(digits - 8)
  std::map<std::string, Reference, std::less<>> references_;
  std::shared_ptr<const EquationChecker> equations_;
  std::vector<std::string> asked_;
  std::shared_ptr<SettledAnswers> settled_ = std::make_shared<SettledAnswers>();
};

}  // namespace tackle
