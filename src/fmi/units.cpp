#include "fmi/units.hpp"

namespace hbt::fmi {

const char* SiDimension::baseName(int i) {
  static const char* const kNames[8] = {"kg", "m", "s", "A", "K", "mol", "cd", "rad"};
  return kNames[i];
}

std::string SiDimension::str() const {
  std::string s;
  for (int i = 0; i < 8; ++i) {
    if (exponent[i] == 0) continue;
    if (!s.empty()) s += ".";
    s += baseName(i);
    if (exponent[i] != 1) s += std::to_string(exponent[i]);
  }
  return s.empty() ? "1" : s;
}

namespace si {
namespace {
SiUnit make(const char* name, int kg, int m, int s, int K, int rad) {
  SiUnit u{name, {}};
  u.dimension.exponent = {kg, m, s, 0, K, 0, 0, rad};
  return u;
}
}  // namespace
SiUnit dimensionless() { return make("1", 0, 0, 0, 0, 0); }
SiUnit kelvin() { return make("K", 0, 0, 0, 1, 0); }
SiUnit watt() { return make("W", 1, 2, -3, 0, 0); }
SiUnit pascal() { return make("Pa", 1, -1, -2, 0, 0); }
SiUnit radianPerSecond() { return make("rad/s", 0, 0, -1, 0, 1); }
SiUnit second() { return make("s", 0, 0, 1, 0, 0); }
}  // namespace si

}  // namespace hbt::fmi
