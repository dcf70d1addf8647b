// Internal and solar heat gains of the cabin, after the VECTO BusAuxiliaries HVAC steady-state
// model (SSM). ROS-free.
//
//   persons    N = payload / m_passenger + crew                                             [-]
//   Q̇_people = N q_person(T_a),  q_person = q_cold if T_a < T_b else q_warm                 [W]
//   A_window   = a_side L + A_front+rear                                                    [m^2]
//   Q̇_sun    = I(T_a) A_window g f_cloud(T_a) f_orient,  f_cloud = c_cold if T_a < T_b else c_warm [W]
// I(T_a): irradiance [W/m^2] interpolated linearly over the ambient (VECTO's default climatic
// conditions pair each ambient temperature with a solar load), held beyond the table ends.
#pragma once
#include "common/table1d.hpp"
#include "hvac/hvac_params.hpp"

namespace hbt::hvac {

class CabinGains {
 public:
  CabinGains(const GainParams& g, const CabinParams& c, double payload_kg, const std::string& file);
  double persons() const { return persons_; }
  double windowArea_m2() const { return window_m2_; }
  double people_W(double ambient_T_K) const;
  double solar_W(double ambient_T_K) const;

 private:
  GainParams g_;
  CabinParams c_;
  Table1D irradiance_;
  double persons_ = 0.0, window_m2_ = 0.0;
};

}  // namespace hbt::hvac
