// Adapters between the turbocharger models (src/turbo) and the gas-dynamic turbomachine
// boundaries (gasdyn::CompressorOutlet / gasdyn::TurbineEntry), tabulated for speed.
//
// The gas-dynamic boundaries call massFlow() 5-15 times per time step (the face solution is
// iterated); the map look-ups of src/turbo cost 55-150 ns each, so the maps are re-gridded once
// at construction on regular grids and interpolated bilinearly (O(1), no allocation):
//
// Compressor (corrected speed N_c [rpm], pressure ratio PI = p_down/p0_up):
//   N_c = (30 omega/pi) / sqrt(T0/T_ref),  mdot = mdot_c(N_c, PI) (p0/p_ref) / sqrt(T0/T_ref)  [kg/s]
//   work coefficient w(N_c, PI) = dh/(cp T0) from the map; efficiency given to the boundary
//   eta = (PI^k - 1)/w, so that the boundary's T0_out = T0 (1 + (PI^k - 1)/eta) = T0 (1 + w)
//   exactly; for PI <= 1 (choke side, wheel windmilling) eta -> large, T0_out = T0.
// Turbine entry (reduced speed N_r = rpm/sqrt(T0), ER = p0/p_down):
//   mdot_e  = s Phi(N_r, ER) (p0/1000)/sqrt(T0)                          [kg/s], s = 0.5
//   mdot_wg = Cd a A_max p0/sqrt(R T0) psi(1/ER)   (wastegate, entry 0 only, opening a in [0,1])
//   massFlow = mdot_e + mdot_wg;  efficiency = eta_e(N_r, ER) mdot_e/(mdot_e + mdot_wg)
// With that efficiency the boundary's power mdot cp T0 eta (1 - ER^-k) is exactly the wheel
// power of the entry flow and its outlet enthalpy is the adiabatic mix of wheel exit and bypass.
// Tabulation error vs the direct look-up is checked in test_engine_1d_components.
#pragma once
#include <vector>

#include "gasdyn/turbo_boundaries.hpp"
#include "turbo/compressor.hpp"
#include "turbo/turbine.hpp"

namespace hbt::engine_1d {

/// Regular bilinear grid, clamped at the edges.
class Grid2D {
 public:
  Grid2D() = default;
  template <class F>
  Grid2D(double x0, double x1, int nx, double y0, double y1, int ny, F f)
      : x0_(x0), y0_(y0), dx_((x1 - x0) / (nx - 1)), dy_((y1 - y0) / (ny - 1)), nx_(nx), ny_(ny),
        v_(static_cast<std::size_t>(nx) * ny) {
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j) v_[i * ny + j] = f(x0 + i * dx_, y0 + j * dy_);
  }
  double operator()(double x, double y) const {
    double fx = (x - x0_) / dx_, fy = (y - y0_) / dy_;
    fx = fx < 0.0 ? 0.0 : (fx > nx_ - 1 ? nx_ - 1 : fx);
    fy = fy < 0.0 ? 0.0 : (fy > ny_ - 1 ? ny_ - 1 : fy);
    int i = static_cast<int>(fx), j = static_cast<int>(fy);
    if (i > nx_ - 2) i = nx_ - 2;
    if (j > ny_ - 2) j = ny_ - 2;
    fx -= i, fy -= j;
    const double* a = &v_[static_cast<std::size_t>(i) * ny_ + j];
    const double* b = a + ny_;
    return (1 - fx) * ((1 - fy) * a[0] + fy * a[1]) + fx * ((1 - fy) * b[0] + fy * b[1]);
  }

 private:
  double x0_ = 0, y0_ = 0, dx_ = 1, dy_ = 1;
  int nx_ = 2, ny_ = 2;
  std::vector<double> v_;
};

class CompressorFlowMap final : public gasdyn::FlowMap {
 public:
  /// speed unit: rad/s. n_speed x n_pr grid nodes.
  explicit CompressorFlowMap(const turbo::Compressor& c, int n_speed = 121, int n_pr = 241);
  double massFlow(double p0_up, double T0_up, double p_down, double speed) const override;
  double efficiency(double p0_up, double T0_up, double p_down, double speed) const override;
  /// 1 + work/(cp T0) from the map (= 1 + (pr^k - 1)/eta exactly, eta = (pr^k - 1)/work).
  double temperatureRatio(double p0_up, double T0_up, double p_down, double speed,
                          double k) const override;
  double maxCorrectedSpeed() const { return n_max_; }

 private:
  Grid2D flow_, work_;
  double p_ref_, T_ref_, k_, n_max_;
};

class TurbineFlowMap final : public gasdyn::FlowMap {
 public:
  /// One entry; `wastegate` may be null (entry without bypass). speed unit: rad/s.
  TurbineFlowMap(const turbo::TurbineEntry& entry, const turbo::Wastegate* wastegate,
                 int n_speed = 81, int n_er = 201);
  void setWastegateOpening(double a) { opening_ = a < 0.0 ? 0.0 : (a > 1.0 ? 1.0 : a); }
  double wastegateOpening() const { return opening_; }
  double massFlow(double p0_up, double T0_up, double p_down, double speed) const override;
  double efficiency(double p0_up, double T0_up, double p_down, double speed) const override;
  /// Wheel (entry) and bypass flows at a state [kg/s].
  void flows(double p0, double T0, double p_down, double speed, double& m_entry, double& m_wg) const;

 private:
  Grid2D mfp_, eta_;
  std::vector<double> psi_;  // nozzle function over pi = p_down/p0 on [0, 1]
  double share_, er_max_, wg_coeff_ = 0.0, R_;
  double opening_ = 0.0;
  bool has_wg_;
};

}  // namespace hbt::engine_1d
