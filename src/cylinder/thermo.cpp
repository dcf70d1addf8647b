#include "cylinder/thermo.hpp"

#include <cmath>
#include <limits>

namespace hbt::cylinder {
namespace {

// GRI-Mech 3.0 thermo data (TPIS/Burcat); C12H23 Jet-A(g) from Burcat's database.
// Each species: name, M [kg/mol], low-range coefficients, high-range coefficients, nC nH nO nN.
// Molar masses are sums of the element masses C 12.011, H 1.008, O 15.999, N 14.007, Ar 39.948
// g/mol, so that element and mass balances of the groups close exactly.
const Nasa7 kData[kNumSpecies] = {
    {"N2", 28.014e-3,
     {3.29867700E+00, 1.40824040E-03, -3.96322200E-06, 5.64151500E-09, -2.44485400E-12,
      -1.02089990E+03, 3.95037200E+00},
     {2.92664000E+00, 1.48797680E-03, -5.68476000E-07, 1.00970380E-10, -6.75335100E-15,
      -9.22797700E+02, 5.98052800E+00},
     0, 0, 0, 2},
    {"O2", 31.998e-3,
     {3.78245636E+00, -2.99673416E-03, 9.84730201E-06, -9.68129509E-09, 3.24372837E-12,
      -1.06394356E+03, 3.65767573E+00},
     {3.28253784E+00, 1.48308754E-03, -7.57966669E-07, 2.09470555E-10, -2.16717794E-14,
      -1.08845772E+03, 5.45323129E+00},
     0, 0, 2, 0},
    {"AR", 39.948e-3,
     {2.5, 0, 0, 0, 0, -7.45375000E+02, 4.36600000E+00},
     {2.5, 0, 0, 0, 0, -7.45375000E+02, 4.36600000E+00},
     0, 0, 0, 0},
    {"CO2", 44.009e-3,
     {2.35677352E+00, 8.98459677E-03, -7.12356269E-06, 2.45919022E-09, -1.43699548E-13,
      -4.83719697E+04, 9.90105222E+00},
     {3.85746029E+00, 4.41437026E-03, -2.21481404E-06, 5.23490188E-10, -4.72084164E-14,
      -4.87591660E+04, 2.27163806E+00},
     1, 0, 2, 0},
    {"H2O", 18.015e-3,
     {4.19864056E+00, -2.03643410E-03, 6.52040211E-06, -5.48797062E-09, 1.77197817E-12,
      -3.02937267E+04, -8.49032208E-01},
     {3.03399249E+00, 2.17691804E-03, -1.64072518E-07, -9.70419870E-11, 1.68200992E-14,
      -3.00042971E+04, 4.96677010E+00},
     0, 2, 1, 0},
    {"CO", 28.010e-3,
     {3.57953347E+00, -6.10353680E-04, 1.01681433E-06, 9.07005884E-10, -9.04424499E-13,
      -1.43440860E+04, 3.50840928E+00},
     {2.71518561E+00, 2.06252743E-03, -9.98825771E-07, 2.30053008E-10, -2.03647716E-14,
      -1.41518724E+04, 7.81868772E+00},
     1, 0, 1, 0},
    {"H2", 2.016e-3,
     {2.34433112E+00, 7.98052075E-03, -1.94781510E-05, 2.01572094E-08, -7.37611761E-12,
      -9.17935173E+02, 6.83010238E-01},
     {3.33727920E+00, -4.94024731E-05, 4.99456778E-07, -1.79566394E-10, 2.00255376E-14,
      -9.50158922E+02, -3.20502331E+00},
     0, 2, 0, 0},
    {"OH", 17.007e-3,
     {3.99201543E+00, -2.40131752E-03, 4.61793841E-06, -3.88113333E-09, 1.36411470E-12,
      3.61508056E+03, -1.03925458E-01},
     {3.09288767E+00, 5.48429716E-04, 1.26505228E-07, -8.79461556E-11, 1.17412376E-14,
      3.85865700E+03, 4.47669610E+00},
     0, 1, 1, 0},
    {"H", 1.008e-3,
     {2.50000000E+00, 7.05332819E-13, -1.99591964E-15, 2.30081632E-18, -9.27732332E-22,
      2.54736599E+04, -4.46682853E-01},
     {2.50000001E+00, -2.30842973E-11, 1.61561948E-14, -4.73515235E-18, 4.98197357E-22,
      2.54736599E+04, -4.46682914E-01},
     0, 1, 0, 0},
    {"O", 15.999e-3,
     {3.16826710E+00, -3.27931884E-03, 6.64306396E-06, -6.12806624E-09, 2.11265971E-12,
      2.91222592E+04, 2.05193346E+00},
     {2.56942078E+00, -8.59741137E-05, 4.19484589E-08, -1.00177799E-11, 1.22833691E-15,
      2.92175791E+04, 4.78433864E+00},
     0, 0, 1, 0},
    {"N", 14.007e-3,
     {2.5, 0, 0, 0, 0, 5.61046370E+04, 4.19390870E+00},
     {2.41594290E+00, 1.74890650E-04, -1.19023690E-07, 3.02262450E-11, -2.03609820E-15,
      5.61337730E+04, 4.64960960E+00},
     0, 0, 0, 1},
    {"NO", 30.006e-3,
     {4.21847630E+00, -4.63897600E-03, 1.10410220E-05, -9.33613540E-09, 2.80357700E-12,
      9.84462300E+03, 2.28084640E+00},
     {3.26060560E+00, 1.19110430E-03, -4.29170480E-07, 6.94576690E-11, -4.03360990E-15,
      9.92097460E+03, 6.36930270E+00},
     0, 0, 1, 1},
    {"C12H23", 167.316e-3,
     {2.08692170E+00, 1.33149650E-01, -8.11574520E-05, 2.94092860E-08, -6.51952130E-12,
      -3.59128140E+04, 2.73552890E+01},
     {2.48802010E+01, 7.82500480E-02, -3.15509730E-05, 5.78789000E-09, -3.98279680E-13,
      -4.31106840E+04, -9.36552550E+01},
     12, 23, 0, 0},
};

constexpr double kTmid = 1000.0;
constexpr double kMC = 12.011e-3, kMH = 1.008e-3;

inline const double* range(const Nasa7& d, double T) { return T < kTmid ? d.lo : d.hi; }

}  // namespace

const Nasa7& species(Species s) { return kData[s]; }

double cpR(Species s, double T) {
  const double* a = range(kData[s], T);
  return a[0] + T * (a[1] + T * (a[2] + T * (a[3] + T * a[4])));
}
double hRT(Species s, double T) {
  const double* a = range(kData[s], T);
  return a[0] + T * (a[1] / 2 + T * (a[2] / 3 + T * (a[3] / 4 + T * a[4] / 5))) + a[5] / T;
}
double sR(Species s, double T) {
  const double* a = range(kData[s], T);
  return a[0] * std::log(T) + T * (a[1] + T * (a[2] / 2 + T * (a[3] / 3 + T * a[4] / 4))) + a[6];
}
double gRT(Species s, double T) { return hRT(s, T) - sR(s, T); }

GasThermo::GasThermo(const FuelSpec& fuel, bool constant_cp, double T_const) : fuel_(fuel) {
  // Air by mole -> mass fractions.
  const double xAir[4] = {0.78084, 0.20946, 0.00934, 0.00036};
  const Species sAir[4] = {kN2, kO2, kAr, kCO2};
  double M_air = 0.0;
  for (int i = 0; i < 4; ++i) M_air += xAir[i] * kData[sAir[i]].M;
  for (int i = 0; i < 4; ++i) Y_[kAir][sAir[i]] = xAir[i] * kData[sAir[i]].M / M_air;
  // Fuel vapour (surrogate formula for stoichiometry, C12H23 polynomial per kg for cp).
  M_fuel_ = fuel.nC * kMC + fuel.nH * kMH;
  Y_[kFuelVap][kFuel] = 1.0;
  // Stoichiometric products per mol fuel: nC CO2 + nH/2 H2O + air inerts.
  const double nO2 = fuel.nC + fuel.nH / 4.0;
  const double nAirMol = nO2 / xAir[1];
  afr_st_ = nAirMol * M_air / M_fuel_;
  double mol[kNumSpecies] = {};
  mol[kN2] = nAirMol * xAir[0];
  mol[kAr] = nAirMol * xAir[2];
  mol[kCO2] = nAirMol * xAir[3] + fuel.nC;
  mol[kH2O] = fuel.nH / 2.0;
  double mtot = 0.0;
  for (int s = 0; s < kNumSpecies; ++s) mtot += mol[s] * kData[s].M;
  for (int s = 0; s < kNumSpecies; ++s) Y_[kBurned][s] = mol[s] * kData[s].M / mtot;

  for (int g = 0; g < kNumGroups; ++g) {
    Poly& P = group_[g];
    double habs_lo = 0.0;
    for (int s = 0; s < kNumSpecies; ++s) {
      const double Y = Y_[g][s];
      if (Y == 0.0) continue;
      const double w = Y * kRu / kData[s].M;
      for (int k = 0; k < 6; ++k) {
        P.lo[k] += w * kData[s].lo[k];
        P.hi[k] += w * kData[s].hi[k];
      }
      P.R += w;
      if (g != kFuelVap) {
        elem_[g][0] += Y / kData[s].M * kData[s].nC;
        elem_[g][1] += Y / kData[s].M * kData[s].nH;
        elem_[g][2] += Y / kData[s].M * kData[s].nO;
        elem_[g][3] += Y / kData[s].M * kData[s].nN;
        if (s == kAr) elem_[g][4] += Y / kData[s].M;
      }
    }
    if (g == kFuelVap) {  // the surrogate's own molar mass sets R and the element counts
      P.R = kRu / M_fuel_;
      elem_[g][0] = fuel.nC / M_fuel_;
      elem_[g][1] = fuel.nH / M_fuel_;
    }
    habs_lo = P.h(kTref);  // absolute (formation-inclusive) enthalpy at T_ref
    P.lo[5] -= habs_lo;
    P.hi[5] -= habs_lo;    // species a5 already make h continuous at 1000 K
    if (constant_cp) {
      const double c0 = P.cp(T_const);
      for (int k = 0; k < 6; ++k) P.lo[k] = P.hi[k] = 0.0;
      P.lo[0] = P.hi[0] = c0;
      P.lo[5] = P.hi[5] = -c0 * kTref;
    }
  }
}

double temperatureFromU(const Poly& ext, double U, double T0) {
  double T = (T0 > 100.0 && T0 < 6000.0) ? T0 : 1000.0;
  for (int it = 0; it < 50; ++it) {
    const double f = ext.u(T) - U;
    const double df = ext.cp(T) - ext.R;
    double dT = -f / df;
    if (dT > 500.0) dT = 500.0;
    if (dT < -500.0) dT = -500.0;
    T += dT;
    if (T < 50.0) T = 50.0;
    if (std::fabs(dT) < 1e-10 * T) return T;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace hbt::cylinder
