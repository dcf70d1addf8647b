"""Benchmarks of the twin (full missions: minutes to hours; never part of the test suite).

  scripts/twin bench [map]          baseline_urban, map engine, full mission, mode nodes and
                                    nodelets: wall/simulated ratio, distance, fuel, per-node compute time
  scripts/twin bench map --until S  the same on the first S seconds only
  scripts/twin bench 1d [--until S]  map engine vs 1D engine (FSM), nodelets: wall/simulated,
                                    engine compute time/simulated, fuel, NOx, torque traces compared
  scripts/twin bench engine [--duration S]  the 1D engine alone on the WHTC (GTR No. 4, speed
                                    imposed, torque requested), FSM then TVD on the same trace:
                                    CPU/simulated of each, FSM/TVD cost, cumulative fuel difference
                                    (engine_1d_whtc --bench; default the whole 1800 s cycle)
  scripts/twin bench ambient [--engines map,1d] [--until S] [--jobs N]  baseline_urban with the
                                    aftertreatment and cooling nodes at 0, 25 and 40 degC, nodelets:
                                    one table per engine (fuel, warm-up, fan energy, charge air,
                                    light-off, engine-out and tailpipe NOx, balances, wall/sim);
                                    N runs at a time (default 1: wall/sim undisturbed)
  scripts/twin bench hybrid [--engines map,1d] [--hvac on,off] [--until S] [--jobs N]  the
                                    hybrid's saving: baseline_urban and hybrid_urban at 0, 25 and
                                    40 degC for each engine and HVAC setting (nodelets; the baseline
                                    with the same Gauss-Seidel torque chain [[vehicle,
                                    aftertreatment, cooling], [engine]] as the hybrid's, so both see
                                    the engine torque without delay); the study table
                                    (docs/bench/hybrid_study[_hvac-X].md) with its checks (every stop served,
                                    every hybrid restarted its engine and asked nothing beyond the
                                    e-machine's and battery's limits: exit 1 otherwise), and one
                                    table per engine and temperature (SOC-corrected saving:
                                    twin_tools.report.hybrid)
  scripts/twin bench study [--engine 1d|map] [--until S] [--jobs N] [--slurm]  the ambient study
                                    as a sweep (config/sweeps/study.yaml: baseline_urban and
                                    hybrid_urban at 0, 25 and 40 degC, full Urban, HVAC on, 1D
                                    engine unless --engine map), N runs at a time (default 2) or a
                                    Slurm job array; prints the study table (fuel, SOC-corrected
                                    hybrid fuel, saving, warm-up, engine-off time, starts, heater
                                    fuel, NOx) with its checks and the wall time, writes
                                    docs/bench/study.md (study_map.md; twin_tools.bench.study)
  scripts/twin bench rates [--engines map,1d] [--until S]  multi-rate stepping vs everything at
                                    the 10 ms base step (cooling macro step, ATS model step 0.01 s
                                    in a config copy): fuel and temperature rises
  scripts/twin bench soak [--runs N] [--jobs J] [--until S]  N full map-engine missions (default 20:
                                    both scenarios, 5 ambients, 2 payloads), J at a time (default 4):
                                    failed runs, timeouts, finite summaries, the manager's RSS from
                                    the first mission to the last (twin_tools.bench.soak)
  scripts/twin bench cosim [--steps K]  the lock-step protocol alone: base steps per second for 3,
                                    5 and 8 probe participants (no model), nodelets and nodes, one
                                    rate / multi-rate / one Gauss-Seidel group per participant
                                    (twin_tools.bench.cosim; K base steps per nodelets run, K/4 for nodes)
  scripts/twin bench fmu [--pairs N] [--until S]  the FMU participant: its overhead per base step
                                    beyond the FMU's own doStep (target <= 2 us, nodelets), and the
                                    full hybrid_urban mission native then with the battery and the
                                    e-machine as exported FMUs (wall time ratio, target within 10 %;
                                    summaries equal); N pairs one after the other (default 1)
                                    (twin_tools.bench.fmu)
Results: printed as Markdown tables and written to docs/bench/<name>.md (name = the bench, with
the engine for ambient, hybrid and rates: one file per engine) with the command, the date and the
machine: commit it with the code it measured. A partial run (--until, --duration below 1800 s,
--steps below the default) writes results/bench/<name>.md instead. The runs' numbers:
results/bench/<name>.json.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

from twin_tools.bench import cosim as bench_cosim
from twin_tools.bench import fmu as bench_fmu_mod
from twin_tools.bench import soak as bench_soak
from twin_tools.bench import study as bench_study
from twin_tools.bench.study import cell, study_checks, study_table
from twin_tools.bench.docs import Measurement
from twin_tools.bench.rates_config import all_fast_config
from twin_tools.paths import REPO


def run_scenario(scenario, out, args):
    t0 = time.time()
    cmd = [os.path.join(REPO, "scripts", "twin"), "run", scenario, "--out", out] + args
    with open(out + ".log", "w") as log:
        rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT)
    wall = time.time() - t0
    if rc != 0:
        print("bench: %s %s failed (log %s.log)" % (scenario, " ".join(args), out), file=sys.stderr)
        return None
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(out, "status.json")) as f:
        st = json.load(f)
    s["compute_time_s"] = st.get("compute_time_s", {})
    s["process_cpu_s"] = st.get("process_cpu_s", {})
    s["process_wall_s"] = wall
    return s


def bench_map(a):
    rows = []
    for mode in ("nodes", "nodelets"):
        out = os.path.join(REPO, "results", "bench", "map_%s" % mode)
        os.makedirs(os.path.dirname(out), exist_ok=True)
        args = ["mode:=" + mode, "ambient:=25", "engine:=map"]
        if a.until:
            args.append("until:=%g" % a.until)
        s = run_scenario("baseline_urban", out, args)
        if s:
            rows.append((mode, s))
    md = ["baseline_urban, map engine, aftertreatment and cooling, ambient 25 °C, macro step %s s%s." % (
              rows[0][1]["macro_step_s"] if rows else "?", ", first %g s" % a.until if a.until else ", full mission"),
          "compute = the models' steps (steady clock); process CPU = user + system CPU from START to the end "
          "of the processes hosting participants (nodelets: the one manager, the stepper's nodelet in it; "
          "nodes: the stepper's own process not counted; roslaunch, rosmaster, rosout never).", "",
          "| mode | sim time [s] | wall time [s] | wall/sim | wall / summed compute | wall / participants' process CPU | steps/s | distance [km] | fuel [L/100km] | compute time per node [s] | process CPU [s] |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for mode, s in rows:
        steps = s["sim_time_s"] / s["macro_step_s"]
        compute = sum(s["compute_time_s"].values())
        procs = {", ".join(v["participants"]): v["cpu_s"] - v["cpu_at_start_s"]
                 for v in s["process_cpu_s"].values() if v["participants"] != ["stepper"]}
        cpu = sum(procs.values())
        md.append("| %s | %.1f | %.1f | %.4f | %.2f | %.2f | %.0f | %.3f | %.2f | %s | %s |" % (
            mode, s["sim_time_s"], s["wall_time_s"], s["wall_time_s"] / s["sim_time_s"],
            s["wall_time_s"] / compute if compute > 0 else float("nan"),
            s["wall_time_s"] / cpu if cpu > 0 else float("nan"),
            steps / s["wall_time_s"], s.get("distance_km", float("nan")),
            s.get("fuel_l_per_100km", float("nan")),
            ", ".join("%s %.1f" % kv for kv in sorted(s["compute_time_s"].items())),
            "; ".join("%s %.1f" % kv for kv in sorted(procs.items()))))
    print("\n" + "\n".join(md))
    a.measurement.write("map", "Map engine: wall time as nodes and as nodelets", md, bool(a.until))
    with open(os.path.join(REPO, "results", "bench", "map.json"), "w") as f:
        json.dump(dict(rows), f, indent=2)
    return 0 if len(rows) == 2 else 1


def bench_engine(a):
    """WHTC with FSM and TVD (engine_1d_whtc --bench): the solver cost targets of SPEC §3."""
    tool = os.path.join(REPO, "build", "devel", "lib", "hybrid_bus_twin", "engine_1d_whtc")
    if not os.path.exists(tool):
        print("bench: %s not built (run scripts/twin setup)" % tool, file=sys.stderr)
        return 1
    out = os.path.join(REPO, "results", "bench", "engine_whtc")
    os.makedirs(out, exist_ok=True)
    cmd = [tool, "--bench", "--duration", "%g" % a.duration, "--out", out, "--root", REPO,
           "--no-plot"]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(out + ".log", "w") as log:
        log.write(p.stdout)
    print(p.stdout)
    line = [l for l in p.stdout.splitlines() if l.startswith("BENCH:")]
    if p.returncode != 0 or not line:
        print("bench: engine_1d_whtc --bench failed (log %s.log)" % out, file=sys.stderr)
        return 1
    def num(pattern):
        m = re.search(pattern, line[0])
        return float(m.group(1)) if m else float("nan")
    res = {"duration_s": a.duration,
           "fsm_cpu_per_sim": num(r"FSM CPU/sim ([-+\d.]+)"),
           "tvd_cpu_per_sim": num(r"TVD CPU/sim ([-+\d.]+)"),
           "fsm_over_tvd_cost_pct": num(r"FSM/TVD cost ([-+\d.]+) %"),
           "fuel_fsm_g": num(r"fuel FSM ([-+\d.]+) g"),
           "fuel_tvd_g": num(r"vs TVD ([-+\d.]+) g"),
           "fuel_fsm_vs_tvd_pct": num(r"g: ([-+\d.]+) %")}
    with open(os.path.join(REPO, "results", "bench", "engine_whtc.json"), "w") as f:
        json.dump(res, f, indent=1)
    md = ["The 1D engine alone on the WHTC (GTR No. 4: speed imposed, torque requested), the FSM pipe "
          "solver then the fine-mesh TVD reference on the same trace (engine_1d_whtc --bench).", "",
          "| WHTC [s] | FSM CPU/sim | TVD CPU/sim | FSM/TVD cost | fuel FSM vs TVD |",
          "|---|---|---|---|---|",
          "| %.0f | %.4f | %.4f | %.1f %% | %+.2f %% |" % (
              a.duration, res["fsm_cpu_per_sim"], res["tvd_cpu_per_sim"], res["fsm_over_tvd_cost_pct"],
              res["fuel_fsm_vs_tvd_pct"])]
    print("\n".join(md))
    a.measurement.write("engine", "1D engine on the WHTC: FSM against TVD", md, a.duration < 1800.0)
    return 0


def bench_1d(a):
    """Full mission with the 1D engine (FSM) against the map engine, same machine, nodelets."""
    rows = []
    outs = {}
    for engine in ("map", "1d"):
        out = os.path.join(REPO, "results", "bench", "engine_%s" % engine)
        os.makedirs(os.path.dirname(out), exist_ok=True)
        args = ["mode:=nodelets", "ambient:=25", "engine:=" + engine, "timeout:=10"]
        if a.until:
            args.append("until:=%g" % a.until)
        s = run_scenario("baseline_urban", out, args)
        if s:
            rows.append((engine, s))
            outs[engine] = out
    md = ["baseline_urban (aftertreatment and cooling), ambient 25 °C, nodelets%s: map engine against "
          "the 1D engine (FSM)." % (", first %g s" % a.until if a.until else ", full mission"), "",
          "| engine | sim time [s] | wall/sim | engine compute/sim | wall / engine compute | other participants' compute/sim | distance [km] | fuel [kg] | fuel [L/100km] | NOx engine-out [g] |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for engine, s in rows:
        c = s["compute_time_s"]
        ce = c.get("engine", float("nan"))
        md.append("| %s | %.1f | %.4f | %.4f | %.3f | %.4f | %.3f | %.3f | %.2f | %s |" % (
            engine, s["sim_time_s"], s["wall_time_s"] / s["sim_time_s"], ce / s["sim_time_s"],
            s["wall_time_s"] / ce, sum(v for k, v in c.items() if k != "engine") / s["sim_time_s"],
            s.get("distance_km", float("nan")),
            s.get("fuel_kg", float("nan")), s.get("fuel_l_per_100km", float("nan")),
            "%.1f" % s["nox_engine_out_g"] if "nox_engine_out_g" in s else "-"))
    print("\n" + "\n".join(md))
    a.measurement.write("1d", "Map engine against 1D engine (FSM)", md, bool(a.until))
    if len(outs) == 2:
        subprocess.call([sys.executable, "-m", "twin_tools.bench.compare_engines",
                         outs["map"], outs["1d"], "--from", "40", "--to", "120"])
    with open(os.path.join(REPO, "results", "bench", "engine.json"), "w") as f:
        json.dump(dict(rows), f, indent=2)
    return 0 if len(rows) == 2 else 1


def bench_ambient(a):
    """The baseline at 0, 25 and 40 degC with each engine (nodelets)."""
    from concurrent.futures import ThreadPoolExecutor
    engines = [e for e in a.engines.split(",") if e]
    jobs = []
    for engine in engines:
        for amb in (0, 25, 40):
            out = os.path.join(REPO, "results", "bench", "ambient_%s_%dC" % (engine, amb))
            os.makedirs(os.path.dirname(out), exist_ok=True)
            args = ["mode:=nodelets", "ambient:=%d" % amb, "engine:=" + engine, "timeout:=10"]
            if a.until:
                args.append("until:=%g" % a.until)
            jobs.append(((engine, amb), out, args))
    with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        results = list(ex.map(lambda j: (j[0], run_scenario("baseline_urban", j[1], j[2])), jobs))
    table = {}
    cols = [("fuel_kg", "fuel [kg]", "%.3f"), ("fuel_l_per_100km", "L/100km", "%.2f"),
            ("warmup_s", "warm-up [s]", "%.0f"), ("fan_kwh", "fan [kWh]", "%.3f"),
            ("mean_charge_air_c", "charge air [°C]", "%.1f"), ("ats_lightoff_s", "ATS light-off [s]", "%.0f"),
            ("nox_engine_out_g", "NOx engine-out [g]", "%.0f"), ("nox_tailpipe_g", "NOx tailpipe [g]", "%.1f"),
            ("mean_back_pressure_kpa", "back-pressure [kPa]", "%.2f"),
            ("cooling_balance_closure", "cooling balance", "%.1e"), ("ats_balance_closure", "ATS balance", "%.1e")]
    for engine in engines:
        md = ["baseline_urban, %s engine, aftertreatment + cooling, nodelets, cold start at the ambient "
              "temperature%s; %d run(s) at a time (wall/sim is that of runs sharing the machine when more "
              "than one)." % (engine, ", first %g s" % a.until if a.until else ", full mission", max(1, a.jobs)), "",
              "| ambient | " + " | ".join(c[1] for c in cols) + " | wall/sim |",
              "|---" * (len(cols) + 2) + "|"]
        for (e, amb), s in results:
            if e != engine:
                continue
            if s is None:
                md.append("| %d °C | run failed |" % amb)
                continue
            table["%s_%d" % (e, amb)] = s
            cells = [(c[2] % s[c[0]]) if c[0] in s else "-" for c in cols]
            md.append("| %d °C | %s | %.4f |" % (amb, " | ".join(cells), s["wall_time_s"] / s["sim_time_s"]))
        print("\n" + "\n".join(md))
        a.measurement.write("ambient_%s" % engine, "Baseline at 0, 25 and 40 °C, %s engine" % engine, md, bool(a.until))
    with open(os.path.join(REPO, "results", "bench", "ambient.json"), "w") as f:
        json.dump(table, f, indent=2)
    return 0 if all(s for _, s in results) else 1


HYBRID_ROWS = [("fuel_kg", "fuel [kg]", "%.3f"), ("fuel_soc_corrected_kg", "fuel, SOC-corrected [kg]", "%.3f"),
               ("fuel_l_per_100km", "fuel [L/100 km]", "%.2f"), ("fuel_saving_pct", "fuel saving [%]", "%.2f"),
               ("heater_fuel_kg", "  of which auxiliary heater [kg]", "%.3f"), ("hvac_kwh", "HVAC [kWh]", "%.2f"),
               ("engine_positive_kwh", "engine positive work [kWh]", "%.2f"),
               ("em_boost_kwh", "EM boosting [kWh]", "%.2f"), ("em_brake_kwh", "EM braking + charging [kWh]", "%.2f"),
               ("em_regen_kwh", "  of which regenerative braking [kWh]", "%.2f"),
               ("em_loss_kwh", "EM + inverter losses [kWh]", "%.2f"), ("battery_loss_kwh", "battery loss [kWh]", "%.3f"),
               ("fan_kwh", "fan [kWh]", "%.2f"), ("pump_kwh", "HT pump [kWh]", "%.3f"), ("lt_pump_kwh", "LT pump [kWh]", "%.3f"),
               ("nox_engine_out_g", "NOx engine-out [g]", "%.0f"), ("nox_tailpipe_g", "NOx tailpipe [g]", "%.1f"),
               ("coolant_warm_s", "coolant at the EMS's warm threshold (70 °C) [s]", "%.0f"),
               ("warmup_s", "thermostat opening (83 °C) [s]", "%.0f"), ("ats_lightoff_s", "SCR light-off [s]", "%.0f"),
               ("scr_standstill_mean_c", "SCR at standstill, mean [°C]", "%.0f"),
               ("scr_standstill_min_c", "SCR at standstill, min [°C]", "%.0f"),
               ("soc_final", "final SOC [-]", "%.3f"), ("battery_max_c", "max cell T [°C]", "%.1f"),
               ("winding_max_c", "max winding T [°C]", "%.1f"), ("em_derating_s", "EM derating [s]", "%.0f"),
               ("em_clamped_s", "EM request clamped [s]", "%.1f"), ("battery_limited_s", "battery request limited [s]", "%.1f"),
               ("stops_served", "stops served", "%d"),
               ("engine_off_s", "engine off [s]", "%.0f"), ("engine_starts", "restarts", "%d"),
               ("warmup_inhibit_s", "warm-up inhibit [s]", "%.0f"), ("stops_served", "stops served", "%d"),
               ("electric_path_closure", "electric-path balance", "%.1e"), ("speed_rmse_kmh", "speed RMSE [km/h]", "%.2f")]

def bench_hybrid(a):
    """Baseline vs hybrid at 0, 25 and 40 degC with each engine (nodelets) and each HVAC setting."""
    from concurrent.futures import ThreadPoolExecutor
    engines = [e for e in a.engines.split(",") if e]
    hvacs = [h for h in a.hvac.split(",") if h] or [""]
    jobs = []
    for engine in engines:
        for hvac in hvacs:
            for amb in (0, 25, 40):
                for scen in ("baseline_urban", "hybrid_urban"):
                    out = os.path.join(REPO, "results", "bench", "hybrid_%s_%s_%dC%s" % (
                        scen.split("_")[0], engine, amb, "_hvac-" + hvac if hvac else ""))
                    os.makedirs(os.path.dirname(out), exist_ok=True)
                    args = ["mode:=nodelets", "ambient:=%d" % amb, "engine:=" + engine, "timeout:=10"]
                    if hvac:
                        args.append("hvac:=" + hvac)
                    if scen == "baseline_urban":  # the hybrid's first group (urban.launch hy_order)
                        args.append("order:=[[vehicle, aftertreatment, cooling%s], [engine]]" % (
                            "" if hvac == "off" else ", hvac"))
                    if a.until:
                        args.append("until:=%g" % a.until)
                    jobs.append(((engine, amb, hvac, scen), out, args))
    t0 = time.time()
    with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        results = dict(ex.map(lambda j: (j[0], (j[1], run_scenario(j[0][3], j[1], j[2]))), jobs))
    wall_s = time.time() - t0
    # the hybrid's saving against its baseline (SOC-corrected): the report from the hybrid's bag
    for engine in engines:
        for hvac in hvacs:
            for amb in (0, 25, 40):
                (bo, bs), (ho, hs) = results[(engine, amb, hvac, "baseline_urban")], results[(engine, amb, hvac, "hybrid_urban")]
                if bs and hs:
                    subprocess.call([sys.executable, "-m", "twin_tools.report.postprocess", ho,
                                     "--bag", os.path.join(ho, "run.bag"), "--baseline", os.path.join(bo, "summary.json")],
                                    stdout=subprocess.DEVNULL)
                    with open(os.path.join(ho, "summary.json")) as f:
                        cpu = hs.get("compute_time_s", {})
                        hs.clear()
                        hs.update(json.load(f))
                        hs["compute_time_s"] = cpu
    head = ("VECTO Urban%s, nodelets, %d run(s) at a time; both runs of a pair with the torque chain stepped "
            "without delay (Gauss-Seidel groups). Saving = (baseline fuel - hybrid fuel corrected for the "
            "battery's energy change) / baseline fuel (twin_tools.report.hybrid). Wall time of all %d runs: %.0f s." % (
                " (first %g s)" % a.until if a.until else ", full mission", max(1, a.jobs), len(jobs), wall_s))
    checks = study_checks(results, full_mission=not a.until)
    study = [head, ""] + study_table(results, engines, hvacs) + [
        "", "Checks:", ""] + ["- %s %s" % ("ok:" if ok else "FAILED:", what) for what, ok in checks] + [""]
    print("\n".join(study))
    tag = "".join("_hvac-" + h for h in hvacs if h)  # one file per HVAC selection
    a.measurement.write("hybrid_study" + tag, "Baseline against 48 V P1 hybrid: the study", study, bool(a.until))
    table = {}
    for engine in engines:
        lines = [head, ""]
        for hvac in hvacs:
            for amb in (0, 25, 40):
                bs, hs = results[(engine, amb, hvac, "baseline_urban")][1], results[(engine, amb, hvac, "hybrid_urban")][1]
                lines += ["## %s engine, %d °C%s" % (engine, amb, ", hvac:=" + hvac if hvac else ""), "",
                          "| quantity | baseline | hybrid |", "|---|---|---|"]
                for key, label, fmt in HYBRID_ROWS:
                    lines.append("| %s | %s | %s |" % (label, cell(bs, key, fmt), cell(hs, key, fmt)))
                for s, name in ((bs, "baseline"), (hs, "hybrid")):
                    if s:
                        table["%s_%s_%d%s" % (name, engine, amb, "_hvac-" + hvac if hvac else "")] = s
                wall = lambda s: ("%.4f" % (s["wall_time_s"] / s["sim_time_s"])) if s else "-"
                lines += ["| wall/sim | %s | %s |" % (wall(bs), wall(hs)), ""]
        print("\n".join(lines))
        a.measurement.write("hybrid_%s%s" % (engine, tag), "Baseline against 48 V P1 hybrid at 0, 25 and 40 °C, %s engine" % engine,
                            lines, bool(a.until))
    with open(os.path.join(REPO, "results", "bench", "hybrid%s.json" % tag), "w") as f:
        json.dump(table, f, indent=2)
    return 0 if all(s for _, s in results.values()) and all(ok for _, ok in checks) else 1


def bench_rates(a):
    """The documented rates vs all at 10 ms, full mission, nodelets."""
    import shutil
    tmp = os.path.join(REPO, "results", "bench", "rates_config")
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    cfg = all_fast_config(tmp)
    rows = []
    for engine in [e for e in a.engines.split(",") if e]:
        res = {}
        for name, extra in (("multirate", []), ("all_10ms", ["config:=" + cfg])):
            out = os.path.join(REPO, "results", "bench", "rates_%s_%s" % (engine, name))
            args = ["mode:=nodelets", "engine:=" + engine, "timeout:=10"] + extra
            if a.until:
                args.append("until:=%g" % a.until)
            res[name] = run_scenario("baseline_urban", out, args)
        rows.append((engine, res))
    for engine, res in rows:
        md = ["baseline_urban, %s engine, nodelets%s: the documented rates (cooling and aftertreatment "
              "nodes at 0.1 s) against everything at the 10 ms base step (a config copy: "
              "twin_tools.bench.rates_config)." % (engine, ", first %g s" % a.until if a.until else ", full mission"), "",
              "| engine | quantity | multi-rate | all 10 ms | difference |", "|---|---|---|---|---|"]
        m, f = res["multirate"], res["all_10ms"]
        if not (m and f):
            md.append("| %s | run failed | | | |" % engine)
        else:
            for key in ("fuel_kg", "warmup_s", "ats_lightoff_s", "nox_tailpipe_g", "fan_kwh"):
                if key in m and key in f and f[key]:
                    md.append("| %s | %s | %.4f | %.4f | %+.3f %% |" % (engine, key, m[key], f[key], 100 * (m[key] / f[key] - 1)))
            md.append("| %s | wall/sim | %.4f | %.4f | |" % (engine, m["wall_time_s"] / m["sim_time_s"], f["wall_time_s"] / f["sim_time_s"]))
        print("\n" + "\n".join(md))
        a.measurement.write("rates_%s" % engine, "Multi-rate stepping against everything at 10 ms, %s engine" % engine,
                            md, bool(a.until))
    with open(os.path.join(REPO, "results", "bench", "rates.json"), "w") as fh:
        json.dump({e: r for e, r in rows}, fh, indent=2)
    return 0 if all(r["multirate"] and r["all_10ms"] for _, r in rows) else 1


def main():
    ap = argparse.ArgumentParser(prog="twin bench", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", nargs="?", default="map",
                    choices=["map", "1d", "engine", "ambient", "hybrid", "study", "rates", "cosim", "soak", "fmu"])
    ap.add_argument("--engines", default="map,1d", help="ambient, hybrid: engine models, comma-separated")
    ap.add_argument("--engine", default="1d", choices=["1d", "map"], help="study: the engine model (default 1d)")
    ap.add_argument("--slurm", action="store_true", help="study: the sweep as a Slurm job array (twin sweep --slurm)")
    ap.add_argument("--hvac", default="", help="hybrid: HVAC settings to run, comma-separated (on,off; default: "
                                              "the scenarios' default only)")
    ap.add_argument("--jobs", type=int, default=None, help="ambient, hybrid (default 1), study (default 2), "
                                                           "soak (default 4): runs at a time")
    ap.add_argument("--runs", type=int, default=20, help="soak: missions")
    ap.add_argument("--pairs", type=int, default=1, help="fmu: native + FMU mission pairs, one after the other")
    ap.add_argument("--until", type=float, default=0.0, help="simulate only the first S seconds")
    ap.add_argument("--duration", type=float, default=1800.0,
                    help="engine: WHTC seconds to run (default the whole 1800 s)")
    ap.add_argument("--steps", type=int, default=bench_cosim.FULL_STEPS, help="cosim: base steps per nodelets run")
    a = ap.parse_args()
    a.measurement = Measurement(sys.argv[1:])
    if a.jobs is None:
        a.jobs = {"soak": 4, "study": 2}.get(a.what, 1)
    if a.what == "soak":
        return bench_soak.bench_soak(a)
    if a.what == "study":
        return bench_study.bench_study(a)
    if a.what == "cosim":
        return bench_cosim.bench_cosim(a, REPO)
    if a.what == "fmu":
        return bench_fmu_mod.bench_fmu(a)
    return {"map": bench_map, "1d": bench_1d, "engine": bench_engine, "ambient": bench_ambient, "hybrid": bench_hybrid, "rates": bench_rates}[a.what](a)


if __name__ == "__main__":
    sys.exit(main())
