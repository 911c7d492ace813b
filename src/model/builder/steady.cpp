// A steady motion whose rate is unknown (`steady:`): the rate's square is an unknown of the
// solve (the balances are linear in it: m omega^2 r), the rate's name reads as its root
// wherever the description writes it (omega is sqrt(omega^2)), and the rate and its period
// are reported. A real rate needs omega^2 >= 0: a validity condition.
#include "model/builder/stages.hpp"

namespace tackle::build {

using namespace GiNaC;

namespace {

Unit radians_per_second() { return Unit{1, Dimension::time().pow(-1), "rad/s"}; }

// The unit the rate is reported in (rad/s unless said): a rate's, or nothing (reported).
std::optional<Unit> rate_unit(BuildContext& ctx, const SteadyDesc& st) {
  if (!st.unit) return radians_per_second();
  std::string err;
  int col = 0;
  auto unit = parse_unit(st.unit->text, err, col);
  if (!unit) {
    ctx.diags.error(st.unit->at.shifted(col), "'unit' of 'steady': " + err);
    return std::nullopt;
  }
  if (!(unit->dimension == Dimension::time().pow(-1))) {
    ctx.diags.error(st.unit->at, "'unit' of 'steady' is " + with_article(unit->dimension.describe()) +
                                     " (expected a rate, such as rad/s or rpm)");
    return std::nullopt;
  }
  return unit;
}

}  // namespace

void steady(BuildContext& ctx) {
  if (!ctx.d.steady || ctx.d.steady->rate.text.empty()) return;  // (no rate: reported when read)
  const SteadyDesc& st = *ctx.d.steady;
  const Text period = st.period ? *st.period : Text{"tau", st.at};
  // (A unit that is not a rate is reported; the rate is made all the same, in rad/s, so that
  // the expressions written in it raise no second error.)
  const auto unit = rate_unit(ctx, st).value_or(radians_per_second());
  if (!ctx.claim(st.rate, "steady rate") || !ctx.claim(period, "period")) return;
  const Dimension rate = unit.dimension;
  const std::string tex = default_tex(st.rate.text);
  const SymbolInfo& squared =
      ctx.table->add(st.rate.text + "^2", "{" + tex + "^{2}}", SymbolRole::unknown, rate.pow(2), false, st.rate.at);
  ctx.table->set_alias(st.rate.text, sqrt(squared.sym));
  const SymbolInfo& root = ctx.table->add(st.rate.text, tex, SymbolRole::defined, rate, false, st.rate.at);
  const SymbolInfo& tau =
      ctx.table->add(period.text, std::nullopt, SymbolRole::defined, Dimension::time(), false, period.at);
  SteadySpec spec{root.name, tau.name, squared.sym, {}};
  spec.reported.push_back({root.name, root.tex, sqrt(squared.sym), true, rate, unit});
  spec.reported.push_back({tau.name, tau.tex, 2 * Pi / sqrt(squared.sym), true, Dimension::time(), std::nullopt});
  ctx.m.conditions.push_back(
      {squared.sym, 0, ">=", "the rate is real", "no real rate keeps this motion steady", "steady motion"});
  ctx.m.steady = std::move(spec);
}

}  // namespace tackle::build
