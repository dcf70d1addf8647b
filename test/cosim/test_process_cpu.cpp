// Process CPU accounting of a run (src/cosim/core/process_cpu.hpp): the per-process sums the
// stepper writes to status.json, and the clock they come from.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>

#include "cosim/core/process_cpu.hpp"

using hbt::cosim::core::cpuByProcess;
using hbt::cosim::core::processCpuSeconds;
using hbt::cosim::core::processName;

TEST(ProcessCpu, NodeletsOfOneProcessCountOnce) {
  // a, b: two nodelets of one manager (reports at different times: the latest is the largest);
  // c: a node of its own on another host; d: never reported a process
  const auto p = cpuByProcess({{"a", {"bus:11", 2.0, 0.4}},
                               {"b", {"bus:11", 3.0, 0.3}},
                               {"c", {"rig:11", 1.0, 0.1}},
                               {"d", {"", 0.5, 0.0}}});
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].process, "?:d");
  EXPECT_EQ(p[0].cpu_s, 0.5);
  EXPECT_EQ(p[1].process, "bus:11");
  EXPECT_EQ(p[1].participants, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(p[1].cpu_s, 3.0);
  EXPECT_EQ(p[1].cpu_at_start_s, 0.4);  // the set-up ends with the later READY
  EXPECT_EQ(p[2].process, "rig:11");  // same pid, other host: another process
  EXPECT_EQ(p[2].participants, (std::vector<std::string>{"c"}));
  double total = 0.0;
  for (const auto& q : p) total += q.cpu_s;
  EXPECT_EQ(total, 4.5);  // not 6.5: the shared process once
}

TEST(ProcessCpu, NameIsHostAndPid) {
  const std::string& n = processName();
  const auto colon = n.rfind(':');
  ASSERT_NE(colon, std::string::npos) << n;
  EXPECT_GT(colon, 0u) << n;
  EXPECT_EQ(n.substr(colon + 1), std::to_string(getpid()));
}

TEST(ProcessCpu, ClockCountsBusyWorkAndNotSleep) {
  // busy work: the process clock advances by 50 ms of CPU within a (generous) 20 s of wall time
  const double c0 = processCpuSeconds();
  const auto w0 = std::chrono::steady_clock::now();
  volatile double x = 0.0;
  while (processCpuSeconds() - c0 < 0.05 &&
         std::chrono::steady_clock::now() - w0 < std::chrono::seconds(20))
    for (int i = 0; i < 10000; ++i) x = x + 1e-9 * i;
  const double busy = processCpuSeconds() - c0;
  EXPECT_GE(busy, 0.05);
  // a sleeping process uses (almost) no CPU: 200 ms asleep cost far less than 100 ms
  const double c1 = processCpuSeconds();
  usleep(200000);
  EXPECT_LT(processCpuSeconds() - c1, 0.1);
  EXPECT_GE(processCpuSeconds(), c1);
}

TEST(ProcessCpu, TaskStateOfThisProcessAndThread) {
  // this thread is running while it reads its own state; its CPU time grows with work done
  using hbt::cosim::core::readTaskState;
  const long pid = static_cast<long>(getpid()), tid = hbt::cosim::core::currentThreadId();
  const auto before = readTaskState(pid, tid);
  ASSERT_TRUE(before.known);
  EXPECT_EQ(before.state, 'R');
  volatile double x = 0.0;
  for (long i = 0; i < 200000000L && readTaskState(pid, tid).cpu_s < before.cpu_s + 0.05; ++i) x = x + 1e-9 * i;
  EXPECT_GE(readTaskState(pid, tid).cpu_s, before.cpu_s + 0.05);
  EXPECT_TRUE(readTaskState(pid).known);
  EXPECT_FALSE(readTaskState(999999999L).known);  // beyond any pid_max: no such process
}

TEST(ProcessCpu, SplitProcessName) {
  using hbt::cosim::core::splitProcessName;
  EXPECT_EQ(splitProcessName("vm:1234"), (std::pair<std::string, long>("vm", 1234)));
  EXPECT_EQ(splitProcessName("my:host:42").second, 42);
  EXPECT_EQ(splitProcessName("?:battery").second, 0);
  EXPECT_EQ(splitProcessName("nohost").second, 0);
}
