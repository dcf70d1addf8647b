// vehicle_accel: full-load acceleration of the bus from standstill on the flat with the
// map-based engine (lock-step coupled at the macro step). Prints the 0-30 and 0-50 km/h times
// and every shift / lock-up event (time, engine speed before/after, vehicle speed). A gear
// change starts a slip phase "gS" (e.g. 1L->2S) that ends when the clutch has synchronised
// (2S->2L); the lock-up slip in 1C ends with 1C->1L.
//
//   vehicle_accel [--dt 0.01] [--payload 1500] [--vmax 80] [--base <package root>]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "common/units.hpp"
#include "vehicle/tools/coupled_sim.hpp"

using namespace hbt;

int main(int argc, char** argv) {
  double dt = 0.01, payload = 1500.0, vmax_kmh = 80.0;
  std::string base;
  if (const char* env = std::getenv("HBT_SOURCE_DIR")) base = env;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--dt")) dt = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--payload")) payload = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--vmax")) vmax_kmh = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--base")) base = argv[i + 1];
    else { std::fprintf(stderr, "unknown option %s\n", argv[i]); return 2; }
  }
  try {
    vehicle::VehicleParams vp;
    vp.chassis.payload_kg = payload;
    vehicle::CoupledSim sim(vp, engine_map::MapEngineParams{}, base);
    sim.reset(0.0, 0);
    vehicle::VehicleInputs in;
    in.driver_enabled = false;
    in.brake_pedal_cmd = 1.0;
    for (int k = 0; k < 100; ++k) sim.step(dt, in);  // 1 s held at idle in neutral
    std::printf("# full-load acceleration, m = %.0f kg, dt = %.3f s, idle %.0f rpm\n",
                vp.totalMass_kg(), dt, units::radpsToRpm(sim.vehicle().engine_speed_rad_s));
    std::printf("# event            t[s]  from->to  n_before[rpm] n_after[rpm]  v[km/h]\n");
    in.brake_pedal_cmd = 0.0;
    in.accel_pedal_cmd = 1.0;
    double t30 = -1, t50 = -1, t0 = sim.time();
    vehicle::DriveMode mode = sim.vehicle().mode;
    int gear = sim.vehicle().gear;
    double n_prev = sim.vehicle().engine_speed_rad_s;
    while (sim.time() - t0 < 120.0) {
      sim.step(dt, in);
      const auto& o = sim.vehicle();
      const double kmh = units::mpsToKmh(o.speed_m_s);
      if (o.mode != mode || o.gear != gear) {
        const char* what = o.gear != gear ? "shift (slip)"
                           : mode == vehicle::DriveMode::Shifting ? "synchronised"
                           : o.mode == vehicle::DriveMode::Locked ? "lock-up" : "unlock";
        auto name = [](vehicle::DriveMode m, int g) {
          static char b[8];
          std::snprintf(b, sizeof b, "%d%s", g,
                        m == vehicle::DriveMode::Converter ? "C"
                        : m == vehicle::DriveMode::Locked  ? "L"
                        : m == vehicle::DriveMode::Shifting ? "S" : "N");
          return std::string(b);
        };
        std::printf("  %-14s %6.2f  %3s->%-3s  %8.0f     %8.0f     %6.1f\n", what, sim.time() - t0,
                    name(mode, gear).c_str(), name(o.mode, o.gear).c_str(),
                    units::radpsToRpm(n_prev), units::radpsToRpm(o.engine_speed_rad_s), kmh);
        mode = o.mode;
        gear = o.gear;
      }
      n_prev = o.engine_speed_rad_s;
      if (t30 < 0 && kmh >= 30.0) t30 = sim.time() - t0;
      if (t50 < 0 && kmh >= 50.0) t50 = sim.time() - t0;
      if (kmh >= vmax_kmh) break;
    }
    std::printf("t(0-30 km/h) = %.2f s\nt(0-50 km/h) = %.2f s\n", t30, t50);
    std::printf("fuel %.3f kg, engine work %.2f MJ, energy residual %.3g J\n",
                sim.engine().fuel_mass_kg, sim.vehicle().energy.engine_J / 1e6,
                sim.vehicle().energy.residual_J());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vehicle_accel: %s\n", e.what());
    return 1;
  }
  return 0;
}
