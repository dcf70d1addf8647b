"""scripts/twin bench soak [--runs 20] [--jobs 4] [--until S]: many full map-engine missions in a
row, several at a time, to show that runs survive load and that nothing grows from one mission to
the next. The matrix is both scenarios x ambients x payloads (SOAK_AMBIENTS_C, SOAK_PAYLOADS_KG),
the scenarios alternating, cut to --runs. Each run is a `twin run` (nodelets: one manager process
holds every participant, the stepper and the recorder) on its own master port. While it runs, the
resident memory of its manager (VmRSS of /proc/<pid>/status, [MiB]) is sampled every second.

Per run: status, wall time, whether a timeout ended it (a participant starved of CPU taken for
dead: "did not answer", "no participant progressed", "start-up timed out"), whether every number
of its summary.json is finite, the manager's RSS and its anonymous part (RssAnon: heap, stacks,
mapped memory the process itself allocated; RSS adds file-backed pages of the shared libraries,
which come and go with the page cache) at the first sample after a fifth of the manager's sampled
life (the simulation; `twin run` then writes the report, which can take longer than the mission
on a loaded machine) and at its last sample, the peak RSS (VmHWM), and the high-water mark of the bag
writer's queue (the recorder's final diagnostics, bag_queue_high_water_kib: the most memory the
messages waiting for run.bag's writer thread held at once; bounded by its budget,
src/cosim/bag_writer.hpp).

Verdict lines: failed runs, false timeouts, non-finite summaries, and memory growth, per scenario:
- within a mission: late - early RssAnon beyond the bag queue's high-water mark. A writer thread
  starved of CPU lets its queue fill up to the budget once; the heap keeps those pages after the
  queue drains (glibc keeps freed chunks in its arena), so a step of up to the high-water mark is
  the bounded buffer, not a leak;
- from the first mission to the last: the least-squares line of the late RssAnon over the mission
  index, its rise over the soak.
Flat: both within RSS_FLAT_PCT of the scenario's mean late RssAnon."""
import json
import math
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

from twin_tools.launch import ports
from twin_tools.launch.manager_watch import manager_pid
from twin_tools.paths import REPO
from twin_tools.report.diagnostics import read_diagnostics

SOAK_AMBIENTS_C = (0, 10, 25, 32, 40)  # [degC]
SOAK_PAYLOADS_KG = (500, 3000)         # [kg]: near empty, and about 40 standing passengers
RSS_FLAT_PCT = 5.0   # [%] allowed memory growth (within a mission; first to last, fitted)
SAMPLE_PERIOD_S = 1.0  # [s] wall
TIMEOUT_WORDS = ("did not answer", "no participant progressed", "start-up timed out")


def matrix(n_runs):
    runs = []
    for payload in SOAK_PAYLOADS_KG:
        for ambient in SOAK_AMBIENTS_C:
            for scenario in ("baseline_urban", "hybrid_urban"):
                runs.append((scenario, ambient, payload))
    return runs[:n_runs]


def memory_mib(pid):
    """(VmRSS, RssAnon, VmHWM) of process pid [MiB], or None once it is gone."""
    vals = {}
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith(("VmRSS:", "RssAnon:", "VmHWM:")):
                    key, kb = line.split()[:2]
                    vals[key[:-1]] = int(kb) / 1024.0
    except OSError:
        return None
    return (vals.get("VmRSS"), vals.get("RssAnon"), vals.get("VmHWM")) if "VmRSS" in vals else None


def fitted_rise(values):
    """Rise of the least-squares line through values[i] at i = 0..n-1 from the first to the last
    index (same unit as values), or None for fewer than 2 values."""
    n = len(values)
    if n < 2:
        return None
    mx, my = (n - 1) / 2.0, sum(values) / n
    sxx = sum((i - mx) ** 2 for i in range(n))
    slope = sum((i - mx) * (y - my) for i, y in enumerate(values)) / sxx
    return slope * (n - 1)


def steady_samples(samples):
    """[(rss, anon)] of the samples [(t, rss, anon)] from a fifth of the sampled span on (the
    manager's start-up left out), in order; [] for no samples."""
    if not samples:
        return []
    t_first, t_last = samples[0][0], samples[-1][0]
    return [(rss, anon) for t, rss, anon in samples if t >= t_first + 0.2 * (t_last - t_first)]


def finite_numbers(obj):
    """True if every number in a JSON value is finite."""
    if isinstance(obj, dict):
        return all(finite_numbers(v) for v in obj.values())
    if isinstance(obj, list):
        return all(finite_numbers(v) for v in obj)
    if isinstance(obj, float):
        return math.isfinite(obj)
    return True


def run_one(index, scenario, ambient, payload, root, until):
    out = os.path.join(root, "%02d_%s_%dC_%dkg" % (index, scenario, ambient, payload))
    port, lock = ports.reserve_port(index)
    args = [os.path.join(REPO, "scripts", "twin"), "run", scenario, "--out", out, "mode:=nodelets",
            "engine:=map", "ambient:=%g" % ambient, "payload:=%g" % payload]
    if until:
        args.append("until:=%g" % until)
    env = dict(os.environ, HBT_SETUP_DONE="1", HBT_ROS_PORT=str(port))
    samples, pid, peak = [], None, 0.0
    t0 = time.time()
    with open(out + ".log", "w") as log:
        proc = subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT, env=env)
        while proc.poll() is None:
            time.sleep(SAMPLE_PERIOD_S)
            if pid is None:
                pid = manager_pid(port)
            m = memory_mib(pid) if pid else None
            if m:
                samples.append((time.time() - t0, m[0], m[1]))
                peak = max(peak, m[2] or 0.0)
    wall = time.time() - t0
    os.close(lock)
    row = {"run": os.path.basename(out), "scenario": scenario, "ambient_c": ambient, "payload_kg": payload,
           "rc": proc.returncode, "wall_s": wall, "samples": len(samples), "rss_peak_mib": peak}
    try:
        with open(os.path.join(out, "status.json")) as f:
            st = json.load(f)
        row["status"], row["message"] = st.get("status"), st.get("message", "")
        row["sim_time_s"] = st.get("sim_time_s")
    except (OSError, ValueError) as e:
        row["status"], row["message"] = "no status", str(e)
    try:
        with open(os.path.join(out, "summary.json")) as f:
            row["summary_finite"] = finite_numbers(json.load(f))
    except (OSError, ValueError):
        row["summary_finite"] = None
    row["timeout"] = any(w in row.get("message", "") for w in TIMEOUT_WORDS)
    row["bag_queue_high_water_mib"] = bag_queue_high_water_mib(out)
    steady = steady_samples(samples)
    row["rss_early_mib"], row["anon_early_mib"] = steady[0] if steady else (None, None)
    row["rss_late_mib"], row["anon_late_mib"] = steady[-1] if steady else (None, None)
    return row


def bag_queue_high_water_mib(run_dir):
    """The recorder's bag_queue_high_water_kib of the run in run_dir [MiB], or None (no diagnostics)."""
    try:
        nodes = read_diagnostics(os.path.join(run_dir, "run.bag"))
        return float(nodes["recorder"]["values"]["bag_queue_high_water_kib"]) / 1024.0
    except Exception:  # no or unreadable diagnostics.bag, no recorder status: no allowance
        return None


def memory_verdict(rows):
    """(verdict lines, flat) of the runs' memory: per scenario, the largest rise of RssAnon within a
    mission beyond that mission's bag queue high-water mark (None: no allowance), and the fitted
    rise of the late RssAnon from the first mission to the last, both against RSS_FLAT_PCT of the
    scenario's mean late RssAnon."""
    lines, flat = [], True
    for scenario in ("baseline_urban", "hybrid_urban"):
        mine = [r for r in rows if r["scenario"] == scenario and r.get("anon_late_mib") and r.get("anon_early_mib")]
        if not mine:
            continue
        mean = sum(r["anon_late_mib"] for r in mine) / len(mine)
        within = max(r["anon_late_mib"] - r["anon_early_mib"] for r in mine)
        queue = lambda r: r.get("bag_queue_high_water_mib") or 0.0
        beyond = max(r["anon_late_mib"] - r["anon_early_mib"] - queue(r) for r in mine)
        rise = fitted_rise([r["anon_late_mib"] for r in mine])
        ok = 100.0 * beyond / mean <= RSS_FLAT_PCT and (rise is None or 100.0 * rise / mean <= RSS_FLAT_PCT)
        flat = flat and ok
        lines.append("- %s, %d missions: RssAnon late %.1f MiB (mean; %.1f in the first mission, %.1f in the "
                     "last); largest rise within a mission %+.2f MiB, beyond the bag queue's high-water mark "
                     "(at most %.2f MiB) %+.2f MiB (%+.1f %%); fitted rise from the first mission to the last %s: "
                     "%s (within %g %% of the mean)" % (
                         scenario, len(mine), mean, mine[0]["anon_late_mib"], mine[-1]["anon_late_mib"], within,
                         max(queue(r) for r in mine), beyond, 100.0 * beyond / mean,
                         "-" if rise is None else "%+.2f MiB (%+.1f %%)" % (rise, 100.0 * rise / mean),
                         "flat" if ok else "GROWS", RSS_FLAT_PCT))
    return lines, flat


def bench_soak(a):
    root = os.path.join(REPO, "results", "bench", "soak")
    os.makedirs(root, exist_ok=True)
    runs = matrix(a.runs)
    jobs = max(1, a.jobs)
    print("soak: %d missions, %d at a time, on %d CPUs" % (len(runs), jobs, os.cpu_count() or 0), file=sys.stderr)
    t0 = time.time()
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(run_one, i, s, amb, p, root, a.until) for i, (s, amb, p) in enumerate(runs)]
        rows = []
        for f in futures:
            rows.append(f.result())
            r = rows[-1]
            print("soak: %s %s (%.0f s wall)" % (r["run"], r["status"], r["wall_s"]), file=sys.stderr)
    total = time.time() - t0
    fmt = lambda v, f="%.1f": "-" if v is None else f % v
    md = ["Full map-engine missions (%s), both scenarios alternating, ambients %s °C, payloads %s kg; %d at a "
          "time (nodelets), each on its own master. RSS: the nodelet manager's resident memory [MiB] (one "
          "process: every participant, the stepper, the recorder) and its anonymous part RssAnon (what the process "
          "allocated itself; RSS adds shared-library pages that come and go with the page cache), at the first "
          "sample after a fifth of the manager's sampled life (early) and at its last sample (late); peak = VmHWM; bag queue "
          "high-water: the most the messages waiting for run.bag's writer thread held at once (the recorder's "
          "diagnostics; budget 4 MiB). Total wall time %.0f s."
          % ("first %g s" % a.until if a.until else "whole Urban cycle", ", ".join(map(str, SOAK_AMBIENTS_C)),
             ", ".join(map(str, SOAK_PAYLOADS_KG)), jobs, total), "",
          "| run | status | wall [s] | timeout | summary finite | RSS early / late [MiB] | RssAnon early / late "
          "[MiB] | peak [MiB] | bag queue high-water [MiB] |",
          "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append("| %s | %s | %.0f | %s | %s | %s / %s | %s / %s | %s | %s |" % (
            r["run"], r["status"], r["wall_s"], "yes" if r["timeout"] else "no",
            {True: "yes", False: "NO", None: "-"}[r["summary_finite"]],
            fmt(r["rss_early_mib"]), fmt(r["rss_late_mib"]), fmt(r.get("anon_early_mib")),
            fmt(r.get("anon_late_mib")), fmt(r["rss_peak_mib"]), fmt(r.get("bag_queue_high_water_mib"), "%.2f")))
    failed = [r for r in rows if r["status"] != "ok"]
    timeouts = [r for r in rows if r["timeout"]]
    not_finite = [r for r in rows if r["summary_finite"] is not True]
    md += ["", "- failed runs: %d of %d%s" % (len(failed), len(rows), "".join(
        "\n  - %s: %s" % (r["run"], r["message"]) for r in failed)),
        "- runs ended by a timeout: %d" % len(timeouts),
        "- summaries with a non-finite number (or none): %d" % len(not_finite)]
    lines, flat = memory_verdict(rows)
    md += lines
    print("\n".join(md))
    a.measurement.write("soak", "Soak: %d full missions, %d at a time" % (len(rows), jobs), md,
                        bool(a.until) or a.runs < 20)
    with open(os.path.join(root, "soak.json"), "w") as f:
        json.dump(rows, f, indent=2)
    return 0 if not failed and not timeouts and not not_finite and flat else 1
