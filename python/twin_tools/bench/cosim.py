"""`scripts/twin bench cosim`: the lock-step protocol alone.

N probe participants (src/cosim/probe_participant.hpp: no model; each reads the previous one's
output, the first reads the last: a ring) under the master stepper, without recorder, in a
generated launch file, for N = 3, 5, 8, as nodes (one process each, TCP) and as nodelets (one
manager, one lock-step thread), in three variants:
  jacobi      one group, everyone at the base step (each reads the others' previous step)
  multirate   one group, every second probe at 10 base steps (cosim/macro_step_s = 10 dt)
  ordered     N groups [[p0], [p1], ...]: each probe reads its predecessor's fresh output, so
              within a base step they step one after the other (the longest chain)
Measured: base steps per second of simulated stepping (the stepper's status.json: steps /
wall_time_s, START to the end) and the participants' compute time (steady clock inside their steps). The full missions are `twin bench map`
(baseline, nodes and nodelets) and `twin bench hybrid`.
"""
import json
import os
import subprocess
import sys

from twin_tools.launch import ports

DT_S = 0.01
FULL_STEPS = 200000  # base steps per nodelets run of the full benchmark (the default of --steps)


def launch_xml(n, mode, variant, out, until_s):
    names = ["p%d" % i for i in range(n)]
    order = "[%s]" % ", ".join("[%s]" % p for p in names) if variant == "ordered" else ""
    nodelets = mode == "nodelets"
    x = ['<launch>', '  <param name="/use_sim_time" value="true" />']
    if nodelets:
        x.append('  <node pkg="nodelet" type="nodelet" name="twin_manager" args="manager" required="true"'
                 ' output="screen"><param name="num_worker_threads" value="1" /></node>')

    def node(name, node_type, plugin, body, required=False):
        how = ('pkg="nodelet" type="nodelet" args="load %s /twin_manager --no-bond"' % plugin if nodelets
               else 'pkg="hybrid_bus_twin" type="%s"' % node_type)
        remap = ('<remap from="/use_sim_time" to="/twin/nodelet_loader_use_sim_time" />' if nodelets else "")
        x.append('  <node %s name="%s"%s output="screen" clear_params="true">%s%s</node>'
                 % (how, name, ' required="true"' if required else "", remap, body))

    node("stepper", "stepper", "hybrid_bus_twin/Stepper",
         '<rosparam param="participants">[%s]</rosparam><param name="dt_s" value="%g" />'
         '<param name="until_s" value="%g" /><param name="timeout_s" value="10.0" />'
         '<param name="status_file" value="%s/status.json" /><param name="progress" value="false" />%s'
         % (", ".join(names), DT_S, until_s, out,
            '<rosparam param="order">%s</rosparam>' % order if order else ""), required=True)
    for i, p in enumerate(names):
        prev = names[i - 1]
        rate = ('<param name="cosim/macro_step_s" value="%g" />' % (10 * DT_S)
                if variant == "multirate" and i % 2 == 1 else "")
        node(p, "probe_participant", "hybrid_bus_twin/Probe",
             '<rosparam param="inputs">[/%s/out]</rosparam><param name="output" value="/%s/out" />%s'
             % (prev, p, rate))
    x.append("</launch>")
    return "\n".join(x) + "\n"


def run_one(root, n, mode, variant, steps):
    out = os.path.join(root, "%s_%s_%d" % (mode, variant, n))
    os.makedirs(out, exist_ok=True)
    status = os.path.join(out, "status.json")
    if os.path.exists(status):
        os.remove(status)
    launch = os.path.join(out, "probe.launch")
    with open(launch, "w") as f:
        f.write(launch_xml(n, mode, variant, out, steps * DT_S))
    port, lock = ports.reserve_port(n)
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_IP="127.0.0.1",
               ROS_HOME=out)
    with open(os.path.join(out, "roslaunch.log"), "w") as log:
        subprocess.call(["roslaunch", "--no-summary", "-p", str(port), launch], env=env,
                        stdout=log, stderr=subprocess.STDOUT, timeout=900)
    os.close(lock)
    if not os.path.exists(status):
        return None
    with open(status) as f:
        st = json.load(f)
    if st.get("status") != "ok":
        return None
    return {"steps": st["steps"], "wall_s": st["wall_time_s"],
            "steps_per_s": st["steps"] / st["wall_time_s"],
            "compute_s": sum(st.get("compute_time_s", {}).values())}


def bench_cosim(a, repo):
    root = os.path.join(repo, "results", "bench", "cosim")
    steps = int(a.steps)
    rows = []
    for mode in ("nodelets", "nodes"):
        for variant in ("jacobi", "multirate", "ordered"):
            for n in (3, 5, 8):
                r = run_one(root, n, mode, variant, steps if mode == "nodelets" else max(steps // 4, 1000))
                rows.append((mode, variant, n, r))
                print("bench cosim: %-8s %-9s N=%d  %s" % (mode, variant, n, "failed" if r is None else
                      "%8.0f base steps/s" % r["steps_per_s"]), file=sys.stderr, flush=True)
    md = ["The lock-step protocol alone: N probe participants (no model) in a ring under the master stepper, "
          "no recorder; %d base steps of %g s per nodelets run, %d per nodes run. jacobi: one group at the "
          "base step; multirate: every second probe at 10 base steps; ordered: one Gauss-Seidel group per "
          "probe (the longest chain)." % (steps, DT_S, max(steps // 4, 1000)), "",
          "| mode | variant | participants | base steps | wall [s] | base steps/s | participants' compute time / wall |",
          "|---|---|---|---|---|---|---|"]
    for mode, variant, n, r in rows:
        if r is None:
            md.append("| %s | %s | %d | failed (see results/bench/cosim/%s_%s_%d/roslaunch.log) | | | |"
                      % (mode, variant, n, mode, variant, n))
        else:
            md.append("| %s | %s | %d | %d | %.2f | %.0f | %.2f |" % (mode, variant, n, r["steps"], r["wall_s"],
                                                                   r["steps_per_s"], r["compute_s"] / r["wall_s"]))
    print("\n" + "\n".join(md))
    a.measurement.write("cosim", "The lock-step protocol alone: base steps per second", md, steps < FULL_STEPS)
    with open(os.path.join(repo, "results", "bench", "cosim.json"), "w") as fh:
        json.dump([{"mode": m, "variant": v, "participants": n, "result": r} for m, v, n, r in rows], fh, indent=2)
    return 0 if all(r is not None for *_, r in rows) else 1
