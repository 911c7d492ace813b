#include <catch2/catch.hpp>

#include "expr/print.hpp"
#include "isolate/isolate.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {
std::map<std::string, Isolation> isolate_all(const std::string& example) {
  const Model m = build_model(read_description(TACKLE_SOURCE_DIR "/examples/" + example), test::rules());
  const auto candidates = candidate_equations(m);
  std::map<std::string, Isolation> out;
  for (const auto& u : model_unknowns(m)) out[to_text(u)] = isolate(m, candidates, u);
  return out;
}
}  // namespace

TEST_CASE("Isolate: AMB about axis OG gives the sign-board's rod tension alone", "[isolate]") {
  const auto r = isolate_all("sample-12.8-sign-board.yaml");
  const Isolation& t = r.at("T_HI");
  REQUIRE(t.equation);
  CHECK(t.equation->label == "AMB board about G (axis OG, along y)");
  CHECK(to_text(*t.value) == "a*m*sqrt(b^2 + d^2 + e^2)/(2*d)");
}

TEST_CASE("Isolate: O_y and G_y of sample 12.9 cannot be had from any one equation", "[isolate]") {
  const auto r = isolate_all("sample-12.9-indeterminate.yaml");
  for (const char* name : {"O_y", "G_y"}) {
    INFO(name);
    CHECK_FALSE(r.at(name).equation);
    CHECK(r.at(name).impossible);
  }
  for (const char* name : {"O_x", "O_z", "G_x", "G_z", "T_HI"}) {
    INFO(name);
    CHECK(r.at(name).equation);
  }
  CHECK(to_text(*r.at("G_z").value) == "m*(a*c + d*g - a*e)/(2*d)");
}

TEST_CASE("Isolate: every suitcase unknown has its own equation, about a point the book does not name", "[isolate]") {
  const auto r = isolate_all("sample-12.7-suitcase.yaml");
  CHECK(r.at("a_C").equation->label == "LMB suitcase (along [1, mu])");
  CHECK(to_text(*r.at("a_C").value) == "-g*mu");
  CHECK(r.at("N_B").equation->label == "AMB suitcase about the point [-h*mu, h] (z)");
  CHECK(to_text(*r.at("N_B").value) == "g*m*(2*h*mu + l)/(2*l)");
  CHECK(to_text(*r.at("N_A").value) == "g*m*(l - 2*h*mu)/(2*l)");
}

TEST_CASE("Isolate: in 1-D the search covers each body's LMB and the constraints", "[isolate]") {
  const auto r = isolate_all("figure-12.5d-motion-doubled.yaml");
  REQUIRE(r.at("T").equation);
  CHECK(r.at("T").equation->label == "LMB B (x)");
  CHECK(to_text(*r.at("T").value) == "F/2");
  CHECK_FALSE(r.at("ddot(x_B)").equation);
  CHECK_FALSE(r.at("ddot(x_B)").impossible);  // 1-D: only the listed equations were tried
}
