// status.json of a run (docs/outputs.md), ROS-free: written by the stepper at the run's end, by
// the recorder when the stepper fell silent (died or hung), and -- when neither could -- by twin
// (python/twin_tools/launch/lost_status.py, the same keys).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cosim/core/process_cpu.hpp"

namespace hbt::cosim::core {

struct RunStatus {
  std::string status;   // "ok", "error", "interrupted"
  std::string message;  // why the run ended
  double sim_time_s = 0.0;   // simulated time reached [s]
  double wall_time_s = 0.0;  // wall time of the stepping [s]
  uint64_t steps = 0;        // base steps done
  double macro_step_s = 0.0;  // base step [s]
  std::map<std::string, double> compute_time_s;  // participant -> time in its model [s]
  std::vector<ProcessCpu> process_cpu;            // CPU time per process [s]
};

/// The JSON text of `s` (17 significant digits).
std::string toJson(const RunStatus& s);

/// Disk reserved beside the status file (<path>.reserve) at the start of a run and freed just
/// before the status is written, so that the run's end is on record even when the disk filled
/// up meanwhile (the bag is what fills it).
constexpr long kStatusReserve_bytes = 64 * 1024;
std::string statusReserveFile(const std::string& status_file);
/// Allocates the reserve (best effort).
void reserveStatusSpace(const std::string& status_file);
/// Frees the reserve and writes `s` to `path`; "" or what failed (strerror).
std::string writeStatusFile(const std::string& path, const RunStatus& s);
/// True if `path` holds a status already (a non-empty file).
bool statusWritten(const std::string& path);

}  // namespace hbt::cosim::core
