"""Thermal and emission results of a run (cooling and aftertreatment nodes), from the bag data of
postprocess.read_run: summary keys and plots. Every key is left out when the node that owns it
did not run (a figure that means nothing for the run is not printed).

Summary keys: fan_kwh (crank-side fan drive energy, signed), pump_kwh (HT pump shaft energy),
warmup_s (first time the HT coolant reached the thermostat's opening start), coolant_warm_s (first
time it reached the EMS's warm threshold, config/ems.yaml warmup/coolant_warm_K: 70 degC; stop-start
and boost wait for it), ats_lightoff_s (first SCR light-off), scr_standstill_mean_c and
scr_standstill_min_c (SCR brick temperature while the bus stands: time mean and minimum over the
standstill periods after the light-off, where stop-start lets the brick cool), nox_engine_out_g, nox_tailpipe_g, nox_conversion_pct, nh3_slip_g, adblue_kg,
mean_charge_air_c (time mean of the intake-manifold temperature), mean_back_pressure_kpa
(time mean of the over-pressure at the turbine outlet), cooling_balance_closure and
ats_balance_closure (|energy residual| / heat or enthalpy in).
"""
import os

import numpy as np
import yaml

from twin_tools import wiring
from twin_tools.paths import REPO

# topics (twin_tools.wiring: the participants' topics.yaml)
AFTERTREATMENT_STATE = wiring.topic("aftertreatment", "state")
COOLING_STATE = wiring.topic("cooling", "state")
ENGINE_EXHAUST = wiring.topic("engine", "exhaust")
ENGINE_STATE = wiring.topic("engine", "state")
VEHICLE_ENGINE_COMMAND = wiring.topic("vehicle", "engine_command")

VEHICLE_STATE = wiring.topic("vehicle", "state")

J_PER_KWH = 3.6e6
STANDSTILL_M_S = 0.01  # the bus stands below this speed [m/s]


# Engine oil "warm" for the summary's oil_80c_s: 80 degC, where the cold-oil friction factor of
# the engines' Vogel law (config/engine_map.yaml) is down to 1.07 of the warm map's at 90 degC.
OIL_WARM_K = 353.15


def coolant_warm_K():
    """The EMS's warm threshold of the HT coolant [K] (config/ems.yaml warmup/coolant_warm_K)."""
    with open(os.path.join(REPO, "config", "ems.yaml")) as f:
        return float(yaml.safe_load(f)["warmup"]["coolant_warm_K"])


def first_time_at_or_above(t, x, level):
    """First time [s] x reaches level, None if never."""
    i = np.flatnonzero(x >= level)
    return float(t[i[0]]) if len(i) else None


def standstill_scr(ats, veh, after_s):
    """(time mean, min) of the SCR brick temperature [K] while the bus stands after after_s [s];
    None when it never stands then."""
    t = ats["t"]
    v = np.interp(t, veh["t"], veh["speed_m_s"])
    still = (v < STANDSTILL_M_S) & (t >= after_s)
    if np.count_nonzero(still[1:]) == 0:
        return None
    dt = np.diff(t)
    T = ats["scr_temperature_k"]
    w = dt * still[1:]
    return float(np.sum(T[1:] * w) / np.sum(w)), float(np.min(T[1:][still[1:]]))


def _time_mean(d, field):
    t, x = d["t"], d[field]
    if len(t) < 2:
        return float(x[-1])
    return float(np.trapz(x, t) / (t[-1] - t[0]))


def thermal_summary(data):
    s = {}
    cool, ats = data.get(COOLING_STATE), data.get(AFTERTREATMENT_STATE)
    eng, exh = data.get(ENGINE_STATE), data.get(ENGINE_EXHAUST)
    if cool is not None:
        s["fan_kwh"] = float(cool["fan_drive_energy_j"][-1]) / J_PER_KWH
        s["pump_kwh"] = float(cool["pump_energy_j"][-1]) / J_PER_KWH
        w = float(cool["warmup_time_s"][-1])
        if w >= 0.0:
            s["warmup_s"] = w
        warm = first_time_at_or_above(cool["t"], cool["coolant_ht_temperature_k"], coolant_warm_K())
        if warm is not None:
            s["coolant_warm_s"] = warm
        if "oil_temperature_k" in cool:  # the engine oil node: first time at 80 degC
            oil = first_time_at_or_above(cool["t"], cool["oil_temperature_k"], OIL_WARM_K)
            if oil is not None:
                s["oil_80c_s"] = oil
        heat_in = float(cool["engine_heat_j"][-1] + cool["lt_heat_j"][-1])
        if "engine_oil_heat_j" in cool:  # the engine's friction heat into its oil
            heat_in += float(cool["engine_oil_heat_j"][-1])
        if "aux_heater_j" in cool:  # the fuel-fired heater's heat (hvac:=on)
            heat_in += float(cool["aux_heater_j"][-1])
        if heat_in > 0:
            s["cooling_balance_closure"] = abs(float(cool["energy_residual_j"][-1])) / heat_in
    if exh is not None:
        s["nox_engine_out_g"] = float(exh["nox_mass_kg"][-1]) * 1000.0
    if ats is not None:
        lo = float(ats["light_off_time_s"][-1])
        if lo >= 0.0:
            s["ats_lightoff_s"] = lo
        s["nox_tailpipe_g"] = float(ats["tailpipe_nox_mass_kg"][-1]) * 1000.0
        nin = float(ats["engine_nox_mass_kg"][-1])
        if nin > 0:
            s["nox_conversion_pct"] = 100.0 * (1.0 - float(ats["tailpipe_nox_mass_kg"][-1]) / nin)
        veh = data.get(VEHICLE_STATE)
        scr = standstill_scr(ats, veh, max(lo, 0.0)) if veh is not None and lo >= 0.0 else None
        if scr is not None:
            s["scr_standstill_mean_c"] = scr[0] - 273.15
            s["scr_standstill_min_c"] = scr[1] - 273.15
        s["nh3_slip_g"] = float(ats["nh3_slip_mass_kg"][-1]) * 1000.0
        if "dpf_soot_load_g_l" in ats:  # DPF soot and passive regeneration
            s["dpf_soot_load_final_g_l"] = float(ats["dpf_soot_load_g_l"][-1])
            s["soot_engine_out_g"] = float(ats["soot_engine_out_kg"][-1]) * 1000.0
            s["soot_burnt_no2_g"] = float(ats["soot_burnt_kg"][-1]) * 1000.0
            s["dpf_no2_to_no_mol"] = float(ats["dpf_no2_to_no_mol"][-1])
        s["adblue_kg"] = float(ats["urea_mass_kg"][-1])
        h_in = float(ats["enthalpy_in_j"][-1])
        if h_in > 0:
            s["ats_balance_closure"] = abs(float(ats["energy_residual_j"][-1])) / h_in
        amb = data.get(VEHICLE_ENGINE_COMMAND)
        p_amb = float(amb["ambient_pressure_pa"][-1]) if amb is not None else 101325.0
        s["mean_back_pressure_kpa"] = (_time_mean(ats, "back_pressure_pa") - p_amb) / 1000.0
    if eng is not None and "charge_air_temperature_k" in eng and float(eng["charge_air_temperature_k"][-1]) > 0:
        s["mean_charge_air_c"] = _time_mean(eng, "charge_air_temperature_k") - 273.15
    return s


def thermal_plots(data, save, plt):
    """Adds thermal.png, fan.png, nox.png (each only when its node ran); `save(fig, name)`."""
    cool, ats = data.get(COOLING_STATE), data.get(AFTERTREATMENT_STATE)
    exh = data.get(ENGINE_EXHAUST)
    if cool is not None or ats is not None:
        fig, ax = plt.subplots(figsize=(12, 4.5))
        if cool is not None:
            ax.plot(cool["t"], cool["coolant_ht_temperature_k"] - 273.15, lw=0.9, label="HT coolant (engine outlet)")
            ax.plot(cool["t"], cool["metal_temperature_k"] - 273.15, lw=0.9, label="engine metal")
            if "oil_temperature_k" in cool:
                ax.plot(cool["t"], cool["oil_temperature_k"] - 273.15, lw=0.9, label="engine oil")
            for f, lab in (("radiator_coolant_temperature_k", "radiator volume"),
                           ("convector_coolant_temperature_k", "convector volume")):
                if f in cool:  # the HT coolant volumes (src/cooling/coolant_network.hpp)
                    ax.plot(cool["t"], cool[f] - 273.15, lw=0.7, ls="--", label=lab)
        if ats is not None:
            for f, lab in (("doc_temperature_k", "DOC"), ("dpf_temperature_k", "DPF"),
                           ("scr_temperature_k", "SCR"), ("asc_temperature_k", "ASC")):
                ax.plot(ats["t"], ats[f] - 273.15, lw=0.8, label=lab + " brick")
        ax.set(xlabel="time [s]", ylabel="temperature [°C]", title="Coolant and aftertreatment temperatures")
        ax.legend(ncol=3, fontsize=8)
        save(fig, "thermal.png")
    if cool is not None:
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(12, 5.5), sharex=True)
        a1.plot(cool["t"], cool["fan_speed_rad_s"] * 60 / (2 * np.pi), lw=0.7)
        a1.set(ylabel="fan speed [rpm]", title="Cooling fan (viscous clutch)")
        a2.plot(cool["t"], cool["fan_drive_power_w"] / 1000.0, lw=0.7)
        a2.axhline(0.0, color="0.5", lw=0.5)
        a2.set(xlabel="time [s]", ylabel="fan drive power [kW] (<0 windmilling)")
        save(fig, "fan.png")
    if exh is not None:
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(12, 5.5), sharex=True)
        a1.plot(exh["t"], exh["nox_mass_kg"] * 1000.0, lw=0.9, label="engine-out")
        if ats is not None:
            a1.plot(ats["t"], ats["tailpipe_nox_mass_kg"] * 1000.0, lw=0.9, label="tailpipe")
        a1.set(ylabel="cumulative NOx [g]", title="NOx and exhaust back-pressure")
        a1.legend()
        if ats is not None:
            a2.plot(ats["t"], (ats["back_pressure_pa"] - 101325.0) / 1000.0, lw=0.6)
            a2.set(ylabel="turbine-outlet over-pressure [kPa]")
        a2.set(xlabel="time [s]")
        save(fig, "nox.png")
