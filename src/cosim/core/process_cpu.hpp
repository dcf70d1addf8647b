#pragma once
// CPU time of the processes a run is made of (ROS-free). A participant reports its process's CPU
// time (user + system, every thread: the model, the transport's serialisation and its system
// calls) with each status; the stepper sums it per process (the nodelets of one manager share a
// process, so it counts once) and writes it beside compute_time_s in status.json. This is the
// "CPU the participants use" that wall time is compared with in scripts/twin bench map; the
// steady-clock compute_time_s counts only the models' steps.

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hbt::cosim::core {

/// CPU time of this process so far [s] (CLOCK_PROCESS_CPUTIME_ID: a system call, ~2.6 us on the
/// development VM, so read once per status report, never per step).
double processCpuSeconds();
/// This process as "host:pid".
const std::string& processName();

/// What one participant reported of its process.
struct CpuReport {
  std::string process;        // "host:pid"; empty = never reported
  double cpu_s = 0.0;         // CPU time at its last report [s]
  double cpu_at_start_s = 0.0;  // at its READY for the start (set-up done, nothing stepped) [s]
};

/// One process of the run and its CPU time [s].
struct ProcessCpu {
  std::string process;                    // "host:pid"
  std::vector<std::string> participants;  // sorted
  double cpu_s = 0.0;           // the largest (latest) value reported from it
  double cpu_at_start_s = 0.0;  // the largest READY value: its set-up; cpu_s - this = stepping
};

/// What the kernel says of a process (tid = 0) or of one of its threads (/proc/<pid>[/task/<tid>]/stat):
/// its scheduling state ('R' running or runnable, 'S' sleeping, 'D' waiting for a disk, 'T'
/// stopped, ...) and its CPU time (user + system) [s]. known = false: no such process or thread.
struct TaskState {
  bool known = false;
  char state = '?';
  double cpu_s = 0.0;
};
TaskState readTaskState(long pid, long tid = 0);
/// This thread's kernel id (gettid), read once per thread.
long currentThreadId();
/// "host:pid" -> (host, pid); pid 0 if it is not of that form.
std::pair<std::string, long> splitProcessName(const std::string& process);

/// Group the participants' reports (name -> report) by process. A participant that never
/// reported a process is a process of its own named "?:<name>".
std::vector<ProcessCpu> cpuByProcess(const std::map<std::string, CpuReport>& reports);

}  // namespace hbt::cosim::core
