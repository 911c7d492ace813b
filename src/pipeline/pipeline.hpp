// The derivation of an analysis (analysis/analysis.hpp): the narration, with the described
// sweep's and motion's figures (run in analysis/runs.hpp). The command line, the Python
// module and the tests start here.
#pragma once

#include <vector>

#include "analysis/analysis.hpp"
#include "analysis/runs.hpp"
#include "report/derivation.hpp"

namespace tackle {

/// The derivation, with the described sweep's figure when there is one. A phased analysis
/// gives one derivation per phase (`explain_phases`); `explain` takes a single one.
[[nodiscard]] Derivation explain(const Analysis& a, const ReportOptions& options = {});
[[nodiscard]] std::vector<Derivation> explain_phases(const Analysis& a, const ReportOptions& options = {});

}  // namespace tackle
