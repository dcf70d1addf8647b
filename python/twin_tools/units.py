"""Constants the scripts share with the C++ models, read from their one definition,
src/common/units.hpp (its lines `constexpr double NAME = NUMBER;`):

  DIESEL_LHV_J_KG       kDieselLhv_J_kg              diesel lower heating value [J/kg]
  DIESEL_DENSITY_KG_L   kDieselDensity_kg_m3 x m3/L  diesel density [kg/L]

constant(NAME) reads any other such line; a name without one (missing, or its value not a plain
number) raises LookupError naming the file and the name.
"""
import os
import re

from twin_tools.paths import REPO

UNITS_HPP = os.path.join(REPO, "src", "common", "units.hpp")
_LINE = re.compile(r"^\s*constexpr\s+double\s+(\w+)\s*=\s*([^;]*?)\s*;")
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def constant(name, path=UNITS_HPP):
    """The value of `constexpr double <name> = <number>;` in `path` (float)."""
    with open(path) as f:
        for line in f:
            m = _LINE.match(line)
            if m and m.group(1) == name:
                if not _NUMBER.match(m.group(2)):
                    raise LookupError("%s: %s = %s is not a plain number" % (path, name, m.group(2)))
                return float(m.group(2))
    raise LookupError("%s: no line 'constexpr double %s = <number>;'" % (path, name))


DIESEL_LHV_J_KG = constant("kDieselLhv_J_kg")
DIESEL_DENSITY_KG_L = constant("kDieselDensity_kg_m3") * constant("kM3_per_litre")
