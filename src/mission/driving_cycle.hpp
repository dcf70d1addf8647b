// Distance-based VECTO driving cycle (.vdri): reader, validation and road-geometry look-ups.
//
// File format (VECTO DistanceBasedDrivingCycle, CSV, '#' comments):
//   <s> [m]  distance along the road,   strictly increasing (only change points are stored)
//   <v> [km/h] target vehicle speed,    0 <= v <= 250
//   <grad> [%] road gradient,           |grad| <= 30
//   <stop> [s] stop (dwell) time,       >= 0; only allowed on rows with v = 0
// Semantics (VECTO): the values of the LEFT sample apply from its <s> up to the next sample.
// A row with v = 0 is a stop point: the vehicle comes to rest exactly at that <s>, stands for
// <stop> seconds, then drives off with the target speed of the NEXT row (as VECTO's
// DrivingCycleDataReader does). If the next row is itself a stop point (two stops in a row, e.g.
// Construction s = 8491/8524 m, HeavyUrban 10410/10502 m), the next POSITIVE target ahead is
// used: the vehicle then drives to the next stop as fast as its limits allow over that short gap.
// "Stops" in summaries are rows with v = 0 and stop > 0 (the 121 stops of Urban).
// Altitude (as VECTO): z(s_0) = 0, z(s_{k+1}) = z(s_k) + (s_{k+1} - s_k) * grad_k / 100 [m],
// piecewise linear in s (grade constant on each interval, from the left sample).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace hbt::mission {

struct DrivingCycle {
  std::string source;                   // file the cycle was read from (for messages)
  std::vector<double> distance_m;       // s_k [m], strictly increasing
  std::vector<double> target_speed_m_s; // v_k [m/s] as written (0 on stop rows)
  std::vector<double> grade_percent;    // grad_k [%] (applies on [s_k, s_{k+1}))
  std::vector<double> stop_time_s;      // stop_k [s]
  std::vector<double> altitude_m;       // z_k [m], integrated from grad, z_0 = 0

  std::size_t size() const { return distance_m.size(); }
  double startDistance_m() const { return distance_m.front(); }
  double endDistance_m() const { return distance_m.back(); }
  double length_m() const { return distance_m.back() - distance_m.front(); }
  /// Row k is a stop point (v = 0): the vehicle must be at rest there.
  bool isStopPoint(std::size_t k) const { return target_speed_m_s[k] <= 0.0; }
  /// Number of rows with v = 0 and stop > 0.
  std::size_t stopCount() const;
  /// Sum of the stop times [s].
  double totalStopTime_s() const;
  /// Target speed [m/s] on the interval that starts at row k (after a stop point: the next
  /// positive target ahead; 0 if there is none).
  double intervalTarget_m_s(std::size_t k) const;
  /// Index k of the interval [s_k, s_{k+1}) holding s (clamped to the first/last row).
  std::size_t intervalIndex(double s_m) const;
  /// Road gradient [%] at distance s (left sample; constant extrapolation outside).
  double gradeAt(double s_m) const;
  /// Altitude [m] at distance s (linear between samples; constant extrapolation outside).
  double altitudeAt(double s_m) const;
};

/// Sanity limits of the reader (documented constants).
constexpr double kMaxAbsGrade_percent = 30.0;
constexpr double kMaxTargetSpeed_kmh = 250.0;

/// Reads and validates a .vdri file. Throws hbt::InputError(file, column/line, what) for a
/// missing file, missing column, truncated row, NaN, distance not strictly increasing,
/// negative speed or stop time, |grad| > 30 %, stop time on a row with v > 0, < 2 rows.
DrivingCycle readVdri(const std::string& path);

/// Builds a cycle from columns already in memory (same validation; `source` names it in errors).
/// Speeds in km/h as in the file format.
DrivingCycle makeCycle(const std::string& source, const std::vector<double>& s_m,
                       const std::vector<double>& v_kmh, const std::vector<double>& grad_percent,
                       const std::vector<double>& stop_s);

}  // namespace hbt::mission
