#!/usr/bin/python3
"""`scripts/twin sweep --slurm` on a real one-node Slurm cluster that this test starts and stops:
munged (its own key and socket), slurmctld and slurmd (Debian's slurm-wlm) in a temporary folder,
on loopback ports, no cgroups, as root. A 2-run sweep (baseline_urban and hybrid_urban, 20 s) is
submitted as a job array; checks: both tasks ran under Slurm (task logs, the job id in every
run's sweep_task.json), the aggregated table equals the runs' summaries, the hybrid's fuel saving
is taken against the baseline, and the same sweep run locally gives identical numbers
(determinism). The daemons are stopped at the end, also when a check fails.

Packages: `scripts/twin test` installs slurm-wlm and munge (TEST_PKGS); run alone, the test installs
them itself when it is root. It is skipped (exit 77, a message saying why) only where it cannot:
not root (slurmd must run as root) and the packages missing or not installable."""
import csv
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SKIP = 77  # ctest SKIP_RETURN_CODE
TOOLS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel")
PATH = "/usr/sbin:/usr/bin:/sbin:/bin"

SPEC = """\
scenarios: [baseline_urban, hybrid_urban]
jobs: 2
fixed: {until: 20, timeout: 10}
vary:
  ambient: [25]
"""


def have_tools():
    return all(shutil.which(t, path=PATH) for t in TOOLS)


def ensure_packages():
    """None when Slurm and munge are usable, else the reason to skip."""
    if os.geteuid() != 0:
        return "not root: slurmd must run as root to start the sweep's tasks"
    if have_tools():
        return None
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    for cmd in (["apt-get", "update", "-qq"],
                ["apt-get", "install", "-y", "-q", "--no-install-recommends", "slurm-wlm", "munge"]):
        r = subprocess.run(cmd, env=env, capture_output=True, text=True)
        if r.returncode != 0:
            return "slurm-wlm and munge could not be installed (%s: %s)" % (" ".join(cmd), r.stderr.strip()[-300:])
    return None if have_tools() else "slurm-wlm installed but %s missing" % [t for t in TOOLS if not shutil.which(t, path=PATH)]


def free_ports(n, lo=23100, hi=23999):
    """n ports free now in [lo, hi) (below the ephemeral range, outside the sweep's ROS ports)."""
    out = []
    for p in range(lo, hi):
        with socket.socket() as s:
            try:
                s.bind(("127.0.0.1", p))
            except OSError:
                continue
        out.append(p)
        if len(out) == n:
            return out
    raise RuntimeError("no free ports in [%d, %d)" % (lo, hi))


def mem_mb():
    with open("/proc/meminfo") as f:
        kb = int(next(l for l in f if l.startswith("MemTotal:")).split()[1])
    return int(kb / 1024 * 0.9)


class Cluster:
    """munged + slurmctld + slurmd in `d`, each a child process of this test."""

    def __init__(self, d):
        self.d, self.procs, self.stopped = d, [], []
        for sub in ("munge", "state", "spool", "log"):
            os.makedirs(os.path.join(d, sub), exist_ok=True)
        os.chmod(d, 0o755)
        os.chmod(os.path.join(d, "munge"), 0o755)
        self.key = os.path.join(d, "munge", "munge.key")
        with open(self.key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(self.key, 0o400)
        self.socket = os.path.join(d, "munge", "munge.socket")
        ctld, slurmd = free_ports(2)
        self.conf = os.path.join(d, "slurm.conf")
        with open(self.conf, "w") as f:
            f.write("\n".join([
                "ClusterName=hbtsweep",
                "SlurmctldHost=localhost(127.0.0.1)",
                "SlurmctldPort=%d" % ctld,
                "SlurmdPort=%d" % slurmd,
                "AuthType=auth/munge",
                "CredType=cred/munge",
                "AuthInfo=socket=%s" % self.socket,
                "SlurmUser=root",
                "SlurmdUser=root",
                "StateSaveLocation=%s/state" % d,
                "SlurmdSpoolDir=%s/spool" % d,
                "SlurmctldPidFile=%s/slurmctld.pid" % d,
                "SlurmdPidFile=%s/slurmd.pid" % d,
                "SlurmctldLogFile=%s/log/slurmctld.log" % d,
                "SlurmdLogFile=%s/log/slurmd.log" % d,
                "ProctrackType=proctrack/linuxproc",
                "TaskPlugin=task/none",
                "SwitchType=switch/none",
                "MpiDefault=none",
                "SelectType=select/cons_tres",
                "SelectTypeParameters=CR_CPU",
                "AccountingStorageType=accounting_storage/none",
                "JobAcctGatherType=jobacct_gather/none",
                "JobCompType=jobcomp/none",
                "ReturnToService=2",
                "MinJobAge=30",
                "NodeName=hbtnode NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=%d RealMemory=%d State=UNKNOWN"
                % (os.cpu_count(), mem_mb()),
                "PartitionName=hbt Nodes=hbtnode Default=YES MaxTime=INFINITE State=UP",
                ""]))
        self.env = dict(os.environ, SLURM_CONF=self.conf)

    def _start(self, name, cmd):
        log = open(os.path.join(self.d, "log", name + ".out"), "w")
        p = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=self.env, start_new_session=True)
        log.close()  # the daemon holds its own copy
        self.procs.append((name, p))
        return p

    def start(self):
        m = os.path.join(self.d, "munge")
        self._start("munged", ["munged", "-F", "--key-file=" + self.key, "--socket=" + self.socket,
                               "--pid-file=%s/munged.pid" % m, "--log-file=%s/munged.log" % m,
                               "--seed-file=%s/munged.seed" % m])
        self._wait(lambda: os.path.exists(self.socket), "munged socket")
        self._start("slurmctld", ["slurmctld", "-D", "-i", "-f", self.conf])
        self._start("slurmd", ["slurmd", "-D", "-N", "hbtnode", "-f", self.conf])
        self._wait(lambda: subprocess.run(["sinfo", "-h", "-o", "%T"], env=self.env, capture_output=True,
                                          text=True).stdout.strip() == "idle", "node hbtnode idle")

    def _wait(self, ok, what, timeout_s=60):
        t0 = time.time()
        while time.time() - t0 < timeout_s:
            for name, p in self.procs:
                if p.poll() is not None:
                    raise RuntimeError("%s exited (%d) while waiting for %s: %s" % (name, p.returncode, what, self.logs()))
            if ok():
                return
            time.sleep(0.5)
        raise RuntimeError("timeout waiting for %s: %s" % (what, self.logs()))

    def logs(self):
        out = []
        for f in sorted(os.listdir(os.path.join(self.d, "log"))):
            with open(os.path.join(self.d, "log", f), errors="replace") as fh:
                out.append("--- %s\n%s" % (f, fh.read()[-2000:]))
        return "\n".join(out)

    def stop(self):
        for name, p in reversed(self.procs):  # slurmd, slurmctld, munged
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
            self.stopped.append((name, p.pid))
        self.procs = []


def read_csv(path):
    with open(path) as f:
        return {r["run"]: r for r in csv.DictReader(f)}


class SlurmSweep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_sweep_slurm_")
        os.chmod(cls.tmp, 0o755)  # munged wants every folder above its socket searchable by all
        cls.addClassCleanup(shutil.rmtree, cls.tmp, True)  # also when setUpClass fails
        cls.cluster = Cluster(os.path.join(cls.tmp, "cluster"))
        cls.addClassCleanup(cls.cluster.stop)
        try:  # the daemons stopped before the checks: test_daemons_stopped
            cls.cluster.start()
            spec = os.path.join(cls.tmp, "tiny.yaml")
            with open(spec, "w") as f:
                f.write(SPEC)
            # the sweep as `twin sweep` runs it after its setup (ctest runs after `twin test`'s setup)
            sweep = ["/usr/bin/python3", "-m", "twin_tools.sweep.cli", spec]
            env = dict(cls.cluster.env, HBT_SETUP_DONE="1")
            cls.slurm_out, cls.local_out = os.path.join(cls.tmp, "slurm"), os.path.join(cls.tmp, "local")
            cls.slurm = subprocess.run(sweep + ["--slurm", "--out", cls.slurm_out],
                                       capture_output=True, text=True, timeout=900, env=env)
            cls.local = subprocess.run(sweep + ["--out", cls.local_out],
                                       capture_output=True, text=True, timeout=900, env=env)
        finally:
            cls.cluster_logs = cls.cluster.logs()
            cls.cluster.stop()

    def test_array_ran_under_slurm(self):
        self.assertEqual(self.slurm.returncode, 0, self.slurm.stdout + self.slurm.stderr + self.cluster_logs)
        self.assertIn("submitted Slurm job array", self.slurm.stdout)
        with open(os.path.join(self.slurm_out, "timing.json")) as f:
            job = json.load(f)["slurm_job"]
        self.assertTrue(job.isdigit())
        with open(os.path.join(self.slurm_out, "slurm", "sweep.sbatch")) as f:
            self.assertIn("#SBATCH --array=0-1%2", f.read())
        for k, rid in enumerate(("000_baseline_urban", "001_hybrid_urban")):
            with open(os.path.join(self.slurm_out, "runs", rid, "sweep_task.json")) as f:
                t = json.load(f)
            self.assertEqual((t["rc"], t["slurm_job"]), (0, job))
            with open(os.path.join(self.slurm_out, "slurm", "task_%d.out" % k)) as f:
                self.assertIn("sweep: run %s ended with exit status 0" % rid, f.read())
        self.assertIn("sweep (Slurm job %s): 2/2 done" % job, self.slurm.stdout)

    def test_table_equals_summaries_and_local_run(self):
        self.assertEqual(self.local.returncode, 0, self.local.stdout + self.local.stderr)
        slurm, local = read_csv(os.path.join(self.slurm_out, "sweep.csv")), read_csv(os.path.join(self.local_out, "sweep.csv"))
        self.assertEqual(sorted(slurm), ["000_baseline_urban", "001_hybrid_urban"])
        cols = ("sim_time_s", "distance_km", "fuel_kg", "nox_engine_out_g", "nox_tailpipe_g", "soc_final")
        for rid, row in slurm.items():
            with open(os.path.join(self.slurm_out, "runs", rid, "summary.json")) as f:
                s = json.load(f)
            self.assertEqual(row["status"], "ok")
            for c in cols:
                if c in s:
                    self.assertEqual(row[c], repr(s[c]), (rid, c))
                self.assertEqual(row[c], local[rid][c], (rid, c))  # bit-identical numbers
        self.assertNotEqual(slurm["001_hybrid_urban"]["soc_final"], "")
        h = slurm["001_hybrid_urban"]
        with open(os.path.join(self.slurm_out, "runs", "000_baseline_urban", "summary.json")) as f:
            b = json.load(f)
        with open(os.path.join(self.slurm_out, "runs", "001_hybrid_urban", "summary.json")) as f:
            hs = json.load(f)
        f1 = hs.get("fuel_soc_corrected_kg", hs["fuel_kg"])
        self.assertEqual(float(h["fuel_saving_pct"]), 100.0 * (b["fuel_kg"] - f1) / b["fuel_kg"])
        self.assertEqual(h["fuel_saving_pct"], local["001_hybrid_urban"]["fuel_saving_pct"])

    def test_daemons_stopped(self):
        self.assertEqual([n for n, _ in self.cluster.stopped], ["slurmd", "slurmctld", "munged"])
        for name, pid in self.cluster.stopped:
            with self.assertRaises(ProcessLookupError, msg=name):
                os.kill(pid, 0)


if __name__ == "__main__":
    why = ensure_packages()
    if why:
        print("SKIPPED test_sweep_slurm: %s" % why)
        sys.exit(SKIP)
    unittest.main(verbosity=2)
