"""The aftertreatment's inputs of a recorded run, for `ats_replay` (src/aftertreatment/bench/).

    python3 -m twin_tools.bench.ats_trace RUN/run.bag TRACE.txt

Writes one line per recorded 0.1 s sample: the stamp [ns], the engine's cumulative totals and
point values (ExhaustState: mass, mass x temperature, temperature x time, O2, CO2, H2O, NOx, HC,
CO; flow, temperature, O2/CO2/H2O fractions, NOx/HC/CO flows) and the vehicle's distance, speed and
ambient temperature (VehicleToCooling), in the order ats_replay reads them, every number in
repr() (no rounding). Prints the run's final tailpipe NOx and NH3 slip from
/aftertreatment/state: a replay with the run's config gives the same values.
"""
import sys

from twin_tools.bags.reader import BagError, open_bag

EXHAUST = ("mass_kg", "mass_temperature_kg_k", "temperature_time_k_s", "o2_mass_kg", "co2_mass_kg",
           "h2o_mass_kg", "nox_mass_kg", "hc_mass_kg", "co_mass_kg", "mass_flow_kg_s", "temperature_k",
           "y_o2", "y_co2", "y_h2o", "nox_mass_flow_kg_s", "hc_mass_flow_kg_s", "co_mass_flow_kg_s")
VEHICLE = ("distance_m", "vehicle_speed_m_s", "ambient_temperature_k")


def export(bag_path, out_path):
    """Writes the trace; returns (samples, final AftertreatmentState or None)."""
    exhaust, vehicle, last = {}, {}, None
    with open_bag(bag_path) as bag:
        for topic, m, _ in bag.read_messages(topics=["/engine/exhaust", "/vehicle/to_cooling",
                                                     "/aftertreatment/state"]):
            stamp = m.header.stamp.to_nsec()
            if topic == "/engine/exhaust":
                exhaust[stamp] = [getattr(m, f) for f in EXHAUST]
            elif topic == "/vehicle/to_cooling":
                vehicle[stamp] = [getattr(m, f) for f in VEHICLE]
            else:
                last = m
    stamps = sorted(s for s in exhaust if s in vehicle)
    if len(stamps) < 2:
        raise BagError("%s: fewer than two samples with both /engine/exhaust and /vehicle/to_cooling" % bag_path)
    with open(out_path, "w") as f:
        f.write("# t_ns %s %s\n" % (" ".join(EXHAUST), " ".join(VEHICLE)))
        for s in stamps:
            f.write(" ".join([str(s)] + [repr(float(v)) for v in exhaust[s] + vehicle[s]]) + "\n")
    return len(stamps), last


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    try:
        n, last = export(argv[1], argv[2])
    except BagError as e:
        sys.stderr.write("ats_trace: %s\n" % e)
        return 1
    print("%d samples -> %s" % (n, argv[2]))
    if last is not None:
        print("run's final tailpipe NOx %.9f g, NH3 slip %.9f g" % (1e3 * last.tailpipe_nox_mass_kg,
                                                                    1e3 * last.nh3_slip_mass_kg))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
