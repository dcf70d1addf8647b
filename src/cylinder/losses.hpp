// Wall heat transfer (Woschni 1967) and friction (Chen & Flynn 1965) of one cylinder.
//
// Woschni:  h = C_0 B^−0.2 p^0.8 T^−0.55 w^0.8          [W/(m² K)], B [m], p [kPa], T [K], w [m/s]
//   w = C_1 c_m + C_2 (V_d T_r / (p_r V_r)) (p − p_mot)  characteristic gas velocity [m/s]
//   C_0 = 3.26; C_1 = 6.18 + 0.417 c_u/c_m (gas exchange), 2.28 + 0.308 c_u/c_m (closed cycle),
//   c_u/c_m = R_s π B/(2 S) for swirl ratio R_s; C_2 = 0 before start of combustion and
//   3.24e−3 m/(s K) from start of combustion to exhaust-valve opening. The reference state
//   (p_r, V_r, T_r) is the state at inlet-valve closure, p_mot = p_r (V_r/V)^n_r the motored
//   pressure with the polytropic exponent n_r = γ at IVC.
// Hohenberg 1979 (alternative, developed on DI truck diesels; correlation: hohenberg):
//   h = C_H V^−0.06 p^0.8 T^−0.4 (c_m + 1.4)^0.8          [W/(m² K)], V [m³], p [bar], T [K],
//   C_H = 130; c_m mean piston speed [m/s]. Its "+1.4 m/s" keeps a convective floor at low
//   speed where Woschni's c_m^0.8 falls off (Woschni is known to under-predict at low speed and
//   load); no combustion term (the pressure and temperature carry it).
// Heat flux to each surface s:  Q̇_s = h A_s (T_gas − T_s)   [W].
// Wall temperatures follow the coolant (an input) and the load (fuel per cycle / reference fuel):
//   T_s = T_coolant + ΔT_s,0 + ΔT_s,load · load.
//
// Chen–Flynn friction mean effective pressure with an oil-viscosity (coolant temperature) factor:
//   FMEP = [A + B p_max + C c_m + D c_m²] · (μ(T_oil)/μ(T_oil,ref))^n_μ    [bar], p_max [bar]
//   μ(T) ∝ exp(b/(T − c)) (Vogel), T_oil the oil temperature given (the cooling node's oil
//   node in the twin), or T_coolant + ΔT_oil where none is given.
//   Friction torque of one cylinder: M_f = FMEP V_d / (4π)  [N m].
#pragma once

namespace hbt::cylinder {

/// Woschni heat-transfer coefficient [W/(m² K)] (p in Pa, converted to kPa inside).
double woschniCoefficient(double bore_m, double p_Pa, double T_K, double w_m_s, double C0 = 3.26);

/// Hohenberg heat-transfer coefficient [W/(m² K)] (V [m³], p [Pa], T [K], c_m [m/s]).
double hohenbergCoefficient(double V_m3, double p_Pa, double T_K, double cm_m_s, double C_H = 130.0);

struct WoschniParams {
  double C0 = 3.26;
  double swirl_ratio = 1.5;
  double C2_m_sK = 3.24e-3;
  double multiplier = 1.0;  // calibration factor on h
  bool hohenberg = false;   // correlation: false = Woschni, true = Hohenberg (key "correlation")
  double hohenberg_C = 130.0;  // Hohenberg constant C_H
  /// Characteristic velocity [m/s]. gas_exchange: valves open; combustion: after start of combustion.
  double velocity(bool gas_exchange, bool combustion, double cm, double bore_m, double stroke_m,
                  double Vd, double Tr, double pr, double Vr, double p, double pmot) const;
};

struct WallTemperatures {
  double head_dT0_K = 110.0, head_dTload_K = 90.0;     // fire deck ≈ coolant + 110…200 K
  double liner_dT0_K = 40.0, liner_dTload_K = 50.0;    // liner top  ≈ coolant + 40…90 K
  double piston_dT0_K = 180.0, piston_dTload_K = 130.0;  // oil-cooled crown ≈ coolant + 180…310 K
  void evaluate(double T_coolant_K, double load, double& head, double& liner, double& piston) const;
};

struct ChenFlynn {
  double A_bar = 0.10;
  double B = 0.005;                 // bar per bar of peak pressure
  double C_bar_s_m = 0.13;
  double D_bar_s2_m2 = 0.0015;
  double visc_exponent = 0.25;
  double vogel_b_K = 1170.0, vogel_c_K = 150.0;  // 15W-40-like: ν40/ν100 ≈ 6.9
  double T_oil_ref_K = 363.15;
  double oil_minus_coolant_K = 5.0;
  double viscosityFactor(double T_coolant_K) const;
  /// FMEP [Pa] for peak pressure [Pa], mean piston speed [m/s] and coolant temperature [K].
  double fmep_Pa(double pmax_Pa, double cm_m_s, double T_coolant_K) const;
  /// FMEP [Pa] for peak pressure [Pa], mean piston speed [m/s] and oil temperature [K].
  double fmepAtOil_Pa(double pmax_Pa, double cm_m_s, double T_oil_K) const;
};

}  // namespace hbt::cylinder
