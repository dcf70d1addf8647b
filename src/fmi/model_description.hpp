// modelDescription.xml of an FMI 2.0 FMU (FMI 2.0 chapter 2.2), parsed with tinyxml2 and checked:
// fmiVersion "2.0"; a CoSimulation and/or ModelExchange element with its modelIdentifier; the
// GUID; DefaultExperiment; UnitDefinitions; TypeDefinitions; ModelVariables. Attributes the
// standard makes optional take the standard's defaults (causality "local", variability
// "continuous", BaseUnit factor 1, offset 0, exponents 0). Every rejection is an FmuError naming
// the FMU file and the element, attribute or variable at fault.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fmi/units.hpp"

namespace hbt::fmi {

enum class Causality { kParameter, kCalculatedParameter, kInput, kOutput, kLocal, kIndependent };
enum class Variability { kConstant, kFixed, kTunable, kDiscrete, kContinuous };
enum class VarType { kReal, kInteger, kBoolean, kString, kEnumeration };

const char* name(Causality c);
const char* name(Variability v);
const char* name(VarType t);

/// One ScalarVariable. unit: its own unit attribute, else its declaredType's ("" = none).
/// start: the start attribute's text as written (empty if none). min, max: as the FMU states them.
struct ScalarVariable {
  std::string name;
  unsigned value_reference = 0;
  Causality causality = Causality::kLocal;
  Variability variability = Variability::kContinuous;
  VarType type = VarType::kReal;
  std::string declared_type;
  std::string unit;
  std::optional<std::string> start;
  std::optional<double> min, max;  // the type element's min / max, in the variable's unit, if stated
  std::string description;
};

/// A SimpleType of TypeDefinitions (its type element and unit).
struct SimpleType {
  std::string name;
  VarType type = VarType::kReal;
  std::string unit;
};

/// DefaultExperiment; each value only if the FMU states it.
struct DefaultExperiment {
  std::optional<double> start_time_s, stop_time_s, tolerance, step_size_s;
};

class ModelDescription {
 public:
  /// Parses xml (the text of modelDescription.xml); fmu_file names the FMU in messages.
  static ModelDescription parse(const std::string& xml, const std::string& fmu_file);

  const std::string& fmuFile() const { return fmu_file_; }
  const std::string& modelName() const { return model_name_; }
  const std::string& guid() const { return guid_; }
  /// modelIdentifier of CoSimulation / ModelExchange; nullopt if the FMU has no such element.
  const std::optional<std::string>& coSimulationId() const { return cs_id_; }
  const std::optional<std::string>& modelExchangeId() const { return me_id_; }
  const DefaultExperiment& defaultExperiment() const { return experiment_; }
  int numberOfEventIndicators() const { return n_event_indicators_; }
  /// Continuous states: the <Unknown> elements of ModelStructure/Derivatives (Model Exchange).
  int numberOfContinuousStates() const { return n_states_; }
  const std::map<std::string, UnitDefinition>& units() const { return units_; }
  const std::map<std::string, SimpleType>& types() const { return types_; }
  /// In the order of ModelVariables (index + 1 = the index ModelStructure refers to).
  const std::vector<ScalarVariable>& variables() const { return variables_; }

  /// The variable called name; FmuError naming it if the FMU has none.
  const ScalarVariable& variable(const std::string& name) const;
  /// Conversion of v's values to SI; FmuError naming the variable, its unit and the expected
  /// one if v is not a Real or its unit's dimension is not expected's.
  UnitConversion unitToSi(const ScalarVariable& v, const SiUnit& expected) const;

 private:
  std::string fmu_file_, model_name_, guid_;
  std::optional<std::string> cs_id_, me_id_;
  DefaultExperiment experiment_;
  int n_event_indicators_ = 0;
  int n_states_ = 0;
  std::map<std::string, UnitDefinition> units_;
  std::map<std::string, SimpleType> types_;
  std::vector<ScalarVariable> variables_;
  std::map<std::string, std::size_t> index_;  // variable name -> position in variables_

  friend class ModelDescriptionParser;
};

}  // namespace hbt::fmi
