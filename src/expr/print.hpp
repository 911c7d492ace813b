// Print contexts for tackle's output. Expressions are printed only through these contexts
// (registered GiNaC print functions), never by string surgery. They fix the order of terms
// and factors so that output is identical from run to run (GiNaC's own order depends on
// hash values that can change between runs): numbers first in products, then factors
// sorted by name; positive terms first in sums, each group sorted by name.
//
//   tackle_text  : GiNaC input syntax (`-9*F/(9*m_A+4*m_B)`), parseable back by tackle.
//   tackle_latex : textbook LaTeX (`-\frac{9 F}{9 m_{A} + 4 m_{B}}`), symbols by TeX name.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <ginac/ginac.h>

namespace tackle {

class tackle_text : public GiNaC::print_dflt {
  GINAC_DECLARE_PRINT_CONTEXT(tackle_text, GiNaC::print_dflt)
 public:
  explicit tackle_text(std::ostream& os, unsigned opt = 0) : GiNaC::print_dflt(os, opt) {}
};

class tackle_latex : public GiNaC::print_latex {
  GINAC_DECLARE_PRINT_CONTEXT(tackle_latex, GiNaC::print_latex)
 public:
  explicit tackle_latex(std::ostream& os, unsigned opt = 0) : GiNaC::print_latex(os, opt) {}
};

/// A printed term's shape and index: the text with each index (digits in a name) written as
/// its offset from the first, and the first index (m_12*ddot(x_12) -> "m_#0*ddot(x_#0)", 12).
/// Terms of one shape whose indices go up by one make a run, which LaTeX and the reports'
/// lists write with dots. Nothing when the text has no index.
[[nodiscard]] std::optional<std::pair<std::string, long>> index_shape(const std::string& text);

/// The order a person writes a product's factors in, for LaTeX (m a, mu N_A, m g): a rank per
/// factor, lower first; equal ranks keep the name order. Text keeps the name order.
using FactorRank = std::function<int(const GiNaC::ex& factor)>;
/// Installs a rank for LaTeX printing on this thread while it lives.
class PersonOrder {
 public:
  explicit PersonOrder(FactorRank rank);
  ~PersonOrder();
  PersonOrder(const PersonOrder&) = delete;
  PersonOrder& operator=(const PersonOrder&) = delete;

 private:
  FactorRank rank_;
  const FactorRank* previous_;
};

[[nodiscard]] std::string to_text(const GiNaC::ex& e);
[[nodiscard]] std::string to_latex(const GiNaC::ex& e);
/// Both at once (the sort keys are worked out once for the two).
[[nodiscard]] std::pair<std::string, std::string> to_text_and_latex(const GiNaC::ex& e);

}  // namespace tackle
