#!/usr/bin/python3
"""twin_tools.units: the constants the tools read from src/common/units.hpp equal the C++
build's (printed by the print_units tool, whose path ctest passes as the first argument); a name
without a `constexpr double NAME = NUMBER;` line is an error naming the file and the name."""
import os
import subprocess
import sys
import tempfile
import unittest

from twin_tools import units as twin_units

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

PRINT_UNITS = sys.argv.pop(1) if len(sys.argv) > 1 else None


class TwinUnits(unittest.TestCase):
    def test_values_equal_the_cpp_ones(self):
        self.assertIsNotNone(PRINT_UNITS, "usage: test_twin_units.py PRINT_UNITS (the built tool)")
        out = subprocess.run([PRINT_UNITS], capture_output=True, text=True, check=True).stdout
        cpp = {name: float(value) for name, value in (line.split() for line in out.splitlines())}
        for name in ("kDieselLhv_J_kg", "kDieselDensity_kg_m3", "kM3_per_litre"):
            self.assertEqual(twin_units.constant(name), cpp[name], name)
        self.assertEqual(twin_units.DIESEL_LHV_J_KG, cpp["kDieselLhv_J_kg"])
        self.assertEqual(1.0 / twin_units.DIESEL_DENSITY_KG_L, cpp["dieselLitres(1)"])
        self.assertEqual(twin_units.DIESEL_LHV_J_KG, 42.7e6)  # the values themselves: unchanged
        self.assertEqual(twin_units.DIESEL_DENSITY_KG_L, 0.835)

    def test_missing_or_non_numeric_name_is_an_error(self):
        fd, path = tempfile.mkstemp(suffix=".hpp")
        with os.fdopen(fd, "w") as f:
            f.write("constexpr double kA = 1.5e3;\n"
                    "constexpr double kB = 2.0 * kA;\n"
                    "// constexpr double kC = 3.0;\n")
        try:
            self.assertEqual(twin_units.constant("kA", path), 1500.0)
            for name in ("kB", "kC", "kMissing", "k"):
                with self.assertRaises(LookupError) as cm:
                    twin_units.constant(name, path)
                self.assertIn(path, str(cm.exception))
                self.assertIn(name, str(cm.exception))
        finally:
            os.unlink(path)


if __name__ == "__main__":
    unittest.main(verbosity=2)
