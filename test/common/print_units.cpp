// Prints the constants of src/common/units.hpp that twin_tools.units reads, as the C++
// build has them (%.17g: each double exactly), for test/scenario/test_twin_units.py.
#include <cstdio>

#include "common/units.hpp"

int main() {
  using namespace hbt::units;
  std::printf("kDieselLhv_J_kg %.17g\n", kDieselLhv_J_kg);
  std::printf("kDieselDensity_kg_m3 %.17g\n", kDieselDensity_kg_m3);
  std::printf("kM3_per_litre %.17g\n", kM3_per_litre);
  std::printf("dieselLitres(1) %.17g\n", dieselLitres(1.0));
  return 0;
}
