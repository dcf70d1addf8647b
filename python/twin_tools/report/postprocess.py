"""Results of one run of the twin: summary.json, report.md and PNG plots, computed from the bag
alone (analysed by header.stamp).

  python3 -m twin_tools.report.postprocess DIR --scenario NAME [name:=value ...]
      end of a run (scripts/twin run): stores
      the run's metadata in DIR/run.bag as topic /twin/run_info (std_msgs/String, JSON: scenario,
      launch arguments, DIR/status.json of the stepper, DIR/stops.csv), then reports from the bag
  python3 -m twin_tools.report.postprocess --bag BAG [--out DIR]
      scripts/twin report: the same report from
      any bag a run wrote (default DIR = the bag's folder); identical output
The participants' warnings (summary key `warnings`) and step compute times (report.md only) come
from diagnostics.bag beside the bag (twin_tools.report.diagnostics); without it the report says so.
Exit status: 0 if the run completed, 1 if it was aborted (the message names the failing node),
130 if it was interrupted (SIGINT/SIGTERM: the report covers the stretch that ran and says so).

Fuel: diesel, density and lower heating value as src/common/units.hpp defines them (with their
sources; read by twin_tools.units).
"""
import argparse
import json
import math
import os
import sys

import numpy as np

from twin_tools.bags.append import append_at_end
from twin_tools.bags.columns import Unsupported, read_columns
from twin_tools.bags.reader import BagError, check_bag_file, open_bag
from twin_tools.report import diagnostics, hvac, hybrid, ledger, thermal
from twin_tools.units import DIESEL_DENSITY_KG_L
from twin_tools import wiring

# topics (twin_tools.wiring: the participants' topics.yaml)
ENGINE_STATE = wiring.topic("engine", "state")
VEHICLE_STATE = wiring.topic("vehicle", "state")

J_PER_KWH = 3.6e6


RUN_INFO_TOPIC = "/twin/run_info"


def store_run_info(bag_path, info):
    """Appends the run's metadata (dict) to the bag as one std_msgs/String (JSON), stamped at the
    bag's end."""
    import rospy
    from std_msgs.msg import String
    msg = String(data=json.dumps(info, sort_keys=True))
    check_bag_file(bag_path)
    try:
        append_at_end(bag_path, RUN_INFO_TOPIC, msg)  # without reading the index through rosbag
    except Unsupported:
        with open_bag(bag_path, "a") as bag:  # a bag cut short: BagError saying how to recover it
            t_end = bag.get_end_time() if bag.get_message_count() else 1e-9
            bag.write(RUN_INFO_TOPIC, msg, rospy.Time.from_sec(t_end))


def numeric_fields(msg):
    """Names of a message's number fields (bool, int, float): the ones read_run keeps."""
    return [f for f in msg.__slots__ if isinstance(getattr(msg, f), (bool, int, float))]


def read_run(path):
    """(run info, data) of a bag: the run's metadata (/twin/run_info, JSON) and {topic: {field:
    np.array}} with 't' = header.stamp [s], numeric fields only (bool as 0/1). Read as columns
    (twin_tools.bags.columns); a bag that reader does not handle (compressed, unindexed) through
    rosbag, message by message, with the same result."""
    check_bag_file(path)
    try:
        data, messages = read_columns(path, messages_of=(RUN_INFO_TOPIC,))
        info = json.loads(messages[RUN_INFO_TOPIC][-1].data) if messages.get(RUN_INFO_TOPIC) else None
    except Unsupported:
        info, data = read_run_rosbag(path)
    if info is None:
        sys.exit("twin: %s has no %s (not written by scripts/twin run, or the run did not end)"
                 % (path, RUN_INFO_TOPIC))
    return info, data


def read_run_rosbag(path):
    """read_run through rosbag.Bag.read_messages(): (run info or None, data)."""
    info, data, fields = None, {}, {}
    with open_bag(path) as bag:
        for topic, msg, _ in bag.read_messages():
            if topic == RUN_INFO_TOPIC:
                info = json.loads(msg.data)
                continue
            d = data.get(topic)
            if d is None:  # the first message of a topic fixes its fields (one type per topic)
                fields[topic] = numeric_fields(msg)
                d = data[topic] = {f: [] for f in ["t"] + fields[topic]}
            d["t"].append(msg.header.stamp.to_sec())
            for f in fields[topic]:
                d[f].append(float(getattr(msg, f)))
    return info, {k: {f: np.asarray(v) for f, v in d.items()} for k, d in data.items()}


def cut_after(data, t_s):
    """The samples stamped at or before t_s [s]. An interrupted run's status gives the time every
    participant was done through; the bag may hold up to one grant window (2 reports) beyond it
    from some participants only, so a partial report covers 0..t_s, the same stretch for all."""
    out = {}
    for topic, d in data.items():
        keep = d["t"] <= t_s + 1e-9
        out[topic] = {f: v[keep] for f, v in d.items()}
    return out


def launch_args(pairs):
    out = {}
    for p in pairs:
        k, _, v = p.partition(":=")
        out[k] = v
    return out


def stop_service(out_dir, run_ok):
    """config/mission.yaml stop_service/ exactly as the run used it: the vehicle's
    resolved_config/vehicle.csv (written by the node itself). A missing file or key is an error
    naming it (a run that ended normally always has it); a failed run without it: None."""
    import csv
    path = os.path.join(out_dir, "resolved_config", "vehicle.csv")
    if not os.path.exists(path):
        if not run_ok:
            return None
        raise SystemExit("twin: %s missing: the stop-service definition of the run is unknown" % path)
    vals = {}
    with open(path) as f:
        for row in csv.reader(line for line in f if not line.startswith("#")):
            if len(row) >= 3 and row[1].startswith("stop_service/"):
                vals[row[1].split("/", 1)[1]] = float(row[2])
    for k in ledger.STOP_SERVICE_DEFAULT:
        if k not in vals:
            raise SystemExit("twin: %s: key stop_service/%s missing" % (path, k))
    return vals


def stops_served(veh, stops_csv, sv):
    """Stops of the mission (text of stops.csv, written by the vehicle node from the profile).
    A stop is served when the bus stands still (speed < sv standstill_speed_m_s) for at least
    served_fraction of the stop time within the profile's window [t_start, t_start + stop time +
    window_after_s] (config/mission.yaml stop_service/, the C++ mission runner's definition).
    Returns (served, total, max distance between the standstill position and the stop position [m])."""
    if not stops_csv:
        return None, None, None
    import io
    stops = np.loadtxt(io.StringIO(stops_csv), delimiter=",", skiprows=1, ndmin=2)
    t, v, s = veh["t"], veh["speed_m_s"], veh["distance_m"]
    dt = np.diff(t, append=t[-1])
    still = v < sv["standstill_speed_m_s"]
    served, total, max_pos_err = 0, 0, 0.0
    for pos, t0, dur in stops:
        if t0 + dur > t[-1]:  # beyond the simulated stretch (until:=)
            continue
        total += 1
        win = (t >= t0) & (t <= t0 + dur + sv["window_after_s"]) & still
        if np.sum(dt[win]) >= sv["served_fraction"] * dur - 1e-9:
            served += 1
        if win.any():
            max_pos_err = max(max_pos_err, float(np.max(np.abs(s[win] - pos))))
    return served, total, max_pos_err


def summarise(scenario, args, status, data, stops_csv, sv=ledger.STOP_SERVICE_DEFAULT):
    veh = data.get(VEHICLE_STATE)
    eng = data.get(ENGINE_STATE)
    # defaults as in launch/include/urban.launch (the scenario file sets the architecture)
    arch = args.get("architecture") or ("p1_48v" if scenario == "hybrid_urban" else "conventional")
    s = {
        "scenario": scenario,
        "architecture": arch,
        "engine_model": args.get("engine", "map"),
        "ambient_c": float(args.get("ambient", 25.0)),
        "start": args.get("start") or "cold",  # cold: everything at ambient; warm: warm_start/ of the configs
        "aux_set": args.get("aux") or ("vecto_p1_example_48v" if arch == "p1_48v" else "vecto_p1_example"),
        "gearbox_set": args.get("gearbox") or "typical",  # gear loss set, config/gearbox/<set>.yaml
        # the hvac participant ran (launch argument hvac, default on; only with the thermal nodes)
        "hvac": (args.get("hvac") or "on") if (args.get("thermal") or "true") == "true" else "off",
        "macro_step_s": status["macro_step_s"],
        "sim_time_s": status["sim_time_s"],
        "wall_time_s": status["wall_time_s"],
    }
    if arch == "p1_48v":  # the 48 V pack set: config/battery_pack/<pack>.yaml, empty = battery.yaml's own
        s["battery_pack"] = args.get("pack") or "battery.yaml"
    if veh is None or eng is None:
        return s
    dist_m = veh["distance_m"][-1]
    engine_fuel_kg = eng["fuel_mass_kg"][-1]
    heater_fuel_kg = hvac.heater_fuel_kg(data)  # the fuel-fired heater's (hvac:=on), counted in fuel_kg
    fuel_kg = engine_fuel_kg + heater_fuel_kg
    err = (veh["speed_m_s"] - veh["target_speed_m_s"]) * 3.6
    s.update({
        "distance_km": dist_m / 1000.0,
        "fuel_kg": fuel_kg,
        # a consumption per distance means nothing over a few metres: only from 1 km on
        "fuel_l_per_100km": fuel_kg / DIESEL_DENSITY_KG_L / (dist_m / 1e5) if dist_m >= 1000.0 else None,
        "engine_positive_kwh": eng["positive_work_j"][-1] / J_PER_KWH,
        "engine_motoring_kwh": eng["motoring_work_j"][-1] / J_PER_KWH,
        "speed_rmse_kmh": float(np.sqrt(np.mean(err ** 2))),
        "aux_kwh": veh["aux_work_j"][-1] / J_PER_KWH,
    })
    if data.get(hvac.HVAC_STATE) is not None:
        s["engine_fuel_kg"] = engine_fuel_kg
    s = {k: v for k, v in s.items() if v is not None}
    served, total, pos_err = stops_served(veh, stops_csv, sv)
    if total is not None:
        s["stops_served"], s["stops_total"] = served, total
        s["stop_position_error_max_m"] = pos_err
    L = ledger.energy_ledger(data)
    if L is not None:
        s["energy_kwh"] = L
        s["energy_ledger_closure"] = ledger.ledger_closure(L)
    fuel, time = ledger.fuel_by_state(data, sv)
    if fuel is not None and data.get(hvac.HVAC_STATE) is not None:  # the heater's fuel, its burning time
        fuel["aux_heater"] = heater_fuel_kg
        time["aux_heater"] = hvac.heater_on_time_s(data[hvac.HVAC_STATE])
    if fuel is not None:
        s["fuel_by_state_kg"] = fuel
        s["time_by_state_s"] = time
    s.update(thermal.thermal_summary(data))
    s.update(hvac.hvac_summary(data))
    s.update(hybrid.hybrid_summary(data, s))
    return s


def plots(out, data):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    veh, eng = data.get(VEHICLE_STATE), data.get(ENGINE_STATE)
    if veh is None or eng is None:
        return []
    files = []

    def save(fig, name):
        fig.tight_layout()
        p = os.path.join(out, name)
        fig.savefig(p, dpi=110)
        plt.close(fig)
        files.append(name)

    fig, ax = plt.subplots(figsize=(12, 4))
    ax.plot(veh["t"], veh["target_speed_m_s"] * 3.6, label="target", lw=0.8)
    ax.plot(veh["t"], veh["speed_m_s"] * 3.6, label="actual", lw=0.8)
    ax.set(xlabel="time [s]", ylabel="speed [km/h]", title="Vehicle speed: target vs actual")
    ax.legend()
    save(fig, "speed.png")

    fig, ax = plt.subplots(figsize=(12, 3))
    ax.step(veh["t"], veh["gear"], where="post", lw=0.8)
    ax.set(xlabel="time [s]", ylabel="gear [-]", title="Engaged gear")
    save(fig, "gear.png")

    fig, (a1, a2) = plt.subplots(2, 1, figsize=(12, 6), sharex=True)
    a1.plot(eng["t"], eng["engine_speed_rad_s"] * 60 / (2 * math.pi), lw=0.6)
    a1.set(ylabel="engine speed [rpm]")
    a2.plot(eng["t"], eng["brake_torque_nm"], lw=0.6)
    a2.set(xlabel="time [s]", ylabel="brake torque [Nm]")
    a1.set_title("Engine speed and torque")
    save(fig, "engine.png")

    fig, (a1, a2) = plt.subplots(2, 1, figsize=(12, 6), sharex=True)
    a1.plot(eng["t"], eng["fuel_mass_flow_kg_s"] * 3.6e6, lw=0.6)
    a1.set(ylabel="fuel rate [g/h]")
    a2.plot(eng["t"], eng["fuel_mass_kg"], lw=0.8)
    a2.set(xlabel="time [s]", ylabel="cumulative fuel [kg]")
    a1.set_title("Fuel")
    save(fig, "fuel.png")

    thermal.thermal_plots(data, save, plt)
    hvac.hvac_plots(data, save, plt)
    hybrid.hybrid_plots(data, save, plt)
    L = ledger.energy_ledger(data)
    if L is not None:
        ledger.plot_ledger(L, os.path.join(out, "energy_ledger.png"))
        files.append("energy_ledger.png")
    if ledger.plot_operating_map(data, os.path.join(out, "operating_map.png")):
        files.append("operating_map.png")
    return files


# status.json "status" of a run stopped from outside (SIGINT/SIGTERM, src/cosim/stepper.hpp)
INTERRUPTED = "interrupted"
# exit status of a report of an interrupted run (128 + SIGINT, as the shell reports Ctrl-C)
EXIT_INTERRUPTED = 130


def report(out, s, status, files, diag_lines=(), gaps=()):
    lines = ["# Run report: %s" % s["scenario"], ""]
    lines.append("Status: **%s**%s" % (status["status"], (" - " + status["message"]) if status["message"] else ""))
    lines.append("")
    if status["status"] == INTERRUPTED:
        lines += ["**Partial report**: the run was stopped from outside at t = %.2f s; every figure below "
                  "covers only the stretch 0 - %.2f s of the mission." % (status["sim_time_s"], status["sim_time_s"]), ""]
    for g in gaps:  # a bag that holds less than its run (bag_coverage)
        lines += ["**Incomplete bag**: " + g, ""]
    lines.append("| quantity | value |")
    lines.append("|---|---|")
    for k, v in s.items():
        if isinstance(v, (dict, list)):
            continue
        lines.append("| %s | %s |" % (k, ("%.6g" % v) if isinstance(v, float) else v))
    lines.append("")
    if "energy_kwh" in s:
        lines += ["## Energy ledger", ""] + ledger.ledger_table(s["energy_kwh"]) + [""]
    if "fuel_by_state_kg" in s:
        fuel, time = s["fuel_by_state_kg"], s["time_by_state_s"]
        tot_f = sum(fuel.values())
        tot_t = sum(v for k, v in time.items() if k in ledger.FUEL_STATES)  # the engine's states
        lines += ["## Fuel by operating state", "", "| state | fuel kg | % fuel | time s | % time |",
                  "|---|---|---|---|---|"]
        for k in ledger.FUEL_STATES:
            lines.append("| %s | %.4f | %.1f | %.1f | %.1f |" % (
                k, fuel[k], 100 * fuel[k] / tot_f if tot_f > 0 else 0, time[k],
                100 * time[k] / tot_t if tot_t > 0 else 0))
        if "aux_heater" in fuel:  # beside the engine's states: its time is the burner's on time
            lines.append("| fuel-fired heater (burner on) | %.4f | %.1f | %.1f | |" % (
                fuel["aux_heater"], 100 * fuel["aux_heater"] / tot_f if tot_f > 0 else 0, time["aux_heater"]))
        lines.append("")
    lines += list(diag_lines)
    if s.get("sim_time_s"):
        lines.append("Wall/simulated time ratio: %.4f" % (s["wall_time_s"] / s["sim_time_s"]))
    lines.append("")
    lines.append("Compute time per participant (steady clock inside its steps) [s]: " + ", ".join(
        "%s %.2f" % kv for kv in sorted(status.get("compute_time_s", {}).items())))
    lines.append("")
    lines.append("Fuel density %.3f kg/L (diesel). Data: bag `run.bag` (analyse by header.stamp)." % DIESEL_DENSITY_KG_L)
    lines.append("")
    for f in files:
        lines.append("![%s](%s)" % (f, f))
    with open(os.path.join(out, "report.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")


# the output every participant publishes in every scenario (its other outputs depend on who else
# runs: the vehicle commands the engine only without an EMS)
PRIMARY_OUTPUT_KEYS = ("state", "command")


def bag_coverage(data, status):
    """What the bag lacks for a full report of its run: (the primary outputs of the participants
    that ran -- status.json's compute_time_s -- that are not in the bag, sorted; the simulated time
    the bag's states reach [s], or None without any)."""
    expected = set()
    for p in status.get("compute_time_s", {}):
        if p not in wiring.participants():
            continue  # the recorder, a participant the tools do not know
        keys = [k for k in PRIMARY_OUTPUT_KEYS if k in wiring.declared(p)]
        if keys:
            expected.add(wiring.topic(p, keys[0]))
    missing = sorted(t for t in expected if t not in data)
    ends = [float(d["t"][-1]) for d in data.values() if len(d["t"])]
    return missing, (max(ends) if ends else None)


def coverage_lines(missing, until_s, sim_time_s):
    """Warnings (report.md, stderr) for a bag that holds less than its run."""
    lines = []
    if missing:
        lines.append("Outputs of this run's participants missing from the bag (not recorded, or filtered "
                     "out): %s; what is computed from them is not reported." % ", ".join(missing))
    if until_s is not None and sim_time_s and until_s < sim_time_s - 1.0:
        lines.append("The bag's states end at t = %.1f s of the %.1f s the run simulated (a bag cut or "
                     "filtered): the report covers 0-%.1f s only." % (until_s, sim_time_s, until_s))
    return lines


def report_from_bag(bag, out, baseline=None):
    """summary.json, report.md and plots in `out` from the bag alone; returns (status, summary).
    baseline: a baseline run's summary.json -> fuel_saving_pct (hybrid, SOC-corrected); it must be
    the conventional bus's under the same conditions (hybrid.BaselineError otherwise).
    A bag without some of the run's topics, or ending before the run did, is reported for what it
    holds, and says so (summary keys missing_topics, data_until_s, partial)."""
    base = hybrid.read_baseline(baseline) if baseline else None
    info, data = read_run(bag)
    status = info["status"]
    if status["status"] == INTERRUPTED:
        data = cut_after(data, status["sim_time_s"])
    s = summarise(info["scenario"], info["args"], status, data, info.get("stops_csv", ""),
                  info.get("stop_service") or ledger.STOP_SERVICE_DEFAULT)
    missing, until_s = bag_coverage(data, status)
    gaps = coverage_lines(missing, until_s, status["sim_time_s"])
    if missing:
        s["missing_topics"] = missing
    if until_s is not None and until_s < status["sim_time_s"] - 1.0:
        s["partial"] = True
        s["data_until_s"] = until_s
    for line in gaps:
        print("twin: report: %s: %s" % (bag, line), file=sys.stderr)
    nodes = diagnostics.read_diagnostics(bag, participants=list(status.get("compute_time_s", {})))
    warnings = diagnostics.warnings_list(nodes) if nodes is not None else None
    if warnings is not None:
        s["warnings"] = warnings
    if status["status"] == INTERRUPTED:  # what ran, and that it is not the whole mission
        s["partial"] = True
        s["interrupted_at_s"] = status["sim_time_s"]
    if base is not None:
        hybrid.check_baseline(baseline, base, s)
        pct = hybrid.saving(base, s)
        if pct is not None:
            s["fuel_saving_pct"] = pct
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "summary.json"), "w") as fh:
        json.dump(s, fh, indent=2)
        fh.write("\n")
    files = plots(out, data)
    report(out, s, status, files, diagnostics.report_lines(nodes, warnings), gaps)
    return status, s


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="?")
    ap.add_argument("--scenario")
    ap.add_argument("--bag", help="report from this bag (scripts/twin report)")
    ap.add_argument("--baseline", help="a baseline run's summary.json: adds fuel_saving_pct (SOC-corrected)")
    ap.add_argument("args", nargs="*", help="launch arguments name:=value")
    a = ap.parse_intermixed_args()
    if a.bag:
        out = a.out or os.path.dirname(os.path.abspath(a.bag))
        try:
            status, s = report_from_bag(a.bag, out, a.baseline)
        except (BagError, hybrid.BaselineError) as e:
            print("twin: report: %s" % e, file=sys.stderr)
            return 2
        print("twin: report of %s written to %s" % (a.bag, out))
        return 0
    if not a.out or not a.scenario:
        ap.error("DIR and --scenario are required (or --bag BAG)")
    status = json.load(open(os.path.join(a.out, "status.json")))
    bag = os.path.join(a.out, "run.bag")
    if not os.path.exists(bag):  # failed before the recorder opened its bag: status only
        print("twin: run FAILED: %s" % status["message"], file=sys.stderr)
        return 1
    stops = os.path.join(a.out, "stops.csv")
    info = {"scenario": a.scenario, "args": launch_args(a.args), "status": status,
            "stops_csv": open(stops).read() if os.path.exists(stops) else "",
            "stop_service": stop_service(a.out, status["status"] == "ok")}
    try:
        store_run_info(bag, info)
        status, s = report_from_bag(bag, a.out)
    except (BagError, OSError) as e:  # a run that stopped on its bag (disk full, ...): its status says why
        print("twin: run FAILED: %s" % status["message"], file=sys.stderr)
        print("twin: no report: %s" % (e if isinstance(e, BagError) else "%s: %s" % (e.filename or a.out, e.strerror)),
              file=sys.stderr)
        return 1
    if status["status"] == INTERRUPTED:
        print("twin: run INTERRUPTED: %s; a partial report of the stretch that ran is in %s (report.md, "
              "summary.json: partial)" % (status["message"], a.out), file=sys.stderr)
        return EXIT_INTERRUPTED
    if status["status"] != "ok":
        print("twin: run FAILED: %s" % status["message"], file=sys.stderr)
        return 1
    print("twin: done: %s" % ", ".join("%s=%s" % (k, ("%.4g" % v) if isinstance(v, float) else v)
                                      for k, v in s.items() if not isinstance(v, (dict, list))))
    for w in s.get("warnings", []):
        print("twin: warning from %s at t = %.2f s: %s: %s" % (w["node"], w["first_time_s"], w["warning"], w["message"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
