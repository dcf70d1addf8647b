"""Mission energy ledger of a run, from fuel energy to every sink, computed from the bag.

Three balances, each from the cumulative energies the participants book themselves [J]:

  fuel:    m_fuel LHV            = W_engine,net + Q_coolant + Q_exhaust+other
  crank:   W_engine,net          = W_crank,engine + delay        (engine's own work vs work the
                                   driveline received: they differ by the one-exchange delay)
  heater (hvac:=on): m_fuel,heater LHV = Q_heater,coolant + flue loss  (fuel = Q / eta LHV, exact)
  cabin (hvac:=on):  Q_convectors + Q_people + Q_sun - Q_A/C - Q_body - Q_fresh - Q_doors = C dT
  electric (hybrid):
           W_em,crank (e-machine's own crank work) + e-machine losses = E_dc (inverter DC energy)
           E_battery,terminal + unmet = E_dc + E_dcdc (24 V consumers through the DC/DC)
                                        + E_fan (the pack's own ventilation fans)
           E_battery,chemical = E_battery,terminal + battery losses + RC stored energy
  driveline (vehicle_model.hpp):
           W_crank,engine + W_em = aux (steering, pneumatic, electric, HVAC, fan) + gearbox drag
                                   + converter + gear load + retarder + axle + shift
                                   + rolling + aero + grade (potential) + friction brakes
                                   + kinetic change + residual

Q_coolant is the engine model's own integral of heat to coolant; Q_exhaust+other is what the
fuel energy leaves after brake work and coolant heat (exhaust enthalpy, radiation, unburned fuel),
so the fuel balance closes by definition; the driveline balance is checked: its residual is
computed here from the individual terms, not taken from the vehicle's own residual field.
The ledger is a flat dict of kWh designed to grow (e-machine, battery, pump: add keys to
SINKS/SOURCES). Fuel LHV: diesel, src/common/units.hpp (twin_units.DIESEL_LHV_J_KG).
"""
import math

import numpy as np

from twin_tools.units import DIESEL_LHV_J_KG
from twin_tools import wiring
from twin_tools.report import hvac

# topics (twin_tools.wiring: the participants' topics.yaml)
BATTERY_STATE = wiring.topic("battery", "state")
COOLING_STATE = wiring.topic("cooling", "state")
EMACHINE_STATE = wiring.topic("emachine", "state")
ENGINE_HEAT = wiring.topic("engine", "heat")
ENGINE_STATE = wiring.topic("engine", "state")
VEHICLE_STATE = wiring.topic("vehicle", "state")

J_PER_KWH = 3.6e6
# When the bus stands still at a stop: config/mission.yaml stop_service/ (hbt::mission::StopService),
# taken from the run's resolved configuration (postprocess.stop_service); these defaults only
# for bags written before the run info carried it.
STOP_SERVICE_DEFAULT = {"standstill_speed_m_s": 0.5 / 3.6, "served_fraction": 0.9, "window_after_s": 2.0}

# (ledger key, VehicleState field, label) of every driveline sink, in the order of the report.
DRIVELINE_SINKS = [
    ("aux_steering", "aux_steering_work_j", "steering pump"),
    ("aux_pneumatic", "aux_pneumatic_work_j", "pneumatic system (air compressor)"),
    ("aux_electric", "aux_electric_work_j", "electric system (alternator)"),
    ("aux_hvac", "aux_hvac_work_j",
     "HVAC: A/C compressor + 24 V loads (HVAC, heater circulation pump) via the alternator"),
    ("fan", "fan_work_j", "cooling fan"),
    ("gearbox_drag", "gearbox_drag_loss_j", "gearbox drag"),
    ("converter", "converter_loss_j", "torque converter + lock-up slip"),
    ("gear_load", "gear_loss_j", "gear load-dependent loss"),
    ("retarder", "retarder_loss_j", "retarder drag"),
    ("axle", "axle_loss_j", "axle loss"),
    ("shift", "shift_loss_j", "gear-change clutch slip"),
    ("rolling", "rolling_loss_j", "tyre rolling resistance"),
    ("aero", "aero_loss_j", "aerodynamic drag"),
    ("grade", "potential_energy_j", "grade (potential energy gained)"),
    ("friction_brakes", "friction_brake_loss_j", "friction brakes"),
    ("kinetic_change", "kinetic_energy_change_j", "kinetic energy change"),
]
# Groups for the picture (sinks of the driveline balance).
GROUPS = [
    ("auxiliaries", ["aux_steering", "aux_pneumatic", "aux_electric", "aux_hvac", "fan"]),
    ("driveline losses", ["gearbox_drag", "converter", "gear_load", "retarder", "axle", "shift"]),
    ("road loads", ["rolling", "aero", "grade"]),
    ("friction brakes", ["friction_brakes"]),
    ("kinetic change", ["kinetic_change"]),
]
FUEL_STATES = ["idle_at_stop", "traction", "coasting_motoring", "shifting", "engine_off"]


def _last(d, field, default=0.0):
    if d is None or field not in d or len(d[field]) == 0:
        return default
    return float(d[field][-1])


def energy_ledger(data):
    """{key: kWh} of the run; None when the bag lacks the vehicle or engine state."""
    veh, eng, heat = data.get(VEHICLE_STATE), data.get(ENGINE_STATE), data.get(ENGINE_HEAT)
    if veh is None or eng is None:
        return None
    L = {}
    fuel_J = _last(eng, "fuel_mass_kg") * DIESEL_LHV_J_KG
    pos_J, mot_J = _last(eng, "positive_work_j"), _last(eng, "motoring_work_j")
    net_J = pos_J + mot_J
    coolant_J = _last(heat, "heat_to_coolant_j")  # into the metal, on to the coolant
    oil_J = _last(heat, "heat_to_oil_j")  # friction heat into the oil, on through the oil cooler
    L["fuel_chemical"] = fuel_J
    L["engine_positive"] = pos_J
    L["engine_motoring"] = mot_J
    L["engine_net"] = net_J
    L["engine_heat_to_coolant"] = coolant_J + oil_J
    L["engine_heat_to_oil"] = oil_J
    L["engine_exhaust_and_other"] = fuel_J - net_J - coolant_J - oil_J
    crank_engine_J = _last(veh, "engine_work_j")
    L["crank_engine"] = crank_engine_J
    L["crank_em"] = _last(veh, "em_work_j")
    L["coupling_delay"] = net_J - crank_engine_J
    sinks = 0.0
    for key, field, _ in DRIVELINE_SINKS:
        L[key] = _last(veh, field)
        sinks += L[key]
    L["aux_total"] = _last(veh, "aux_work_j")
    L["residual"] = crank_engine_J + L["crank_em"] - sinks
    em, bat = data.get(EMACHINE_STATE), data.get(BATTERY_STATE)
    if em is not None and bat is not None:
        L["em_motoring"] = _last(em, "mech_motoring_energy_j")
        L["em_generating"] = _last(em, "mech_generating_energy_j")
        L["em_coupling_delay"] = L["em_motoring"] + L["em_generating"] - L["crank_em"]
        L["em_losses"] = sum(_last(em, f) for f in (
            "copper_loss_energy_j", "iron_loss_energy_j", "rotor_loss_energy_j",
            "mechanical_loss_energy_j", "inverter_loss_energy_j", "ratio_loss_energy_j"))
        L["em_dc"] = _last(em, "electrical_energy_j")
        L["dcdc"] = _last(veh, "dcdc_energy_j")
        L["battery_terminal"] = _last(bat, "terminal_energy_j")
        L["battery_unmet"] = _last(bat, "unmet_energy_j")
        L["battery_losses"] = _last(bat, "loss_energy_j")
        L["battery_chemical"] = _last(bat, "chemical_energy_j")
        L["battery_fan"] = _last(bat, "fan_energy_j")  # drawn through the terminals, heat in the pack
        L["electric_residual"] = (L["battery_terminal"] + L["battery_unmet"] - L["em_dc"] - L["dcdc"]
                                  - L["battery_fan"])
    cool = data.get(COOLING_STATE)
    if cool is not None and "electric_pump_energy_j" in cool:  # 24 V: in aux_hvac or the DC/DC
        L["heater_pump"] = _last(cool, "electric_pump_energy_j")
    L.update(hvac.hvac_ledger(data))
    return {k: v / J_PER_KWH for k, v in L.items()}


def ledger_closure(L):
    """Driveline residual relative to the energy the crank received [-] (0 if nothing moved)."""
    src = abs(L["crank_engine"]) + abs(L["crank_em"])
    return abs(L["residual"]) / src if src > 0 else 0.0


def operating_state(veh, eng, standstill_m_s):
    """Per bag sample: index into FUEL_STATES. Standstill -> idle at stop; a gear change in
    progress (drive_mode 3) -> shifting; engine brake torque <= 0 while moving (overrun, fuel
    cut or engine braking) -> coasting/motoring; otherwise traction; engine stopped or being
    cranked (hybrid stop-start) -> engine_off. standstill_m_s: StopService.standstill_speed_m_s."""
    n = min(len(veh["t"]), len(eng["t"]))
    v = veh["speed_m_s"][:n]
    mode = veh["drive_mode"][:n]
    T = eng["brake_torque_nm"][:n]
    st = np.full(n, FUEL_STATES.index("traction"))
    st[T <= 0.0] = FUEL_STATES.index("coasting_motoring")
    st[mode == 3] = FUEL_STATES.index("shifting")
    st[v < standstill_m_s] = FUEL_STATES.index("idle_at_stop")
    if "engine_on" in veh:  # hybrid stop-start (and cranking)
        st[veh["engine_on"][:n] == 0] = FUEL_STATES.index("engine_off")
    return st


def fuel_by_state(data, stop_service=STOP_SERVICE_DEFAULT):
    """({state: kg}, {state: s}): the fuel burnt between two bag samples is booked to the state
    at the end of the interval (the state the engine ran in), so the kg add up to the total
    exactly."""
    veh, eng = data.get(VEHICLE_STATE), data.get(ENGINE_STATE)
    if veh is None or eng is None or len(eng["t"]) < 2:
        return None, None
    st = operating_state(veh, eng, stop_service["standstill_speed_m_s"])
    n = len(st)
    dm = np.diff(eng["fuel_mass_kg"][:n])
    dt = np.diff(eng["t"][:n])
    fuel = {s: float(np.sum(dm[st[1:] == i])) + (float(eng["fuel_mass_kg"][0]) if i == st[0] else 0.0)
            for i, s in enumerate(FUEL_STATES)}
    time = {s: float(np.sum(dt[st[1:] == i])) for i, s in enumerate(FUEL_STATES)}
    return fuel, time


def all_finite(d):
    return all(isinstance(v, (int, float)) and math.isfinite(v) for v in d.values())


def ledger_table(L):
    """Markdown lines of the ledger."""
    fuel = L["fuel_chemical"]
    pct = (lambda x: "%.1f" % (100.0 * x / fuel)) if fuel > 0 else (lambda x: "")
    rows = [("engine fuel chemical energy (LHV %.1f MJ/kg)" % (DIESEL_LHV_J_KG / 1e6), "fuel_chemical"),
            ("engine heat to the cooling (metal and oil, on to the coolant)", "engine_heat_to_coolant"),
            ("  of which friction heat into the oil", "engine_heat_to_oil"),
            ("engine exhaust and other losses", "engine_exhaust_and_other"),
            ("engine brake work, net", "engine_net"),
            ("  of which positive", "engine_positive"),
            ("  of which motoring (driven by the driveline)", "engine_motoring"),
            ("exchange delay (engine's work - work at the crank)", "coupling_delay"),
            ("engine work received by the driveline", "crank_engine"),
            ("e-machine work at the crank", "crank_em")]
    rows += [(label, key) for key, _, label in DRIVELINE_SINKS]
    rows += [("residual of the driveline balance", "residual")]
    if "em_dc" in L:
        rows += [("e-machine crank work while motoring (boost, cranking)", "em_motoring"),
                 ("e-machine crank work while generating (regen, load-point shift)", "em_generating"),
                 ("e-machine exchange delay (own work - work at the crank)", "em_coupling_delay"),
                 ("e-machine + inverter + ratio-stage losses", "em_losses"),
                 ("e-machine DC energy (net, > 0 drawn)", "em_dc"),
                 ("24 V consumers via the DC/DC", "dcdc"),
                 ("battery ventilation fans (48 V)", "battery_fan"),
                 ("battery terminal energy (net, > 0 delivered)", "battery_terminal"),
                 ("battery losses (ohmic + polarisation)", "battery_losses"),
                 ("battery chemical energy (net, > 0 released)", "battery_chemical"),
                 ("residual of the electric path (terminal - DC - DC/DC - fan)", "electric_residual")]
    if "heater_pump" in L:
        rows += [("heater circulation pump, 24 V electric (engine stopped; in aux_hvac via the "
                  "alternator, or in the DC/DC)", "heater_pump")]
    rows += [(label, key) for key, label in hvac.LEDGER_ROWS if key in L]
    out = ["| path | kWh | % of fuel |", "|---|---|---|"]
    for label, key in rows:
        out.append("| %s | %.3f | %s |" % (label, L[key], pct(L[key])))
    out.append("")
    out.append("Driveline balance closes to %.2e of the crank work." % ledger_closure(L))
    return out


def plot_ledger(L, path):
    """Stacked bars: fuel energy -> engine heat + brake work; crank work -> sinks."""
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 5))
    bars = [
        ("fuel", [("heat to coolant", L["engine_heat_to_coolant"]),
                  ("exhaust + other", L["engine_exhaust_and_other"]),
                  ("brake work (net)", L["engine_net"])]),
        ("crank", [(g, sum(L[k] for k in keys)) for g, keys in GROUPS]),
        ("driveline losses", [(label, L[key]) for key, _, label in DRIVELINE_SINKS[5:11]]),
        ("wheels", [(label, L[key]) for key, _, label in DRIVELINE_SINKS[11:]]),
    ]
    cmap = plt.get_cmap("tab20")
    c = 0
    for x, (name, parts) in enumerate(bars):
        bottom = 0.0
        for label, val in parts:
            if val <= 0:
                continue
            ax.bar(x, val, bottom=bottom, color=cmap(c % 20), edgecolor="white", width=0.6)
            if val > 0.02 * L["fuel_chemical"]:
                ax.text(x, bottom + val / 2, "%s\n%.1f" % (label, val), ha="center", va="center", fontsize=7)
            bottom += val
            c += 1
    ax.set_xticks(range(len(bars)))
    ax.set_xticklabels([b[0] for b in bars])
    ax.set_ylabel("energy [kWh]")
    ax.set_title("Where the mission's energy goes (negative terms, e.g. motoring, not drawn)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_operating_map(data, path):
    """Share of time and of fuel over engine speed x brake torque (2-D histograms)."""
    import matplotlib.pyplot as plt
    eng = data.get(ENGINE_STATE)
    if eng is None or len(eng["t"]) < 2:
        return False
    rpm = eng["engine_speed_rad_s"][1:] * 60.0 / (2.0 * math.pi)
    T = eng["brake_torque_nm"][1:]
    dt = np.diff(eng["t"])
    dm = np.diff(eng["fuel_mass_kg"])
    xb = np.linspace(500, 2500, 41)
    yb = np.linspace(min(-300.0, float(T.min())), max(1200.0, float(T.max())), 41)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for ax, w, title in ((axes[0], dt, "time share [%]"), (axes[1], dm, "fuel share [%]")):
        tot = float(np.sum(w))
        H, _, _ = np.histogram2d(rpm, T, bins=[xb, yb], weights=w)
        H = 100.0 * H / tot if tot > 0 else H
        m = ax.pcolormesh(xb, yb, np.ma.masked_less_equal(H.T, 0.0), cmap="viridis")
        fig.colorbar(m, ax=ax)
        ax.plot(rpm, eng["torque_max_nm"][1:], ",", color="0.6")
        ax.set(xlabel="engine speed [rpm]", title=title)
    axes[0].set_ylabel("brake torque [Nm]")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True
