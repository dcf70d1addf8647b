// Compressor map in corrected quantities, with validation, scaling and extrapolation.
//
// Quantities (reference state p_ref, T_ref of the map):
//   corrected speed  N_c = N √(T_ref/T_1)                    [rpm]
//   corrected flow   ṁ_c = ṁ √(T_1/T_ref) / (p_1/p_ref)       [kg/s]
//   pressure ratio   Π = p_2/p_1 (total-to-total)              [-]
//   isentropic head  h_s = Π^k − 1, k = (γ−1)/γ                [-]   (Δh_s = c_p T_1 h_s)
//   work coefficient w = Δh/(c_p T_1)                          [-]   (T_2 = T_1 (1 + w))
// Inside the map w = h_s/η, i.e. T_2 = T_1 (1 + (Π^k − 1)/η).
//
// Representation: every speed line is sorted by flow (surge end first) and parametrised by its
// point index β = k/(n−1) ∈ [0,1]; all lines are resampled onto the union of their β break
// points, so each measured point is a grid node and is reproduced exactly. Between lines:
// linear in N_c at fixed β (ṁ_c, h_s, η). Outside the measured lines (below the lowest, above
// the highest, down to N = 0): similarity laws at fixed β from the end line N_e:
//   ṁ_c = ṁ_c,e · (N/N_e),   h_s = h_s,e · (N/N_e)²,   η = η_e.
// Along a line at given Π:
//   surge side (Π above the surge point): ṁ_c falls linearly in h_s from the surge flow to 0 at
//     the shut-off head h_s,0 = r_shut · h_s,surge; ṁ_c = 0 above it (no reverse flow); η = η_surge.
//   choke side (Π below the last point): choked, ṁ_c = ṁ_c,end (the choke-line value), but
//     never below the flow of the stationary wheel acting as an orifice for a pressure drop:
//     ṁ_c = max(ṁ_c,end, K_th √(min(1 − Π, 1 − π*))),  K_th from throttle_flow_fraction.
//     (At N = 0 this is the orifice law ṁ_c ∝ √Δp, choked at π*.) The wheel work stays at the
//     choke-end value (w = w_end), so the temperature rise stays ≥ 0 (= 0 at N = 0: throttle).
//   A measured line that stops short of the choke flow of the line below it is continued along
//     its last segment until it passes that flow (one added point; measured points unchanged).
// Efficiency is floored at η_floor. No NaN, no negative flow for N ≥ 0, Π > 0.
// Look-ups: O(log n) binary searches over the precomputed grid, one or two pow(), no allocation.
#pragma once
#include <string>
#include <vector>

#include "common/perfect_gas.hpp"

namespace hbt::turbo {

struct CompressorMapFormat {
  std::string col_speed = "speed";           // [rpm]
  std::string col_flow = "mass_flow";        // corrected [kg/s]
  std::string col_pr = "pressure_ratio";     // total-to-total [-]
  std::string col_eff = "efficiency";        // isentropic total-to-total [-]
};

struct CompressorMapOptions {
  double gamma = 1.4;                // air [-]
  double eta_floor = 0.30;           // lower bound of the returned efficiency [-]
  double shutoff_head_ratio = 1.10;  // h_s at zero flow / h_s at the surge point [-]
  double throttle_flow_fraction = 0.5;  // stationary wheel: ṁ_c at critical drop / max map flow
};

struct CompressorLine {
  double speed_rpm = 0.0;                   // corrected speed [rpm]
  std::vector<double> flow, pr, eta;        // sorted by flow, surge end first
};

class CompressorMap {
 public:
  enum Region : int { kInside = 0, kSurgeSide = 1, kShutOff = 2, kChokeSide = 4,
                      kBelowLines = 8, kAboveLines = 16 };
  struct Point {
    double flow_kg_s = 0.0;   // corrected flow [kg/s]
    double eta = 0.0;         // isentropic efficiency [-]
    double work = 0.0;        // w = Δh/(c_p T_1) [-]
    int region = kInside;     // bit set of Region
  };

  CompressorMap() = default;
  /// Reads the CSV (hbt::CsvTable), validates it; errors name the file and the column.
  static CompressorMap read(const std::string& path, const CompressorMapFormat& fmt = {},
                            const CompressorMapOptions& opt = {});
  /// From lines in any order (each with ≥ 2 points); `source` names them in errors.
  CompressorMap(std::vector<CompressorLine> lines, const CompressorMapOptions& opt,
                const std::string& source, const CompressorMapFormat& fmt = {});

  /// Geometric similarity: ṁ_c × f, N_c × 1/√f (Π and η kept). Cumulative.
  void scale(double flow_factor);

  /// Corrected flow, efficiency and work coefficient at corrected speed [rpm] and Π [-].
  Point atPressureRatio(double speed_rpm, double pr) const;

  /// Maximum-efficiency point of every measured line: (Π, ṁ_c) ordered by speed.
  void ridge(std::vector<double>& pr, std::vector<double>& flow) const;

  const std::vector<CompressorLine>& lines() const { return lines_; }
  const std::string& source() const { return source_; }
  double gamma() const { return gas_.gamma; }
  double maxFlow() const;          // largest corrected flow of the (scaled) map [kg/s]
  double throttleCoefficient() const { return k_th_; }  // K_th [kg/s]

 private:
  struct Sel { int i0, i1; double w, sm, sh; };
  Sel select(double speed_rpm, int& region) const;
  void node(const Sel& s, int j, double& m, double& hs, double& eta) const;
  void build(const CompressorMapFormat& fmt);

  std::string source_;
  CompressorMapOptions opt_;
  PerfectGas gas_;
  std::vector<CompressorLine> lines_;
  std::vector<double> beta_;              // union grid [M]
  std::vector<double> speed_;             // [L]
  std::vector<double> m_, hs_, eta_;      // [L × M], row-major by line
  double k_th_ = 0.0;
};

}  // namespace hbt::turbo
