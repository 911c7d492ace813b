#include <catch2/catch.hpp>

#include "expr/print.hpp"

using namespace tackle;
using namespace GiNaC;

TEST_CASE("Printer: deterministic textbook order in text and LaTeX", "[print]") {
  const possymbol F("F"), mA("m_A", "m_{A}"), mB("m_B", "m_{B}"), g("g");
  const realsymbol T("T"), a("ddot(x_A)", "\\ddot{x}_{A}");
  const ex e = -9 * F / (9 * mA + 4 * mB);
  CHECK(to_text(e) == "-9*F/(9*m_A + 4*m_B)");
  CHECK(to_latex(e) == "-\\frac{9 F}{9 m_{A} + 4 m_{B}}");
  CHECK(to_text(2 * T - F) == "2*T - F");
  CHECK(to_text(a * mA) == "m_A*ddot(x_A)");
  CHECK(to_latex(a * mA) == "m_{A} \\ddot{x}_{A}");
  CHECK(to_text(-a / 2) == "-ddot(x_A)/2");
  CHECK(to_latex(-a / 2) == "-\\frac{\\ddot{x}_{A}}{2}");
  CHECK(to_text(g * (mA - mB) * -1 / (mA + mB)) == "g*(m_B - m_A)/(m_A + m_B)");
  CHECK(to_text(numeric(-9, 4)) == "-9/4");
  CHECK(to_latex(numeric(-9, 4)) == "-\\frac{9}{4}");
  CHECK(to_text(sqrt(mA * mB)) == "sqrt(m_A*m_B)");
  CHECK(to_latex(pow(mA, 2)) == "m_{A}^{2}");
  CHECK(to_text(pow(mA + mB, -2)) == "1/(m_A + m_B)^2");
}

TEST_CASE("Printer: the same expression prints the same however it was built", "[print]") {
  const possymbol x("x"), y("y"), z("z");
  CHECK(to_text(z + y + x) == to_text(x + y + z));
  CHECK(to_text(z * y * x) == "x*y*z");
}
