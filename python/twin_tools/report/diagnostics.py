"""The participants' diagnostics of a run (docs/diagnostics.md): read from diagnostics.bag beside
the run's bag (the recorder writes every /diagnostics message there, never into run.bag).

Each participant's last status -- its final one (key final = true), published at the end of the
run -- carries every warning raised during the run with the simulated time of its first raise
(keys warning/<name>/first_time_s, raised, active, active_s, message) and its step compute times
over the run (step_compute_ms_mean_run, step_compute_ms_max_run, steps_total). A node whose final
status is missing (an aborted run) is read from its last periodic status.
"""
import os

DIAGNOSTICS_BAG = "diagnostics.bag"


def read_diagnostics(run_bag):
    """{node: {"final": bool, "t": s, "level": int, "values": {key: value}}} from the
    diagnostics.bag beside `run_bag`, or None if there is none."""
    path = os.path.join(os.path.dirname(os.path.abspath(run_bag)), DIAGNOSTICS_BAG)
    if not os.path.exists(path):
        return None
    from twin_tools.bags.reader import open_bag
    nodes = {}
    with open_bag(path) as bag:
        for _, msg, _ in bag.read_messages(topics=["/diagnostics"]):
            for s in msg.status:
                values = {kv.key: kv.value for kv in s.values}
                final = values.get("final") == "true"
                t = msg.header.stamp.to_sec()
                old = nodes.get(s.name)
                # the final status wins; otherwise the latest in simulated time
                if old is None or (final, t) >= (old["final"], old["t"]):
                    nodes[s.name] = {"final": final, "t": t, "level": s.level, "values": values}
    return nodes


def warnings_list(nodes):
    """[{node, warning, first_time_s, message, raised, active_s}] sorted by first time (then node,
    warning): every warning raised in the run."""
    out = []
    for node, st in nodes.items():
        v = st["values"]
        for key, first in v.items():
            if not (key.startswith("warning/") and key.endswith("/first_time_s")):
                continue
            name = key[len("warning/"):-len("/first_time_s")]
            p = "warning/%s/" % name
            out.append({"node": node, "warning": name, "first_time_s": float(first),
                        "message": v.get(p + "message", ""), "raised": int(v.get(p + "raised", "1")),
                        "active_s": float(v.get(p + "active_s", "0"))})
    out.sort(key=lambda w: (w["first_time_s"], w["node"], w["warning"]))
    return out


def report_lines(nodes, warnings):
    """The report.md section."""
    lines = ["## Diagnostics", ""]
    if nodes is None:
        return lines + ["No %s beside the bag: the participants' warnings and compute times are "
                        "unknown (a bag from before diagnostics, or copied alone)." % DIAGNOSTICS_BAG, ""]
    if warnings:
        lines += ["Warnings raised (first time in simulated time; thresholds: the diagnostics: section of each participant's YAML, config/):", "",
                  "| first time [s] | node | warning | raised | active [s] | first message |",
                  "|---|---|---|---|---|---|"]
        for w in warnings:
            lines.append("| %.2f | %s | %s | %d | %.2f | %s |" % (
                w["first_time_s"], w["node"], w["warning"], w["raised"], w["active_s"], w["message"]))
    else:
        lines.append("No warning raised (checked: %s)." % "; ".join(
            "%s: %s" % (n, nodes[n]["values"].get("warnings_checked") or "none") for n in sorted(nodes)))
    lines += ["", "Step compute time per node (wall clock, whole run; not in summary.json):", "",
              "| node | steps | mean [ms] | max [ms] | CPU [s] | status |", "|---|---|---|---|---|---|"]
    for n in sorted(nodes):
        v = nodes[n]["values"]
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            n, v.get("steps_total", "?"), v.get("step_compute_ms_mean_run", "?"),
            v.get("step_compute_ms_max_run", "?"), v.get("compute_time_s", "?"),
            "final" if nodes[n]["final"] else "no final status (last at t = %.1f s)" % nodes[n]["t"]))
    return lines + [""]
