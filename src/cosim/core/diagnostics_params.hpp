// Parameters of the participants' diagnostics common to all of them (config/diagnostics.yaml,
// loaded by the scenario into /scenario/diagnostics): the status period. Each participant's
// warning thresholds are its own, in the `diagnostics:` section of its YAML
// (Participant::readWarningThresholds). SI units.
#pragma once
#include "common/params.hpp"

namespace hbt::cosim::core {

struct DiagnosticsParams {
  double period_s = 1.0;  ///< simulated time between two statuses of a participant [s]

  /// Every key (names = config/diagnostics.yaml).
  void declare(ParamSet& ps);
};

}  // namespace hbt::cosim::core
