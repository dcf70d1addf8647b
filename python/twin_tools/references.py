"""The shipped scenarios' full missions and their stored summaries.

Each mission of MISSIONS (baseline_urban and hybrid_urban, map engine, nodelets, the scenario's
defaults, at 0, 25 and 40 degC) runs the whole VECTO Urban mission. Its summary.json, less what
depends on the machine (wall_time_s) and on the last bits of the floating point (balance
closures and residuals, checked by the tests against their own bound), is stored in
test/scenario/reference/missions/<scenario>_<ambient>C.json. The test ros_missions
(test/scenario/test_missions.py) runs the same missions and compares every number with the stored
one within REL_TOL (+ ABS_TOL): a change of the physics shows as a failed comparison naming the
mission, the key and both values.

When a change of the physics is meant to move the results, regenerate the references on purpose
and say in the commit why they moved:

    scripts/twin references --update [--only hybrid_urban_40C,...] [--jobs 2]
    scripts/twin references                   # run and compare only (what the test does)
    scripts/twin references --update --from-runs DIR   # from the runs an earlier --out DIR kept
"""
import argparse
import json
import os
import sys
import tempfile
import threading

from twin_tools.launch import run_util  # the tests' launcher: its own master on a free port
from twin_tools.paths import REPO

REFERENCE_DIR = os.path.join(REPO, "test", "scenario", "reference", "missions")
SCENARIOS = ("baseline_urban", "hybrid_urban")
AMBIENTS_C = (0, 25, 40)
MISSIONS = [(s, a) for s in SCENARIOS for a in AMBIENTS_C]
# what the test suite runs (ros_missions): the two ends of the ambient range, which hold the most
# physics (cold SCR and warm-up inhibit; hot cells and fading assist), within the suite's time;
# 25 degC is stored and checked by `scripts/twin references`
SUITE_AMBIENTS_C = (0, 40)
SUITE_MISSIONS = [(s, a) for s in SCENARIOS for a in SUITE_AMBIENTS_C]
# numbers must agree with the stored ones within REL_TOL of the larger magnitude + ABS_TOL
# (same machine kind and compiler: bit-identical; the tolerance admits another libm or compiler)
REL_TOL = 1e-3
ABS_TOL = 1e-9
# not compared: machine time, and round-off quantities (the tests bound them absolutely)
SKIPPED_KEYS = ("wall_time_s",)
ROUND_OFF_MARKERS = ("closure", "residual")
# the run's wall time without progress before it is aborted [s]: generous, two runs share 2 cores
RUN_TIMEOUT_S = 10.0


def name(scenario, ambient_c):
    return "%s_%dC" % (scenario, ambient_c)


def reference_path(scenario, ambient_c):
    return os.path.join(REFERENCE_DIR, name(scenario, ambient_c) + ".json")


def launch_arguments(ambient_c):
    """The launch arguments of a mission (name -> value)."""
    return {"ambient": ambient_c, "mode": "nodelets", "timeout": RUN_TIMEOUT_S}


def summarise(scenario, ambient_c, out_dir):
    """summary.json of a finished run, written by twin_tools.report.postprocess with the run's launch
    arguments as `twin run` does; returns it."""
    import subprocess
    args = ["%s:=%s" % kv for kv in launch_arguments(ambient_c).items()]
    r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.report.postprocess", out_dir,
                        "--scenario", scenario] + args, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("postprocess of %s failed: %s" % (out_dir, r.stderr))
    with open(os.path.join(out_dir, "summary.json")) as f:
        return json.load(f)


def run_mission(scenario, ambient_c, out_dir):
    """Runs one full mission as nodelets (run_util.run_launch: its own master) and summarises it;
    returns (status, summary or None)."""
    launch = os.path.join(REPO, "launch", scenario + ".launch")
    st = run_util.run_launch(launch, out_dir, timeout_s=900, **launch_arguments(ambient_c))
    if st.get("status") != "ok":
        return st, None
    return st, summarise(scenario, ambient_c, out_dir)


def run_all(missions, root, jobs=2):
    """Runs the missions, `jobs` at a time; returns {name: (out_dir, status, summary)}."""
    waiting = list(missions)
    results, lock = {}, threading.Lock()

    def worker():
        while True:
            with lock:
                if not waiting:
                    return
                scenario, ambient = waiting.pop(0)
            out = os.path.join(root, name(scenario, ambient))
            st, summ = run_mission(scenario, ambient, out)
            with lock:
                results[name(scenario, ambient)] = (out, st, summ)

    threads = [threading.Thread(target=worker) for _ in range(max(1, jobs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return results


def stored_view(summary):
    """What is stored of a summary: everything but the machine time and round-off keys."""
    def keep(k):
        return k not in SKIPPED_KEYS and not any(m in k for m in ROUND_OFF_MARKERS)

    def strip(d):
        return {k: (strip(v) if isinstance(v, dict) else v) for k, v in d.items() if keep(k)}
    return strip(summary)


def _differ(a, b):
    """Whether two stored values differ: numbers beyond the tolerance, anything else at all."""
    if isinstance(a, bool) or isinstance(b, bool) or not (
            isinstance(a, (int, float)) and isinstance(b, (int, float))):
        return a != b
    return abs(a - b) > REL_TOL * max(abs(a), abs(b)) + ABS_TOL


def differences(reference, summary, prefix=""):
    """[(key, stored, now)] of every value of the stored view that differs (_differ), dicts and
    lists (the warnings) element by element; keys missing on either side count."""
    out = []
    now = stored_view(summary) if not prefix else summary
    for k in sorted(set(reference) | set(now)):
        a, b = reference.get(k), now.get(k)
        key = prefix + k
        if isinstance(a, dict) and isinstance(b, dict):
            out += differences(a, b, key + ".")
        elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
            for i, (x, y) in enumerate(zip(a, b)):
                if isinstance(x, dict) and isinstance(y, dict):
                    out += differences(x, y, "%s[%d]." % (key, i))
                elif _differ(x, y):
                    out.append(("%s[%d]" % (key, i), x, y))
        elif _differ(a, b):
            out.append((key, a, b))
    return out


def write_reference(scenario, ambient_c, summary):
    os.makedirs(REFERENCE_DIR, exist_ok=True)
    with open(reference_path(scenario, ambient_c), "w") as f:
        json.dump(stored_view(summary), f, indent=1, sort_keys=True)
        f.write("\n")


def read_reference(scenario, ambient_c):
    with open(reference_path(scenario, ambient_c)) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(prog="twin references", description=__doc__.split("\n\n")[0])
    ap.add_argument("--update", action="store_true", help="write the references from these runs")
    ap.add_argument("--only", default="", help="comma-separated mission names, e.g. hybrid_urban_40C")
    ap.add_argument("--jobs", type=int, default=2, help="missions at a time (default 2)")
    ap.add_argument("--out", default="", help="keep the runs here (default: a temporary folder)")
    ap.add_argument("--from-runs", default="", metavar="DIR",
                    help="do not run: summarise the runs kept in DIR/<mission> by an earlier --out DIR")
    a = ap.parse_args()
    names = {name(s, t): (s, t) for s, t in MISSIONS}
    chosen = [x for x in a.only.split(",") if x]
    bad = [x for x in chosen if x not in names]
    if bad:
        ap.error("--only: unknown mission(s) %s; the missions: %s" % (", ".join(bad), ", ".join(names)))
    missions = [names[x] for x in chosen] if chosen else MISSIONS
    if a.jobs < 1:
        ap.error("--jobs: must be >= 1")
    if a.from_runs:
        root = a.from_runs
        results = {}
        for s, t in missions:
            out = os.path.join(root, name(s, t))
            if not os.path.exists(os.path.join(out, "status.json")):
                ap.error("--from-runs: no run %s (status.json missing)" % out)
            with open(os.path.join(out, "status.json")) as f:
                st = json.load(f)
            results[name(s, t)] = (out, st, summarise(s, t, out) if st.get("status") == "ok" else None)
    else:
        root = a.out or tempfile.mkdtemp(prefix="hbt_missions_")
        results = run_all(missions, root, a.jobs)
    failed = 0
    for s, t in missions:
        out, st, summ = results[name(s, t)]
        if summ is None:
            print("%s: run FAILED: %s (%s)" % (name(s, t), st.get("message"), out))
            failed += 1
            continue
        if a.update:
            write_reference(s, t, summ)
            print("%s: reference written (%s)" % (name(s, t), os.path.relpath(reference_path(s, t), REPO)))
            continue
        diff = differences(read_reference(s, t), summ) if os.path.exists(reference_path(s, t)) else [("(no reference)", None, None)]
        for k, ref, now in diff:
            print("%s: %s stored %s, now %s" % (name(s, t), k, ref, now))
        print("%s: %s" % (name(s, t), "as stored" if not diff else "%d differences" % len(diff)))
        failed += bool(diff)
    print("runs in %s" % root)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
