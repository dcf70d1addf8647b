"""HVAC results of a run (the hvac participant, hvac:=on), from the bag data of
postprocess.read_run: summary keys and a plot. Every key is left out when the hvac did not run.

Summary keys: hvac_kwh (energy the HVAC's machines drew: A/C compressor shaft + electric load of
blowers, condenser fans and the heater's burner; the crank-side cost incl. the alternator is the
ledger's aux_hvac), hvac_compressor_kwh, hvac_electric_kwh, heater_fuel_kg (the fuel-fired
heater's fuel, counted in fuel_kg), heater_kwh (its heat into the HT coolant), heater_on_s,
ac_cooling_kwh (heat the A/C removed from the cabin), cabin_heating_kwh (heat the coolant
convectors delivered), cabin_temperature_c_{initial, final, mean, min, max}, cabin_balance_closure
(|cabin energy residual| / heat through the cabin).
"""
import numpy as np
from twin_tools import wiring

HVAC_STATE = wiring.topic("hvac", "state")
J_PER_KWH = 3.6e6
K0 = 273.15


def _l(d, f):
    return float(d[f][-1])


def heater_fuel_kg(data):
    """The fuel-fired heater's fuel [kg] (0 without the hvac)."""
    h = data.get(HVAC_STATE)
    return _l(h, "aux_heater_fuel_kg") if h is not None and len(h["t"]) else 0.0


def heater_on_time_s(h):
    """Time the burner was on [s], booked to the interval's end sample (as fuel_by_state)."""
    if len(h["t"]) < 2:
        return 0.0
    return float(np.sum(np.diff(h["t"])[h["aux_heater_on"][1:] > 0]))


def hvac_summary(data):
    h = data.get(HVAC_STATE)
    if h is None or len(h["t"]) == 0:
        return {}
    T = h["cabin_temperature_k"] - K0
    t = h["t"]
    s = {
        "hvac_kwh": (_l(h, "compressor_energy_j") + _l(h, "electric_energy_j")) / J_PER_KWH,
        "hvac_compressor_kwh": _l(h, "compressor_energy_j") / J_PER_KWH,
        "hvac_electric_kwh": _l(h, "electric_energy_j") / J_PER_KWH,
        "heater_fuel_kg": _l(h, "aux_heater_fuel_kg"),
        "heater_kwh": _l(h, "aux_heater_heat_j") / J_PER_KWH,
        "heater_on_s": heater_on_time_s(h),
        "ac_cooling_kwh": _l(h, "ac_cooling_j") / J_PER_KWH,
        "cabin_heating_kwh": _l(h, "coolant_heat_j") / J_PER_KWH,
        "cabin_temperature_c_initial": float(T[0]),
        "cabin_temperature_c_final": float(T[-1]),
        "cabin_temperature_c_mean": float(np.trapz(T, t) / (t[-1] - t[0])) if len(t) > 1 else float(T[-1]),
        "cabin_temperature_c_min": float(np.min(T)),
        "cabin_temperature_c_max": float(np.max(T)),
    }
    through = sum(abs(_l(h, f)) for f in ("coolant_heat_j", "people_heat_j", "solar_heat_j", "ac_cooling_j"))
    if through > 0:
        s["cabin_balance_closure"] = abs(_l(h, "energy_residual_j")) / through
    return s


def hvac_ledger(data):
    """{key: J} of the HVAC for the energy ledger (empty without the hvac): the heater's fuel
    energy, its heat into the coolant and its flue loss; the cabin's heat flows."""
    h = data.get(HVAC_STATE)
    if h is None or len(h["t"]) == 0:
        return {}
    from twin_tools.units import DIESEL_LHV_J_KG
    L = {"heater_fuel_chemical": _l(h, "aux_heater_fuel_kg") * DIESEL_LHV_J_KG,
         "heater_heat_to_coolant": _l(h, "aux_heater_heat_j")}
    L["heater_flue_loss"] = L["heater_fuel_chemical"] - L["heater_heat_to_coolant"]
    L["hvac_compressor"] = _l(h, "compressor_energy_j")
    L["hvac_electric"] = _l(h, "electric_energy_j")
    for key, field in (("cabin_coolant_heat", "coolant_heat_j"), ("cabin_people", "people_heat_j"),
                       ("cabin_solar", "solar_heat_j"), ("cabin_ac_cooling", "ac_cooling_j"),
                       ("cabin_body", "body_loss_j"), ("cabin_fresh_air", "fresh_air_loss_j"),
                       ("cabin_doors", "door_loss_j"), ("cabin_stored", "stored_energy_change_j"),
                       ("cabin_residual", "energy_residual_j")):
        L[key] = _l(h, field)
    return L


# (ledger key, label) of the HVAC rows of the ledger table
LEDGER_ROWS = [
    ("heater_fuel_chemical", "fuel-fired heater: fuel chemical energy"),
    ("heater_heat_to_coolant", "  of which heat into the heating loop (HT coolant of the convectors)"),
    ("heater_flue_loss", "  of which flue gas loss"),
    ("hvac_compressor", "A/C compressor shaft work"),
    ("hvac_electric", "HVAC electric energy (blowers, condenser fans, burner)"),
    ("cabin_coolant_heat", "cabin: heat from the coolant convectors"),
    ("cabin_people", "cabin: passengers' heat"),
    ("cabin_solar", "cabin: solar gain"),
    ("cabin_ac_cooling", "cabin: heat removed by the A/C"),
    ("cabin_body", "cabin: transmission through the body"),
    ("cabin_fresh_air", "cabin: fresh air"),
    ("cabin_doors", "cabin: door openings"),
    ("cabin_stored", "cabin: stored (C dT)"),
    ("cabin_residual", "cabin: residual of its balance"),
]


def hvac_plots(data, save, plt):
    """Adds hvac.png (cabin temperature, heating/cooling, heater) when the hvac ran."""
    h = data.get(HVAC_STATE)
    if h is None or len(h["t"]) < 2:
        return
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(12, 6), sharex=True)
    a1.plot(h["t"], h["cabin_temperature_k"] - K0, lw=0.9, label="cabin")
    a1.set(ylabel="temperature [°C]", title="Cabin and its HVAC")
    a1.legend()
    a2.plot(h["t"], h["coolant_heat_w"] / 1e3, lw=0.6, label="convector heat from the coolant")
    a2.plot(h["t"], h["aux_heater_heat_w"] / 1e3, lw=0.8, label="fuel-fired heater into the coolant")
    a2.plot(h["t"], h["ac_cooling_w"] / 1e3, lw=0.6, label="A/C cooling")
    a2.plot(h["t"], h["compressor_power_w"] / 1e3, lw=0.6, label="A/C compressor shaft")
    a2.set(xlabel="time [s]", ylabel="power [kW]")
    a2.legend(fontsize=8)
    save(fig, "hvac.png")
