// Pipe description (PipeConfig) and the discretised geometry shared by both solvers (PipeGeometry).
//
// Mesh: `cells` equal cells of length dx = L/cells [m]; faces j = 0..cells at x_j = j dx, cell
// centres at x_i = (i + 1/2) dx. Diameter D [m] is given at the faces (linear taper between
// diameter_left and diameter_right, or the explicit face_diameters list); face area
// A_f = pi D^2/4 [m^2], cell area A_c = (A_f,i + A_f,i+1)/2, cell volume V_i = A_c,i dx [m^3].
// Wall friction: Darcy factor f_D (= 4 x Fanning), wall shear force per unit length
//   F_w = - f_D/(2 D) rho u |u| A   [N/m].
// Wall heat transfer per unit length q_w = h pi D (T_wall - T) [W/m], with h [W/(m^2 K)] either
// given or from the Reynolds analogy St = f_D/8: h = (f_D/8) rho |u| cp.
#pragma once
#include <string>
#include <vector>

namespace hbt::gasdyn {

enum class SolverKind { FSM, TVD };
enum class Limiter { Minmod, VanLeer, Superbee };
enum class WallHeat { None, ReynoldsAnalogy, GivenCoefficient };

struct PipeConfig {
  std::string name = "pipe";
  double length = 1.0;  // [m]
  int cells = 10;
  double diameter_left = 0.05;   // [m] at x = 0
  double diameter_right = 0.05;  // [m] at x = L
  std::vector<double> face_diameters;  // optional, cells+1 values [m]; overrides the taper
  double friction_darcy = 0.0;         // Darcy friction factor [-]
  WallHeat heat = WallHeat::None;
  double h_wall = 0.0;    // [W/(m^2 K)] for GivenCoefficient
  double T_wall = 300.0;  // [K]
  double cfl = 0.9;       // Courant number used for the stable time step [-]
  SolverKind solver = SolverKind::FSM;
  Limiter limiter = Limiter::VanLeer;  // TVD only
  double entropy_fix = 0.1;            // TVD: Harten delta as a fraction of the Roe sound speed
  // FSM artificial (bulk) viscosity q = rho (c2 du^2 + c1 c |du|) in compression [Pa]
  double fsm_visc_linear = 0.1;
  double fsm_visc_quadratic = 0.5;
};

struct PipeGeometry {
  int n = 0;         // cells
  double dx = 0.0;   // [m]
  std::vector<double> A_face, D_face;          // n+1 [m^2], [m]
  std::vector<double> A_cell, D_cell, V_cell;  // n [m^2], [m], [m^3]

  /// Validates the config; throws hbt::InputError(pipe name, key, what).
  static PipeGeometry build(const PipeConfig& cfg);
};

}  // namespace hbt::gasdyn
