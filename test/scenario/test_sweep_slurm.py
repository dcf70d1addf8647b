#!/usr/bin/python3
"""`scripts/twin sweep --slurm` on a real two-node Slurm cluster that this test makes and removes
(test/scenario/slurm_cluster.py): two slurmd, each in a network and UTS namespace of its own (its
own hostname and address, a veth pair to this host), slurmctld and munged on this host, Debian's
slurm-wlm, no cgroups, as root. Both nodes are this machine: they share its file system (the
repository, the sweep's folder), as a real cluster's nodes share one.

The study's sweep (config/sweeps/study.yaml: baseline and hybrid at 0, 25 and 40 degC; here with
the map engine for 20 s) is submitted as a job array, each task asking for a whole node (2 CPUs).
Checks: every task ran under Slurm on the node that Slurm's own job record names (jobcomp), in
that node's namespaces (the hostname the task saw); the tasks are spread over both nodes; the
sweep's table and the study table equal the same sweep run on this machine, every number but the
wall times (determinism); the hybrid's saving is taken against the baseline. The daemons, the
namespaces and the veth pairs are removed at the end, also when a check fails.

Packages: `scripts/twin test` installs slurm-wlm and munge (TEST_PKGS); run alone, the test installs
them itself when it is root. It is skipped (exit 77, a message saying why) only where it cannot:
not root (slurmd must run as root, namespaces need it) and the packages missing or not installable."""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import slurm_cluster

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SKIP = 77  # ctest SKIP_RETURN_CODE
TOOLS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel", "ip", "nsenter", "unshare")
PATH = "/usr/sbin:/usr/bin:/sbin:/bin"
SPEC = os.path.join(REPO, "config", "sweeps", "study.yaml")
ARGS = ["engine:=map", "until:=20"]  # the study's runs, short and with the map engine
RUNS = ["000_baseline_urban_ambient0", "001_baseline_urban_ambient25", "002_baseline_urban_ambient40",
        "003_hybrid_urban_ambient0", "004_hybrid_urban_ambient25", "005_hybrid_urban_ambient40"]


def have_tools():
    return all(shutil.which(t, path=PATH) for t in TOOLS)


def ensure_packages():
    """None when Slurm, munge and the namespace tools are usable, else the reason to skip."""
    if os.geteuid() != 0:
        return "not root: slurmd must run as root to start the sweep's tasks, and the nodes' namespaces need it"
    if have_tools():
        return None
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    for cmd in (["apt-get", "update", "-qq"],
                ["apt-get", "install", "-y", "-q", "--no-install-recommends", "slurm-wlm", "munge", "iproute2",
                 "util-linux"]):
        r = subprocess.run(cmd, env=env, capture_output=True, text=True)
        if r.returncode != 0:
            return "slurm-wlm and munge could not be installed (%s: %s)" % (" ".join(cmd), r.stderr.strip()[-300:])
    return None if have_tools() else "slurm-wlm installed but %s missing" % [t for t in TOOLS if not shutil.which(t, path=PATH)]


def read_csv(path):
    with open(path) as f:
        return {r["run"]: r for r in csv.DictReader(f)}


def read_json(path):
    with open(path) as f:
        return json.load(f)


def study_table(out):
    """The study table (twin_tools.bench.study) of a sweep's folder."""
    from twin_tools.bench import study
    plan = read_json(os.path.join(out, "plan.json"))
    results, _ = study.study_results(plan)
    return study.study_table(results, ["map"], ["on"])


class SlurmSweep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_sweep_slurm_")
        os.chmod(cls.tmp, 0o755)  # munged wants every folder above its socket searchable by all
        cls.addClassCleanup(shutil.rmtree, cls.tmp, True)  # also when setUpClass fails
        cls.cluster = slurm_cluster.Cluster(os.path.join(cls.tmp, "cluster"))
        cls.addClassCleanup(cls.cluster.stop)  # daemons, namespaces, veths: also when start() fails
        try:  # the cluster removed before the checks: test_cluster_removed
            cls.cluster.start()
            cls.node_netns = {n.name: n.netns_inode() for n in cls.cluster.nodes}
            cls.daemon_netns = {name: os.readlink("/proc/%d/ns/net" % p.pid) for name, p in cls.cluster.procs}
            # the sweep as `twin sweep` runs it after its setup (ctest runs after `twin test`'s setup)
            sweep = ["/usr/bin/python3", "-m", "twin_tools.sweep.cli", SPEC]
            env = dict(cls.cluster.env, HBT_SETUP_DONE="1")
            cls.slurm_out, cls.local_out = os.path.join(cls.tmp, "slurm"), os.path.join(cls.tmp, "local")
            t0 = time.time()
            cls.slurm = subprocess.run(sweep + ["--slurm", "--out", cls.slurm_out] + ARGS,
                                       capture_output=True, text=True, timeout=900, env=env)
            cls.slurm_wall_s = time.time() - t0
            cls.jobs_completed = cls.cluster.jobs_completed()
            cls.local = subprocess.run(sweep + ["--out", cls.local_out] + ARGS,
                                       capture_output=True, text=True, timeout=900, env=env)
        finally:
            cls.cluster_logs = cls.cluster.logs()
            cls.cluster.stop()

    def task(self, rid):
        return read_json(os.path.join(self.slurm_out, "runs", rid, "sweep_task.json"))

    def test_array_ran_under_slurm(self):
        self.assertEqual(self.slurm.returncode, 0, self.slurm.stdout + self.slurm.stderr + self.cluster_logs)
        self.assertIn("submitted Slurm job array", self.slurm.stdout)
        job = read_json(os.path.join(self.slurm_out, "timing.json"))["slurm_job"]
        self.assertTrue(job.isdigit())
        with open(os.path.join(self.slurm_out, "slurm", "sweep.sbatch")) as f:
            script = f.read()
        self.assertIn("#SBATCH --array=0-5%2", script)
        self.assertIn("#SBATCH --cpus-per-task=2", script)  # a node per task: the study spec's slurm option
        for k, rid in enumerate(RUNS):
            t = self.task(rid)
            self.assertEqual((t["rc"], t["slurm_job"]), (0, job))
            with open(os.path.join(self.slurm_out, "slurm", "task_%d.out" % k)) as f:
                self.assertIn("sweep: run %s ended with exit status 0" % rid, f.read())
        self.assertIn("sweep (Slurm job %s): 6/6 done" % job, self.slurm.stdout)

    def test_tasks_spread_over_both_nodes(self):
        """Each task ran on the node Slurm's own record names, inside that node's namespaces (the
        hostname it saw is the one set in the node's UTS namespace), and both nodes ran tasks."""
        self.assertEqual(self.slurm.returncode, 0, self.slurm.stdout + self.slurm.stderr + self.cluster_logs)
        job = read_json(os.path.join(self.slurm_out, "timing.json"))["slurm_job"]
        record = {int(j["ArrayTaskId"]): j for j in self.jobs_completed if j.get("ArrayJobId") == job}
        self.assertEqual(sorted(record), list(range(len(RUNS))), self.jobs_completed)
        placed = {}
        for k, rid in enumerate(RUNS):
            t = self.task(rid)
            self.assertEqual(record[k]["JobState"], "COMPLETED", record[k])
            self.assertEqual(t["slurm_node"], record[k]["NodeList"], rid)
            self.assertEqual(t["host"], t["slurm_node"], rid)  # the node's own hostname: its UTS namespace
            placed.setdefault(t["slurm_node"], []).append(rid)
        self.assertEqual(sorted(placed), ["hbtnode1", "hbtnode2"], placed)
        with open(os.path.join(self.slurm_out, "sweep.md")) as f:
            md = f.read()
        for node, rids in placed.items():
            self.assertIn("%s ran %s" % (node, ", ".join(r[:3] for r in rids)), md)
        print("\ntwo-node Slurm sweep: %.0f s wall; %s" % (self.slurm_wall_s, "; ".join(
            "%s ran %s" % (n, ", ".join(r)) for n, r in sorted(placed.items()))), file=sys.stderr)

    def test_daemons_in_their_namespaces(self):
        """Each slurmd ran in its node's network namespace; slurmctld and munged on this host."""
        here = os.readlink("/proc/self/ns/net")
        for n, ino in self.node_netns.items():
            self.assertEqual(self.daemon_netns["slurmd_" + n], "net:[%d]" % ino)
            self.assertNotEqual(self.daemon_netns["slurmd_" + n], here)
        self.assertEqual((self.daemon_netns["slurmctld"], self.daemon_netns["munged"]), (here, here))

    def test_table_equals_summaries_and_local_run(self):
        self.assertEqual(self.local.returncode, 0, self.local.stdout + self.local.stderr)
        slurm, local = read_csv(os.path.join(self.slurm_out, "sweep.csv")), read_csv(os.path.join(self.local_out, "sweep.csv"))
        self.assertEqual(sorted(slurm), RUNS)
        cols = ("sim_time_s", "distance_km", "fuel_kg", "nox_engine_out_g", "nox_tailpipe_g", "soc_final")
        for rid, row in slurm.items():
            s = read_json(os.path.join(self.slurm_out, "runs", rid, "summary.json"))
            self.assertEqual(row["status"], "ok")
            for c in cols:
                if c in s:
                    self.assertEqual(row[c], repr(s[c]), (rid, c))
            # every column bit-identical but the wall time
            self.assertEqual({k: v for k, v in row.items() if k != "wall_s"},
                             {k: v for k, v in local[rid].items() if k != "wall_s"}, rid)
        for amb, (b, h) in zip((0, 25, 40), zip(RUNS[:3], RUNS[3:])):
            self.assertNotEqual(slurm[h]["soc_final"], "")
            bs = read_json(os.path.join(self.slurm_out, "runs", b, "summary.json"))
            hs = read_json(os.path.join(self.slurm_out, "runs", h, "summary.json"))
            f1 = hs.get("fuel_soc_corrected_kg", hs["fuel_kg"])
            self.assertEqual(float(slurm[h]["fuel_saving_pct"]), 100.0 * (bs["fuel_kg"] - f1) / bs["fuel_kg"], amb)
        table = study_table(self.slurm_out)
        self.assertEqual(len(table), 2 + 3)
        self.assertEqual(table, study_table(self.local_out))

    def test_cluster_removed(self):
        self.assertEqual([n for n, _ in self.cluster.stopped], ["slurmd_hbtnode2", "slurmd_hbtnode1", "slurmctld", "munged"])
        for name, pid in self.cluster.stopped:
            with self.assertRaises(ProcessLookupError, msg=name):
                os.kill(pid, 0)
        for n in self.cluster.nodes:
            self.assertEqual(n.exists(), (False, False), n.name)


if __name__ == "__main__":
    why = ensure_packages()
    if why:
        print("SKIPPED test_sweep_slurm: %s" % why)
        sys.exit(SKIP)
    unittest.main(verbosity=2)
