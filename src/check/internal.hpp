// What the checker's own files share (check.cpp, decide.cpp, diagnose.cpp): not part of its
// interface.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace tackle::check_detail {

/// `s` without the white space at its ends (typed.cpp).
[[nodiscard]] std::string trim(std::string_view s);

/// "6.8 N" -> ("6.8", "N"); "6.8" -> ("6.8", ""); nothing when the text is not a number,
/// optionally followed by something that starts like a unit (a letter) (numbers.cpp).
[[nodiscard]] std::optional<std::pair<std::string, std::string>> number_and_unit(const std::string& t);

/// abs(), csgn() and step(): a kink, where the argument changes sign.
[[nodiscard]] bool is_kink(const GiNaC::ex& e);
/// The kinks of `e` (each once, in the order met) added to `out`.
void kinks_of(const GiNaC::ex& e, std::vector<GiNaC::ex>& out);
/// A rational function of independent symbols with rational coefficients (a turning strand's
/// length, in `lengths`, is not independent).
[[nodiscard]] bool rational_function(const GiNaC::ex& e, const GiNaC::exmap& lengths);
/// A rational function as a numerator and a denominator, made without gcds.
[[nodiscard]] std::pair<GiNaC::ex, GiNaC::ex> as_fraction(const GiNaC::ex& e);
/// An answer as people type it, in the parser's ASCII (θ -> theta, × -> *, x² -> x^2, √ ->
/// sqrt, ° -> deg); `origin`: for each byte of the result, the input's character it comes from.
[[nodiscard]] std::string as_typed(std::string_view in, std::vector<int>& origin);
/// `30 deg` -> (30*pi/180): a number followed by deg (not part of a longer name), `origin` kept
/// in step.
[[nodiscard]] std::string degrees_as_radians(const std::string& in, std::vector<int>& origin);

}  // namespace tackle::check_detail
