// Unit conversion of FMU variables to SI (ModelDescription::unitToSi), checked by hand against
// the definitions of the SI units: 0 degC = 273.15 K, 1 kW = 1000 W, 1 bar = 1e5 Pa, 1 rpm =
// 2 pi / 60 rad/s; and an incompatible unit rejected naming the variable and both units.
#include <gtest/gtest.h>

#include <cmath>

#include "fmi/fmu_error.hpp"
#include "fmi/model_description.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

const char* kXml = R"(<?xml version="1.0"?>
<fmiModelDescription fmiVersion="2.0" modelName="m" guid="{g}">
  <CoSimulation modelIdentifier="m"/>
  <UnitDefinitions>
    <Unit name="degC"><BaseUnit K="1" offset="273.15"/></Unit>
    <Unit name="kW"><BaseUnit kg="1" m="2" s="-3" factor="1000"/></Unit>
    <Unit name="bar"><BaseUnit kg="1" m="-1" s="-2" factor="1e5"/></Unit>
    <Unit name="rpm"><BaseUnit s="-1" rad="1" factor="0.10471975511965977"/></Unit>
    <Unit name="1/min"><BaseUnit s="-1" factor="0.016666666666666666"/></Unit>
  </UnitDefinitions>
  <TypeDefinitions>
    <SimpleType name="Power_kW"><Real unit="kW"/></SimpleType>
  </TypeDefinitions>
  <ModelVariables>
    <ScalarVariable name="T" valueReference="0" causality="output"><Real unit="degC"/></ScalarVariable>
    <ScalarVariable name="P" valueReference="1" causality="output"><Real declaredType="Power_kW"/></ScalarVariable>
    <ScalarVariable name="p" valueReference="2" causality="output"><Real unit="bar"/></ScalarVariable>
    <ScalarVariable name="n" valueReference="3" causality="output"><Real unit="rpm"/></ScalarVariable>
    <ScalarVariable name="f" valueReference="4" causality="output"><Real unit="1/min"/></ScalarVariable>
    <ScalarVariable name="x" valueReference="5" causality="output"><Real/></ScalarVariable>
    <ScalarVariable name="k" valueReference="6" causality="output"><Integer/></ScalarVariable>
  </ModelVariables>
</fmiModelDescription>)";

class Units : public ::testing::Test {
 protected:
  ModelDescription md = ModelDescription::parse(kXml, "units.fmu");
  UnitConversion conv(const char* var, const SiUnit& u) { return md.unitToSi(md.variable(var), u); }
};

TEST_F(Units, CelsiusToKelvinByItsOffset) {
  const UnitConversion c = conv("T", si::kelvin());
  EXPECT_DOUBLE_EQ(c.toSi(0.0), 273.15);
  EXPECT_DOUBLE_EQ(c.toSi(40.0), 313.15);
  EXPECT_NEAR(c.fromSi(253.15), -20.0, 1e-12);  // 253.15 - 273.15 rounds in the last bits
}

TEST_F(Units, KilowattToWattThroughTheDeclaredType) {
  EXPECT_DOUBLE_EQ(conv("P", si::watt()).toSi(12.5), 12500.0);
  EXPECT_DOUBLE_EQ(conv("P", si::watt()).fromSi(500.0), 0.5);
}

TEST_F(Units, BarToPascal) { EXPECT_DOUBLE_EQ(conv("p", si::pascal()).toSi(2.5), 2.5e5); }

TEST_F(Units, RpmDeclaredAsAngularSpeedToRadianPerSecond) {
  // 3000 rpm = 3000 * 2 pi / 60 rad/s = 100 pi rad/s
  EXPECT_NEAR(conv("n", si::radianPerSecond()).toSi(3000.0), 100.0 * M_PI, 1e-12);
}

TEST_F(Units, UnitlessVariableIsDimensionless) {
  const UnitConversion c = conv("x", si::dimensionless());
  EXPECT_EQ(c.toSi(3.0), 3.0);
}

TEST_F(Units, IncompatibleUnitNamesVariableAndBothUnits) {
  testing::expectThrowWith<FmuError>([&] { conv("T", si::watt()); },
                                     {"units.fmu", "'T'", "\"degC\"", "[K]", "W", "[kg.m2.s-3]"});
  // a frequency in 1/min is not an angular speed: rad is a dimension of its own
  testing::expectThrowWith<FmuError>([&] { conv("f", si::radianPerSecond()); },
                                     {"'f'", "\"1/min\"", "[s-1]", "rad/s", "[s-1.rad]"});
  testing::expectThrowWith<FmuError>([&] { conv("x", si::pascal()); }, {"'x'", "dimensionless", "Pa"});
  testing::expectThrowWith<FmuError>([&] { conv("k", si::dimensionless()); }, {"'k'", "Integer"});
}

}  // namespace
}  // namespace hbt::fmi
