"""`scripts/twin bench fmu [--until S] [--pairs N]`: what serving a participant by an FMU costs.

The battery and the e-machine are exported (`scripts/twin fmu export battery|emachine`) and the
full hybrid_urban mission (map engine, nodelets, 25 degC) runs natively, then with both FMUs in
place of the native participants (`battery_fmu:= emachine_fmu:=`, no mapping file), one run after
the other on the same machine (N pairs, alternating; default 1). Measured:

(a) the FMU participant's overhead per base step: the wall time (steady clock) of its step
    outside the FMU's own doStep -- looking up the input messages, converting and setting the
    inputs (fmi2Set*), reading the outputs (fmi2Get*), converting and writing them into its
    messages, and the clock reads that time it:
        mean   = (step_compute_ms_mean_run - fmu_do_step_s / fmu_steps) / (base steps per step)
                 (the participant's final /diagnostics: the mean step() time the lock-step
                 measures for every participant, docs/diagnostics.md; the FMU's doStep time,
                 src/fmi/node/fmu_participant.hpp)
        median = fmu_overhead_us_median / (base steps per step): the typical step, unmoved by
                 the steps another process preempted (src/fmi/step_timing.hpp)
    Publishing the messages is not in it: every participant, native or not, publishes, outside
    its compute time. The two FMU participants step at the base step (0.01 s). Target: <= 2 us
    as nodelets. Beside it, for scale: the FMU's doStep (mean and median per step) and the
    mean step compute time of the FMU participant and of the native participant in the native
    run (input lookups and the model's step).
(b) the mission's wall time with the FMUs against the native run (the stepper's wall_time_s,
    START to the end; the whole `twin run` with the report beside it), target within 10 %, and
    whether both summaries agree: every key of summary.json equal but wall_time_s (the exported
    FMUs step the same model libraries: bit-identical, as ros_fmu_round_trip checks on 600 s).

The machine's load is in the table's header (twin_tools.bench.docs): on a shared machine the
ratio of two runs measured one after the other is what counts, not the absolute times."""
import json
import os
import subprocess
import sys
import time

from twin_tools.paths import REPO
from twin_tools.report.diagnostics import read_diagnostics

MODELS = ("battery", "emachine")
BASE_STEP_S = 0.01  # [s] launch/include/urban.launch step
OVERHEAD_TARGET_US = 2.0   # [us] per base step (issue: the FMU participant, nodelets)
WALL_TARGET_PCT = 10.0     # [%] FMU run's wall time over the native run's
RUN_ARGS = ["mode:=nodelets", "engine:=map", "ambient:=25", "timeout:=10"]


def flatten(d, prefix=""):
    """{"/a/b": leaf} of a JSON value."""
    if isinstance(d, dict):
        out = {}
        for k, v in d.items():
            out.update(flatten(v, prefix + "/" + k))
        return out
    if isinstance(d, list):
        out = {}
        for i, v in enumerate(d):
            out.update(flatten(v, "%s/%d" % (prefix, i)))
        return out
    return {prefix: d}


def summary_differences(a, b):
    """Keys of two summary.json whose values differ (or exist in one only), wall_time_s aside."""
    fa, fb = flatten(a), flatten(b)
    return sorted(k for k in set(fa) | set(fb) if k != "/wall_time_s" and fa.get(k) != fb.get(k))


def export_fmus(root):
    """The FMUs as a user gets them: {model: path}, or None when an export failed."""
    fmus = {}
    for m in MODELS:
        path = os.path.join(root, m + ".fmu")
        r = subprocess.run([os.path.join(REPO, "scripts", "twin"), "fmu", "export", m, "--out", path],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if r.returncode != 0 or not os.path.isfile(path):
            print("bench fmu: twin fmu export %s failed:\n%s" % (m, r.stdout), file=sys.stderr)
            return None
        fmus[m] = path
    return fmus


def run(out, extra, until):
    """One hybrid_urban mission: its summary, status and final diagnostics, or None if it failed."""
    args = list(RUN_ARGS) + extra + (["until:=%g" % until] if until else [])
    t0 = time.time()
    with open(out + ".log", "w") as log:
        rc = subprocess.call([os.path.join(REPO, "scripts", "twin"), "run", "hybrid_urban", "--out", out] + args,
                             stdout=log, stderr=subprocess.STDOUT)
    wall = time.time() - t0
    if rc != 0:
        print("bench fmu: hybrid_urban %s failed (log %s.log)" % (" ".join(extra) or "native", out), file=sys.stderr)
        return None
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "status.json")) as f:
        status = json.load(f)
    return {"summary": summary, "status": status, "process_wall_s": wall,
            "diagnostics": read_diagnostics(os.path.join(out, "run.bag")) or {}}


def participant_costs(r, name):
    """{overhead_us_mean, overhead_us_median (per base step), do_step_us_mean, do_step_us_median
    (per step), compute_us (per step)} of participant `name` in run r; None where the run has no
    such value (a native participant has no FMU)."""
    base_steps = r["summary"]["sim_time_s"] / BASE_STEP_S
    v = r["diagnostics"].get(name, {}).get("values", {})
    steps = float(v.get("steps_total", "0"))
    c = {k: None for k in ("overhead_us_mean", "overhead_us_median", "do_step_us_mean", "do_step_us_median", "compute_us")}
    if steps > 0 and "step_compute_ms_mean_run" in v:
        c["compute_us"] = 1e3 * float(v["step_compute_ms_mean_run"])
    if "fmu_do_step_s" in v and c["compute_us"] is not None:
        per_base = steps / base_steps  # steps per base step (1: the base step is its macro step)
        c["do_step_us_mean"] = 1e6 * float(v["fmu_do_step_s"]) / float(v["fmu_steps"])
        c["do_step_us_median"] = float(v["fmu_do_step_us_median"])
        c["overhead_us_mean"] = (c["compute_us"] - c["do_step_us_mean"]) * per_base
        c["overhead_us_median"] = float(v["fmu_overhead_us_median"]) * per_base
    return c


def fmt(x, f="%.2f"):
    return "-" if x is None else f % x


def tables(pairs, until):
    """The Markdown lines of the bench: (a), (b) and the verdicts; and whether every check passed."""
    md = ["hybrid_urban%s, map engine, nodelets, 25 °C: native, then the battery and the e-machine as the FMUs "
          "`scripts/twin fmu export` makes (`battery_fmu:= emachine_fmu:=`), %d pair(s) run one after the "
          "other. Definitions: python/twin_tools/bench/fmu.py." % (" (first %g s)" % until if until else ", full mission",
                                                                  len(pairs)), "",
          "## (a) The FMU participant's overhead per base step", "",
          "overhead = the FMU participant's step outside the FMU's doStep (input lookups, conversions, fmi2Set/Get, "
          "outputs into its messages): mean = mean step compute time - mean doStep time (per base step), median = "
          "the typical step (robust to preemption on a shared machine); compute = the mean step compute time the "
          "lock-step measures (/diagnostics), of the FMU participant and of the native participant in the native run.", "",
          "| pair | participant | overhead median [us] | overhead mean [us] | FMU doStep median / mean [us] | FMU participant compute [us] | native compute [us] |",
          "|---|---|---|---|---|---|---|"]
    worst_median, worst_mean = 0.0, 0.0
    for i, (native, fmu) in enumerate(pairs):
        for m in MODELS:
            c, n = participant_costs(fmu, m), participant_costs(native, m)
            inf = float("inf")
            worst_median = max(worst_median, inf if c["overhead_us_median"] is None else c["overhead_us_median"])
            worst_mean = max(worst_mean, inf if c["overhead_us_mean"] is None else c["overhead_us_mean"])
            md.append("| %d | %s | %s | %s | %s / %s | %s | %s |" % (
                i + 1, m, fmt(c["overhead_us_median"]), fmt(c["overhead_us_mean"]), fmt(c["do_step_us_median"]),
                fmt(c["do_step_us_mean"]), fmt(c["compute_us"]), fmt(n["compute_us"])))
    md += ["", "## (b) The mission: native against the two FMUs", "",
           "| pair | sim time [s] | wall native [s] | wall FMUs [s] | FMUs / native | twin run native [s] | twin run FMUs [s] | summaries |",
           "|---|---|---|---|---|---|---|---|"]
    ratios, agree = [], True
    for i, (native, fmu) in enumerate(pairs):
        wn, wf = native["summary"]["wall_time_s"], fmu["summary"]["wall_time_s"]
        ratios.append(wf / wn)
        diff = summary_differences(native["summary"], fmu["summary"])
        agree = agree and not diff
        md.append("| %d | %.1f | %.1f | %.1f | %.3f | %.0f | %.0f | %s |" % (
            i + 1, native["summary"]["sim_time_s"], wn, wf, wf / wn, native["process_wall_s"], fmu["process_wall_s"],
            "equal (%d keys but wall_time_s)" % len(flatten(native["summary"])) if not diff
            else "DIFFER: %s" % ", ".join(diff[:8]) + (" ..." if len(diff) > 8 else "")))
    ratio = sorted(ratios)[len(ratios) // 2]  # the median pair
    md += ["", "- overhead per base step: median at most %.2f us, mean at most %.2f us (preempted steps included), "
               "against the target %g us: %s (median), %s (mean)" % (
               worst_median, worst_mean, OVERHEAD_TARGET_US, "met" if worst_median <= OVERHEAD_TARGET_US else "NOT met",
               "met" if worst_mean <= OVERHEAD_TARGET_US else "NOT met"),
           "- mission wall time with the FMUs: %+.1f %% of the native run's (median pair) against the target "
           "%g %%: %s" % (100.0 * (ratio - 1.0), WALL_TARGET_PCT, "met" if ratio <= 1.0 + WALL_TARGET_PCT / 100.0 else "NOT met"),
           "- summaries: %s" % ("every key equal but wall_time_s" if agree else "DIFFER (see the table)")]
    return md, agree


def bench_fmu(a):
    root = os.path.join(REPO, "results", "bench", "fmu")
    os.makedirs(root, exist_ok=True)
    fmus = export_fmus(root)
    if fmus is None:
        return 1
    fmu_args = ["%s_fmu:=%s" % (m, fmus[m]) for m in MODELS]
    pairs = []
    for i in range(max(1, a.pairs)):
        native = run(os.path.join(root, "native_%d" % i), [], a.until)
        fmu = run(os.path.join(root, "fmu_%d" % i), fmu_args, a.until)
        print("bench fmu: pair %d: native %s, FMUs %s" % (i + 1, "ok" if native else "failed", "ok" if fmu else "failed"),
              file=sys.stderr, flush=True)
        if not (native and fmu):
            return 1
        pairs.append((native, fmu))
    md, agree = tables(pairs, a.until)
    print("\n".join(md))
    a.measurement.write("fmu", "FMU participant: overhead per step and the mission with two FMUs", md, bool(a.until))
    with open(os.path.join(REPO, "results", "bench", "fmu.json"), "w") as f:
        json.dump([{"native": {k: n[k] for k in ("summary", "status", "process_wall_s")},
                    "fmu": {k: m[k] for k in ("summary", "status", "process_wall_s")},
                    "costs": {p: participant_costs(m, p) for p in MODELS}} for n, m in pairs], f, indent=1)
    return 0 if agree else 1
