#include "cosim/core/process_cpu.hpp"

#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

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

TaskState readTaskState(long pid, long tid) {
  TaskState t;
  const std::string path = "/proc/" + std::to_string(pid) + (tid > 0 ? "/task/" + std::to_string(tid) : "") + "/stat";
  std::ifstream f(path);
  std::string text;
  if (!f || !std::getline(f, text)) return t;
  // "pid (comm) S ppid ...": the name may hold spaces and parentheses; the fields follow the last ')'
  const std::size_t close = text.rfind(')');
  if (close == std::string::npos) return t;
  std::istringstream in(text.substr(close + 1));
  std::string field;
  std::vector<std::string> f3;  // state is field 3, utime 14, stime 15 (proc(5)): here 0, 11, 12
  while (in >> field && f3.size() < 13) f3.push_back(field);
  if (f3.size() < 13 || f3[0].empty()) return t;
  const double tick_s = 1.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
  t.known = true;
  t.state = f3[0][0];
  t.cpu_s = (std::strtod(f3[11].c_str(), nullptr) + std::strtod(f3[12].c_str(), nullptr)) * tick_s;
  return t;
}

long currentThreadId() {
  thread_local const long tid = static_cast<long>(syscall(SYS_gettid));
  return tid;
}

std::pair<std::string, long> splitProcessName(const std::string& process) {
  const std::size_t colon = process.rfind(':');
  if (colon == std::string::npos) return {process, 0};
  char* end = nullptr;
  const long pid = std::strtol(process.c_str() + colon + 1, &end, 10);
  return {process.substr(0, colon), (end && *end == '\0' && pid > 0) ? pid : 0};
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
