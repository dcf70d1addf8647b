#include "cosim/core/diagnostics_params.hpp"

namespace hbt::cosim::core {

void DiagnosticsParams::declare(ParamSet& ps) {
  ps.add("period_s", period_s, "s", 0.001, 3600.0, "simulated time between two statuses");
}

}  // namespace hbt::cosim::core
