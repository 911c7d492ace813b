#include <catch2/catch.hpp>

#include "core/units.hpp"

using namespace tackle;
using GiNaC::numeric;

namespace {
Unit unit(const std::string& text) {
  std::string err;
  int col = 0;
  auto u = parse_unit(text, err, col);
  INFO(text << ": " << err);
  REQUIRE(u);
  return *u;
}
}  // namespace

TEST_CASE("Units: SI units and prefixes convert exactly", "[units]") {
  CHECK(unit("N").to_si == 1);
  CHECK(unit("kN").to_si == 1000);
  CHECK(unit("g").to_si == numeric(1, 1000));
  CHECK(unit("mm").to_si == numeric(1, 1000));
  CHECK(unit("km/h").to_si == numeric(1000, 3600));
  CHECK(unit("m/s^2").dimension == Dimension::acceleration());
  CHECK(unit("kg*m/s^2").dimension == Dimension::force());
  CHECK(unit("N/m").dimension == Dimension::force() / Dimension::length());
}

TEST_CASE("Units: an unknown unit is located within the text", "[units]") {
  std::string err;
  int col = -1;
  CHECK_FALSE(parse_unit("m/ss^2", err, col));
  CHECK(err == "unknown unit 'ss'");
  CHECK(col == 2);
  CHECK_FALSE(parse_unit("kg*", err, col));
  CHECK(err == "unit ends after an operator");
}

TEST_CASE("Units: a unit's error echoes whole characters and escapes control ones", "[units]") {
  std::string err;
  int col = 0;
  CHECK_FALSE(parse_unit("N\x07", err, col));
  CHECK(err == "unexpected '\\x07' in unit");
  CHECK(col == 1);
  // U+202E (right-to-left override) would reorder the rest of the message.
  CHECK_FALSE(parse_unit("k\u202e", err, col));
  CHECK(err == "unknown unit 'k\\u202E'");
  CHECK_FALSE(parse_unit("k\u00e9", err, col));
  CHECK(err == "unknown unit 'k\u00e9'");
}

TEST_CASE("Units: dimensions are named and given SI units", "[units]") {
  CHECK(Dimension::force().describe() == "force");
  CHECK((Dimension::force() / Dimension::length()).describe() == "stiffness (force per length)");
  CHECK(si_unit_name(Dimension::acceleration()) == "m/s^2");
  CHECK(si_unit_name(Dimension::force()) == "N");
  CHECK(si_unit_name(Dimension::mass().pow(2)) == "kg^2");
  CHECK(unit_latex("m/s^2") == "\\mathrm{m/s^{2}}");
}

TEST_CASE("Units: US customary units convert exactly", "[units]") {
  CHECK(unit("ft").to_si == numeric(3048, 10000));
  CHECK(unit("lbf").to_si == numeric(44482216152605LL, 10000000000000LL));
  CHECK(unit("slug").dimension == Dimension::mass());
  CHECK(unit("slug").to_si == unit("lbf").to_si / unit("ft").to_si);
  CHECK(unit("mph").to_si == numeric(44704, 100000));
  CHECK(unit("ft/s^2").dimension == Dimension::acceleration());
  CHECK(unit("pdl").to_si == unit("lbm").to_si * unit("ft").to_si);
  std::string err;
  int col = 0;
  CHECK_FALSE(parse_unit("klbf", err, col));  // no prefixes on US units
  CHECK(err == "unknown unit 'klbf'");
}

TEST_CASE("Units: an impulse is in N*s, an energy or a work in J (issue 30)", "[units][trust]") {
  // A force times a time: N*s (the same as kg*m/s, the unit of momentum).
  CHECK(tackle::si_unit_name(tackle::Dimension::force() * tackle::Dimension::time()) == "N*s");
  CHECK(tackle::si_unit_name(tackle::Dimension::mass() * tackle::Dimension::velocity()) == "N*s");
  // A moment and an energy share a dimension: N*m by default, J where the quantity is an energy.
  CHECK(tackle::si_unit_name(tackle::Dimension::force() * tackle::Dimension::length()) == "N*m");
  CHECK(tackle::joule().text == "J");
  CHECK(tackle::joule().dimension == tackle::Dimension::force() * tackle::Dimension::length());
  CHECK(GiNaC::ex(tackle::joule().to_si).is_equal(1));
  CHECK(tackle::si_unit_name(tackle::Dimension::force() * tackle::Dimension::velocity()) == "W");
}
