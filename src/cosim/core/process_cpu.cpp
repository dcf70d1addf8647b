#include "cosim/core/process_cpu.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>

namespace hbt::cosim::core {

double processCpuSeconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return 0.0;
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

const std::string& processName() {
  static const std::string name = [] {
    char host[256] = {0};
    if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
    return std::string(host[0] ? host : "localhost") + ":" + std::to_string(getpid());
  }();
  return name;
}

std::vector<ProcessCpu> cpuByProcess(const std::map<std::string, CpuReport>& reports) {
  std::map<std::string, ProcessCpu> by;
  for (const auto& kv : reports) {
    const std::string proc = kv.second.process.empty() ? "?:" + kv.first : kv.second.process;
    ProcessCpu& p = by[proc];
    p.process = proc;
    p.participants.push_back(kv.first);  // the map is sorted by name: so is this list
    p.cpu_s = std::max(p.cpu_s, kv.second.cpu_s);
    p.cpu_at_start_s = std::max(p.cpu_at_start_s, kv.second.cpu_at_start_s);
  }
  std::vector<ProcessCpu> out;
  for (auto& kv : by) out.push_back(std::move(kv.second));
  return out;
}

}  // namespace hbt::cosim::core
