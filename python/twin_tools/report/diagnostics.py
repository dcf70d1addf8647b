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
DIAGNOSTICS_TOPIC = "/diagnostics"
# Bag time [s] read first from the end: every participant publishes a status at every simulated
# second (config period_s 1) and its final one at the end, so a run that ended normally has all
# its participants' final statuses in the last second.
TAIL_S = 2.0


def read_diagnostics(run_bag, participants=None):
    """{node: {"final": bool, "t": s, "level": int, "values": {key: value}}} from the
    diagnostics.bag beside `run_bag`, or None if there is none.

    participants: the run's participant names (status.json's compute_time_s), if known. Then the
    last TAIL_S seconds of the bag are read first; when they hold a final status of every
    participant and nothing but final statuses' nodes, that is the answer (the whole bag would give
    the same: a final status wins over any periodic one, and the finals are published last).
    Otherwise (an aborted run, a node that stopped early, participants unknown) every message is
    read. A full mission's diagnostics.bag holds ~73 000 messages: ~5 s to read, the tail ~0.1 s."""
    path = os.path.join(os.path.dirname(os.path.abspath(run_bag)), DIAGNOSTICS_BAG)
    if not os.path.exists(path):
        return None
    from twin_tools.bags.reader import open_bag
    with open_bag(path) as bag:
        if participants:
            import genpy
            import rosbag
            try:
                start = genpy.Time.from_sec(max(0.0, bag.get_end_time() - TAIL_S))
            except rosbag.ROSBagException:  # "Bag contains no message": nothing to read
                return {}
            nodes = _latest(bag.read_messages(topics=[DIAGNOSTICS_TOPIC], start_time=start))
            if set(participants) <= set(nodes) and all(st["final"] for st in nodes.values()):
                return nodes
        return _latest(bag.read_messages(topics=[DIAGNOSTICS_TOPIC]))


def _latest(messages):
    """Each node's status to report from (topic, msg, t) of DiagnosticArray messages: its final
    status (key final = true) wins; otherwise the latest in simulated time."""
    nodes = {}
    for _, msg, _ in messages:
        t = msg.header.stamp.to_sec()
        for s in msg.status:
            values = {kv.key: kv.value for kv in s.values}
            final = values.get("final") == "true"
            old = nodes.get(s.name)
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
