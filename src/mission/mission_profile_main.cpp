// mission_profile: command-line front end of the mission pre-processor.
//
//   mission_profile --cycle config/data/cycles/vecto/Urban.vdri --out profile.csv [--dt 0.1]
//                   [--vacc <file.vacc>] [--ds 0.25] [--mass-kg 16660] [--power-kw 160]
//                   [--no-lac] [--no-overspeed]
// Defaults are those of hbt::mission::MissionParams. Prints a summary (duration, distance,
// stops served, max acceleration/deceleration). Exit 0 ok, 1 bad input data, 2 usage error.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "common/errors.hpp"
#include "mission/mission_preprocessor.hpp"

namespace {

void usage(std::FILE* to) {
  std::fprintf(to,
      "usage: mission_profile --cycle <cycle.vdri> --out <profile.csv> [options]\n"
      "  --dt <s>          output sample time [s] (default 0.1)\n"
      "  --vacc <file>     driver acceleration limits .vacc (default Bus.vacc of the repo)\n"
      "  --ds <m>          distance grid step of the planner [m] (default 0.25)\n"
      "  --mass-kg <kg>    vehicle mass [kg] (default 16660)\n"
      "  --power-kw <kW>   max traction power at the wheels [kW], 0 = none (default 160)\n"
      "  --no-lac          disable look-ahead coasting\n"
      "  --no-overspeed    disable downhill overspeed\n"
      "  --help            this text\n");
}

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double number(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') throw UsageError(flag + " expects a number, got '" + text + "'");
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hbt::mission;
  MissionParams p;
  p.cycle_file.clear();
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw UsageError(a + " needs a value");
        return argv[++i];
      };
      if (a == "--help" || a == "-h") { usage(stdout); return 0; }
      else if (a == "--cycle") p.cycle_file = value();
      else if (a == "--out") p.profile_csv_file = value();
      else if (a == "--vacc") p.accel_limits_file = value();
      else if (a == "--dt") p.dt_s = number(a, value());
      else if (a == "--ds") p.ds_max_m = number(a, value());
      else if (a == "--mass-kg") p.vehicle.mass_kg = number(a, value());
      else if (a == "--power-kw") p.vehicle.max_wheel_power_W = 1e3 * number(a, value());
      else if (a == "--no-lac") p.driver.lac_enabled = false;
      else if (a == "--no-overspeed") p.driver.overspeed_enabled = false;
      else throw UsageError("unknown argument '" + a + "'");
    }
    if (p.cycle_file.empty()) throw UsageError("--cycle is required");
    if (p.profile_csv_file.empty()) throw UsageError("--out is required");
    if (!(p.dt_s > 0.0) || p.dt_s > 10.0) throw UsageError("--dt must be in (0, 10] s");
    if (!(p.ds_max_m > 0.0) || p.ds_max_m > 10.0) throw UsageError("--ds must be in (0, 10] m");
    if (!(p.vehicle.mass_kg > 0.0)) throw UsageError("--mass-kg must be > 0");
    if (p.vehicle.max_wheel_power_W < 0.0) throw UsageError("--power-kw must be >= 0");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "mission_profile: %s\n", e.what());
    usage(stderr);
    return 2;
  }
  try {
    const MissionProfile prof = buildMissionProfile(p);
    const ProfileSummary s = prof.summary();
    std::printf("cycle          %s\n", p.cycle_file.c_str());
    std::printf("profile        %s (%zu samples, dt = %g s)\n", p.profile_csv_file.c_str(),
                prof.samples().size(), p.dt_s);
    std::printf("duration       %.1f s\n", s.duration_s);
    std::printf("distance       %.1f m (cycle length %.1f m)\n", s.distance_m,
                prof.cycle().length_m());
    std::printf("stops served   %zu of %zu (standing %.1f s, cycle stop time %.1f s)\n",
                s.stops_served, s.stops_in_cycle, s.standing_time_s,
                prof.cycle().totalStopTime_s());
    std::printf("max speed      %.2f km/h\n", s.max_speed_m_s * 3.6);
    std::printf("max accel      %.3f m/s2\n", s.max_accel_m_s2);
    std::printf("max decel      %.3f m/s2\n", s.max_decel_m_s2);
    std::printf("mean speed     %.2f km/h (incl. stops)\n",
                s.duration_s > 0 ? 3.6 * s.distance_m / s.duration_s : 0.0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mission_profile: %s\n", e.what());
    return 1;
  }
  return 0;
}
