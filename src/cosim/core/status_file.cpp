#include "cosim/core/status_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace hbt::cosim::core {
namespace {
std::string jsonEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') { o += '\\'; o += c; }
    else if (c == '\n') o += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
    else o += c;
  }
  return o;
}
}  // namespace

std::string toJson(const RunStatus& s) {
  std::ostringstream f;
  f << std::setprecision(17);
  f << "{\n  \"status\": \"" << jsonEscape(s.status) << "\",\n  \"message\": \"" << jsonEscape(s.message)
    << "\",\n  \"sim_time_s\": " << s.sim_time_s << ",\n  \"wall_time_s\": " << s.wall_time_s
    << ",\n  \"steps\": " << s.steps << ",\n  \"macro_step_s\": " << s.macro_step_s
    << ",\n  \"compute_time_s\": {";
  bool first = true;
  for (const auto& kv : s.compute_time_s) {
    f << (first ? "" : ",") << "\n    \"" << jsonEscape(kv.first) << "\": " << kv.second;
    first = false;
  }
  f << (first ? "" : "\n  ") << "},\n  \"process_cpu_s\": {";
  first = true;
  for (const auto& p : s.process_cpu) {
    f << (first ? "" : ",") << "\n    \"" << jsonEscape(p.process) << "\": {\"cpu_s\": " << p.cpu_s
      << ", \"cpu_at_start_s\": " << p.cpu_at_start_s << ", \"participants\": [";
    for (std::size_t i = 0; i < p.participants.size(); ++i)
      f << (i ? ", " : "") << "\"" << jsonEscape(p.participants[i]) << "\"";
    f << "]}";
    first = false;
  }
  f << (first ? "" : "\n  ") << "}\n}\n";
  return f.str();
}

std::string statusReserveFile(const std::string& status_file) { return status_file + ".reserve"; }

void reserveStatusSpace(const std::string& status_file) {
  const int fd = ::open(statusReserveFile(status_file).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  (void)::posix_fallocate(fd, 0, kStatusReserve_bytes);
  ::close(fd);
}

std::string writeStatusFile(const std::string& path, const RunStatus& s) {
  ::unlink(statusReserveFile(path).c_str());  // its space is the status file's
  std::ofstream f(path);
  f << toJson(s);
  f.close();
  return f ? "" : std::strerror(errno);
}

bool statusWritten(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && st.st_size > 0;
}

}  // namespace hbt::cosim::core
