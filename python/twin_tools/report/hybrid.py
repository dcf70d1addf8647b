"""Hybrid results of a run (EMS, e-machine, battery nodes), from the bag data of
postprocess.read_run: summary keys, the electric-path balance, the SOC-corrected fuel and plots.
Every key is left out when the node that owns it did not run.

Summary keys: em_boost_kwh (crank work of the e-machine while motoring), em_brake_kwh (crank work
it absorbed while generating, positive: regenerative braking + load-point shift), em_regen_kwh
(the part absorbed while the EMS was in regen mode, booked per bag interval by the mode at the
interval's end), em_loss_kwh, battery_loss_kwh, battery_heat_kwh (through the housing), battery_vent_heat_kwh (carried
out by the ventilation air), battery_fan_kwh (the pack's ventilation fans, drawn from the 48 V bus), battery_fan_on_s, battery_housing_max_c, dcdc_kwh, soc_initial,
soc_final, soc_min and soc_max (the lowest and highest SOC of the run's bag samples), battery_max_c, winding_max_c, em_derating_s (time with the e-machine's live limits
below its peak envelope), em_clamped_s (time the EMS asked beyond the e-machine's live limits and
the e-machine clamped), battery_limited_s (time the battery's power request exceeded its limits), engine_off_s, engine_starts, cranking_s, warmup_inhibit_s,
electric_path_closure (|battery terminal energy + unmet - e-machine DC energy - DC/DC energy - fan| /
throughput), battery_balance_closure, em_balance_closure, fuel_soc_corrected_kg and, given a
baseline summary (scripts/twin report --baseline), fuel_saving_pct.

SOC correction: the battery's net chemical energy change dE (J, > 0 = the run ended with more
energy stored) was bought with fuel, so fuel_soc_corrected = fuel - dE / (LHV eta_engine
eta_charge), with eta_engine = the run's mean engine efficiency (positive brake work / fuel
energy) and eta_charge = the run's own charging chain (battery chemical energy stored per joule
of e-machine generating work at the crank). Both measured in the run itself; with dE = 0 the
correction vanishes.
"""
import json
import os

import numpy as np

from twin_tools.units import DIESEL_LHV_J_KG
from twin_tools import wiring

# topics (twin_tools.wiring: the participants' topics.yaml)
BATTERY_STATE = wiring.topic("battery", "state")
COOLING_STATE = wiring.topic("cooling", "state")
EMACHINE_STATE = wiring.topic("emachine", "state")
EMS_COMMAND = wiring.topic("ems", "command")
ENGINE_STATE = wiring.topic("engine", "state")
VEHICLE_STATE = wiring.topic("vehicle", "state")

J_PER_KWH = 3.6e6
MODE_REGEN, MODE_STOPPED = 2, 4


def _l(d, f):
    return float(d[f][-1])


def _interval_by_mode(cum, t_cum, mode, t_mode, which):
    """Sum of the increments of a cumulative series over bag intervals whose end sample has
    mode == which (EMS mode sampled at the same stamps)."""
    n = min(len(cum), len(mode))
    inc = np.diff(cum[:n])
    return float(np.sum(inc[mode[1:n] == which]))


def hybrid_summary(data, summary):
    s = {}
    em, bat, ems = data.get(EMACHINE_STATE), data.get(BATTERY_STATE), data.get(EMS_COMMAND)
    veh, eng, cool = data.get(VEHICLE_STATE), data.get(ENGINE_STATE), data.get(COOLING_STATE)
    if em is None or bat is None:
        return s
    s["em_boost_kwh"] = _l(em, "mech_motoring_energy_j") / J_PER_KWH
    s["em_brake_kwh"] = -_l(em, "mech_generating_energy_j") / J_PER_KWH
    if ems is not None:
        s["em_regen_kwh"] = -_interval_by_mode(em["mech_generating_energy_j"], em["t"], ems["mode"], ems["t"],
                                               MODE_REGEN) / J_PER_KWH
    loss_fields = ["copper_loss_energy_j", "iron_loss_energy_j", "rotor_loss_energy_j",
                   "mechanical_loss_energy_j", "inverter_loss_energy_j", "ratio_loss_energy_j"]
    s["em_loss_kwh"] = sum(_l(em, f) for f in loss_fields) / J_PER_KWH
    s["battery_loss_kwh"] = _l(bat, "loss_energy_j") / J_PER_KWH
    s["battery_heat_kwh"] = _l(bat, "heat_to_air_j") / J_PER_KWH
    s["battery_vent_heat_kwh"] = _l(bat, "ventilation_heat_j") / J_PER_KWH
    s["soc_initial"] = float(bat["soc"][0])
    s["soc_final"] = _l(bat, "soc")
    s["soc_min"] = float(np.min(bat["soc"]))
    s["soc_max"] = float(np.max(bat["soc"]))
    s["battery_max_c"] = float(np.max(bat["cell_temperature_k"])) - 273.15
    s["battery_fan_kwh"] = _l(bat, "fan_energy_j") / J_PER_KWH
    s["battery_fan_on_s"] = _l(bat, "fan_on_time_s")
    s["battery_housing_max_c"] = float(np.max(bat["housing_temperature_k"])) - 273.15
    s["winding_max_c"] = float(np.max(em["winding_temperature_k"])) - 273.15
    der = em["derating_factor"] < 1.0 - 1e-9
    dt = np.diff(em["t"])
    s["em_derating_s"] = float(np.sum(dt[der[1:]]))
    # limits: the e-machine clamps a request beyond its live limits (it never exceeds them); the
    # EMS should not ask beyond them: time with a clamped request (bag samples), and the
    # battery's own count of steps whose request exceeded its power limits
    clamped = np.abs(em["torque_request_nm"] - em["torque_nm"]) > 1e-6 * (1.0 + np.abs(em["torque_request_nm"]))
    s["em_clamped_s"] = float(np.sum(dt[clamped[1:]]))
    s["battery_limited_s"] = _l(bat, "limited_time_s")
    if veh is not None and "dcdc_energy_j" in veh:
        s["dcdc_kwh"] = _l(veh, "dcdc_energy_j") / J_PER_KWH
    if cool is not None:
        s["lt_pump_kwh"] = _l(cool, "lt_pump_energy_j") / J_PER_KWH
    if ems is not None:
        s["engine_off_s"] = _l(ems, "stopped_time_s")
        s["engine_starts"] = int(_l(ems, "engine_starts"))
        s["cranking_s"] = _l(ems, "cranking_time_s")
        s["warmup_inhibit_s"] = _l(ems, "warmup_inhibit_time_s")
    # balances
    term, dc = _l(bat, "terminal_energy_j"), _l(em, "electrical_energy_j")
    dcdc = _l(veh, "dcdc_energy_j") if veh is not None and "dcdc_energy_j" in veh else 0.0
    unmet, fan = _l(bat, "unmet_energy_j"), _l(bat, "fan_energy_j")
    throughput = _l(em, "electrical_drawn_energy_j") - _l(em, "electrical_returned_energy_j") + abs(dcdc) + fan
    if throughput > 0:
        s["electric_path_closure"] = abs(term + unmet - dc - dcdc - fan) / throughput
        s["battery_balance_closure"] = abs(_l(bat, "energy_residual_j")) / throughput
        s["em_balance_closure"] = abs(_l(em, "energy_residual_j")) / throughput
    # SOC-corrected fuel
    if eng is not None:
        fuel = _l(eng, "fuel_mass_kg")
        pos = _l(eng, "positive_work_j")
        eta_eng = pos / (fuel * DIESEL_LHV_J_KG) if fuel > 0 else 0.0
        dE = -_l(bat, "chemical_energy_j")  # > 0: energy stored over the run
        gen = -_l(em, "mech_generating_energy_j")
        # charging chain: chemical energy stored per J of generating work (from the run's totals:
        # DC returned x battery charge efficiency ~ terminal -> chemical on the charging side)
        ret = -_l(em, "electrical_returned_energy_j")
        eta_em = ret / gen if gen > 0 else 0.9
        eta_bat = 1.0 - (_l(bat, "loss_energy_j") / (throughput if throughput > 0 else 1.0))
        eta_charge = eta_em * eta_bat
        s["eta_engine_mean"] = eta_eng
        s["eta_charge_chain"] = eta_charge
        s["battery_energy_change_kwh"] = dE / J_PER_KWH
        if eta_eng > 0 and eta_charge > 0:
            # the engine's fuel corrected, plus the fuel-fired heater's (in fuel_kg with hvac:=on)
            total = summary.get("fuel_kg", fuel)
            s["fuel_soc_corrected_kg"] = total - dE / (DIESEL_LHV_J_KG * eta_eng * eta_charge)
    return s


# a baseline must have run under the same conditions as the hybrid it is compared with (the aux set
# differs by design: the hybrid's carries the DC/DC load)
COMPARABLE_KEYS = ("engine_model", "ambient_c", "start", "gearbox_set", "hvac", "macro_step_s", "sim_time_s")


class BaselineError(ValueError):
    """A --baseline file that is no conventional run's summary under this run's conditions."""


def read_baseline(path):
    """The summary.json at `path` (scripts/twin report --baseline): read and checked to be a run's
    summary, before any bag is read. BaselineError names the file and what is wrong."""
    if os.path.isdir(path):
        raise BaselineError("%s: a folder, not a summary.json (a run's is DIR/summary.json)" % path)
    try:
        with open(path) as f:
            base = json.load(f)
    except OSError as e:
        raise BaselineError("%s: cannot be read: %s" % (path, e.strerror or e))
    except ValueError as e:
        raise BaselineError("%s: not JSON (%s): --baseline takes a run's summary.json" % (path, e))
    if not isinstance(base, dict) or "scenario" not in base or "fuel_kg" not in base:
        raise BaselineError("%s: not a run's summary.json (no scenario or fuel_kg; a run cut before it "
                            "reported fuel has none)" % path)
    return base


def check_baseline(path, base, run):
    """BaselineError unless `base` (read_baseline) is the conventional bus's run under the
    conditions of the hybrid run summary `run` (COMPARABLE_KEYS), each difference named."""
    if run.get("architecture") == "conventional":
        raise BaselineError("--baseline: this run (%s) is the conventional bus; the saving is a hybrid's "
                            "against it: report the hybrid's bag with this baseline" % run.get("scenario"))
    if base.get("architecture") != "conventional":
        raise BaselineError("%s: a run of %s (architecture %s): --baseline takes the conventional bus's "
                            "summary (baseline_urban)" % (path, base.get("scenario"), base.get("architecture")))
    diffs = []
    for k in COMPARABLE_KEYS:
        a, b = base.get(k), run.get(k)
        same = (a == b or (isinstance(a, (int, float)) and isinstance(b, (int, float))
                           and abs(a - b) <= 1e-6 * max(1.0, abs(b))))
        if k in base and k in run and not same:
            diffs.append("%s %s (baseline) vs %s (this run)" % (k, a, b))
    if diffs:
        raise BaselineError("%s: not run under this run's conditions: %s" % (path, "; ".join(diffs)))


def saving(base, hyb):
    """fuel_saving_pct of a hybrid summary against a baseline summary of the same scenario."""
    f0 = base.get("fuel_kg")
    f1 = hyb.get("fuel_soc_corrected_kg", hyb.get("fuel_kg"))
    if not f0 or f1 is None:
        return None
    return 100.0 * (f0 - f1) / f0


def hybrid_plots(data, save, plt):
    """hybrid.png (power split, SOC, battery T and current), em_map.png (operating points on the
    envelope, efficiency), em_thermal.png (winding/magnet temperatures and the live limits)."""
    em, bat, ems, eng = data.get(EMACHINE_STATE), data.get(BATTERY_STATE), data.get(EMS_COMMAND), data.get(ENGINE_STATE)
    if em is None or bat is None:
        return
    fig, ax = plt.subplots(4, 1, figsize=(12, 10), sharex=True)
    if eng is not None:
        ax[0].plot(eng["t"], eng["brake_torque_nm"] * eng["engine_speed_rad_s"] / 1000.0, lw=0.5, label="engine")
    ax[0].plot(em["t"], em["torque_nm"] * em["speed_rad_s"] / 1000.0, lw=0.5, label="e-machine (crank)")
    ax[0].set(ylabel="power [kW]", title="Power split at the crank, battery")
    ax[0].legend(fontsize=8)
    ax[1].plot(bat["t"], bat["soc"] * 100.0, lw=0.8)
    ax[1].set(ylabel="SOC [%]")
    ax[2].plot(bat["t"], bat["cell_temperature_k"] - 273.15, lw=0.8, label="cells")
    if "housing_temperature_k" in bat:
        ax[2].plot(bat["t"], bat["housing_temperature_k"] - 273.15, lw=0.8, label="housing")
        ax[2].legend(fontsize=8)
    ax[2].axhline(45.0, color="r", lw=0.5, ls="--")
    ax[2].set(ylabel="battery T [°C]")
    ax[3].plot(bat["t"], bat["current_a"], lw=0.4)
    ax[3].set(xlabel="time [s]", ylabel="current [A] (>0 disch.)")
    save(fig, "hybrid.png")

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.5))
    w = em["speed_rad_s"] * 60 / (2 * np.pi)
    order = np.argsort(w)
    a1.plot(w[order], em["torque_max_peak_nm"][order], "k-", lw=0.8, label="peak envelope")
    a1.plot(w[order], em["torque_min_peak_nm"][order], "k-", lw=0.8)
    a1.plot(w[order], em["torque_max_continuous_nm"][order], "k--", lw=0.6, label="continuous")
    a1.plot(w[order], em["torque_min_continuous_nm"][order], "k--", lw=0.6)
    a1.plot(w, em["torque_nm"], ".", ms=1.5, alpha=0.4, label="operating points")
    a1.set(xlabel="crank speed [rpm]", ylabel="crank torque [Nm]", title="E-machine operating points")
    a1.legend(fontsize=8)
    P_m = em["torque_nm"] * em["speed_rad_s"]
    P_e = em["electrical_power_w"]
    eff = np.full_like(P_m, np.nan)
    mot, gen = (P_m > 500) & (P_e > 0), (P_m < -500) & (P_e < 0)
    eff[mot] = P_m[mot] / P_e[mot]
    eff[gen] = P_e[gen] / P_m[gen]
    a2.plot(np.abs(P_m[mot]) / 1000, eff[mot], ".", ms=1.5, label="motoring")
    a2.plot(np.abs(P_m[gen]) / 1000, eff[gen], ".", ms=1.5, label="generating")
    a2.set(xlabel="|crank power| [kW]", ylabel="efficiency incl. inverter [-]", ylim=(0.5, 1.0),
           title="E-machine efficiency")
    a2.legend(fontsize=8)
    save(fig, "em_map.png")

    fig, (a1, a2) = plt.subplots(2, 1, figsize=(12, 6), sharex=True)
    for f, lab in (("winding_temperature_k", "winding"), ("magnet_temperature_k", "magnets"),
                   ("stator_temperature_k", "stator"), ("housing_temperature_k", "housing")):
        a1.plot(em["t"], em[f] - 273.15, lw=0.8, label=lab)
    a1.set(ylabel="temperature [°C]", title="E-machine temperatures and live (derated) limits")
    a1.legend(fontsize=8, ncol=4)
    a2.plot(em["t"], em["torque_max_nm"], lw=0.6, label="live max")
    a2.plot(em["t"], em["torque_max_peak_nm"], lw=0.6, ls="--", label="peak max")
    a2.plot(em["t"], em["torque_min_nm"], lw=0.6, label="live min")
    a2.plot(em["t"], em["torque_min_peak_nm"], lw=0.6, ls="--", label="peak min")
    a2.set(xlabel="time [s]", ylabel="crank torque limit [Nm]")
    a2.legend(fontsize=8, ncol=4)
    save(fig, "em_thermal.png")
