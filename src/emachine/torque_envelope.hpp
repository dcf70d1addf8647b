// Torque envelopes of the e-machine at its own shaft (EM side, before the ratio stage).
//
// Peak envelope = the VECTO .vemp curve (drive T_d(n) >= 0, recuperation T_r(n) <= 0 vs EM speed
// n, measured/declared at the nominal DC voltage V_nom = 48 V). The file lists the points in the
// order VECTO wrote them (the generic 15 kW file has the 651.09 rpm corner before 648.70 rpm):
// they are sorted by speed; identical speeds with identical torques are merged, identical speeds
// with different torques are an InputError.
//   Between two points with ω_i > 0 the POWER P = T ω is interpolated linearly in ω, so every
//   data point is reproduced exactly and the envelope between the sparse high-speed points follows
//   the constant-power curve the data sample (linear-in-torque interpolation, VECTO's, would give
//   up to +23 % power between 1948 and 4865 rpm). On a segment starting at ω = 0 the torque is
//   interpolated linearly. Below the first point: its torque; above the last: its power held.
// Voltage (field-weakening approximation): the speed at which the inverter runs out of voltage
// scales with V_dc, so the whole curve is stretched along the speed axis by
//   s = min(V_dc, V_eff,max)/V_nom:   T_peak(ω, V) = u(V) · T_vemp(ω/s),
// i.e. the current-limited torque below the corner is unchanged, the corner speed moves ∝ V and
// the power above it scales ∝ V (it is a voltage/DC-current limit). u(V) = clamp((V − V_0)/
// (V_1 − V_0)) is the under-voltage cut-off of the 48 V system (LV 148: no function below 24 V,
// full function above 36 V).
// Continuous envelope (both directions): |T| <= T_cont and |T ω| <= s P_cont, and never above the
// peak envelope; T_cont = 220 Nm = P_cont / ω(651.09 rpm), the speed at which VECTO states the
// continuous power 15 kW (GenericEM parameters: continuous power 15 kW at 651 rpm).
#pragma once
#include <string>
#include <vector>

namespace hbt::emachine {

class TorqueEnvelope {
 public:
  TorqueEnvelope() = default;
  /// Reads and validates the .vemp file (columns n [rpm], T_drive [Nm], T_recuperation [Nm]).
  /// Throws InputError naming the file and the column.
  TorqueEnvelope(const std::string& vemp_path, double nominal_voltage_V, double max_effective_voltage_V,
                 double undervoltage_zero_V, double undervoltage_full_V, double continuous_power_W,
                 double continuous_torque_Nm);
  /// From tabulated points (speed [rad/s], drive >= 0, recuperation <= 0 [Nm]); `source` names
  /// the origin in errors.
  TorqueEnvelope(std::vector<double> speed_rad_s, std::vector<double> drive_Nm,
                 std::vector<double> recup_Nm, const std::string& source, double nominal_voltage_V,
                 double max_effective_voltage_V, double undervoltage_zero_V,
                 double undervoltage_full_V, double continuous_power_W, double continuous_torque_Nm);

  /// Peak drive torque >= 0 at EM speed w >= 0 and DC voltage V.
  double peakDrive(double w_rad_s, double V) const { return peak(w_rad_s, V, drive_); }
  /// Peak recuperation torque <= 0.
  double peakRecup(double w_rad_s, double V) const { return -peak(w_rad_s, V, recup_); }
  /// Continuous envelope magnitude (both directions), <= the respective peak.
  double continuousDrive(double w_rad_s, double V) const;
  double continuousRecup(double w_rad_s, double V) const;  // <= 0
  double speedScale(double V) const;        // s
  double undervoltageFactor(double V) const;  // u
  const std::vector<double>& speeds() const { return w_; }
  const std::vector<double>& drive() const { return drive_; }
  const std::vector<double>& recup() const { return recup_; }  // stored as magnitudes >= 0

 private:
  double peak(double w, double V, const std::vector<double>& T) const;
  double nominal(double w, const std::vector<double>& T) const;  // at s = 1, u = 1
  double continuousMagnitude(double w, double V) const;
  std::vector<double> w_, drive_, recup_;
  double V_nom_ = 48.0, V_max_ = 52.0, V0_ = 24.0, V1_ = 36.0, P_cont_ = 15e3, T_cont_ = 220.0;
};

}  // namespace hbt::emachine
