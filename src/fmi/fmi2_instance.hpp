// What an instance of an FMI 2.0 FMU does in both interface types (FMI 2.0 section 2.1): instantiate
// (resources location = LoadedFmu::resourceUri(), the callbacks below) -> setupExperiment
// (tolerance, start, stop) -> enter/exit initialisation -> set and get variables -> terminate and
// free (destructor). CsInstance and MeInstance add the stepping of their interface type.
//
// Variables are resolved by name once (settable()/gettable(): type and causality checked) and
// then set and read through their value references. Status fmi2OK and fmi2Warning pass; any
// other status of any call, or a NaN read from a Real, throws hbt::ModelDivergence naming the
// FMU and instance, the call or variable and the communication time t [s]. The FMU's log
// messages (printf formats) are formatted and handed to the caller's LogSink. Deterministic: no
// clock, no threads; the FMU decides the rest.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fmi/loaded_fmu.hpp"

namespace hbt::fmi {

/// Receives each log message of the FMU: instance name, status, category, formatted message.
using LogSink = std::function<void(const std::string& instance, fmi2Status status,
                                   const std::string& category, const std::string& message)>;
const char* statusName(fmi2Status s);

/// A variable resolved once: its description and value reference.
struct VariableRef {
  const ScalarVariable* variable = nullptr;
  fmi2ValueReference vr = 0;
};

/// Variables of one type set or read together: one fmi2Set<Type>/fmi2Get<Type> call over the
/// value-reference vector per communication step instead of one call per variable (FMI 2.0
/// section 2.1.7 takes vectors). Made once by Fmi2Instance::batch (types checked there).
struct VariableBatch {
  VarType type = VarType::kReal;
  std::vector<fmi2ValueReference> vrs;
  std::vector<const ScalarVariable*> variables;  // parallel to vrs: the names in messages
  const ScalarVariable* fixed = nullptr;         // the first fixed parameter among them, if any
  std::size_t size() const { return vrs.size(); }
};

class Fmi2Instance {
 public:
  /// Instantiates fmu as instance_name with fmu's interface type; FmuError if fmi2Instantiate
  /// returns NULL (its log messages, in sink, say why).
  Fmi2Instance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name, LogSink sink);
  virtual ~Fmi2Instance();
  Fmi2Instance(const Fmi2Instance&) = delete;
  Fmi2Instance& operator=(const Fmi2Instance&) = delete;

  /// A variable of type t the importer may set: causality input, or a parameter whose
  /// variability is fixed or tunable. FmuError naming the variable otherwise.
  VariableRef settable(const std::string& name, VarType t) const;
  /// A variable of type t the importer may read (any causality). FmuError naming it otherwise.
  VariableRef gettable(const std::string& name, VarType t) const;
  /// The variables refs (from settable() or gettable(), each of type t: Integer includes
  /// Enumeration) as one batch; FmuError naming a variable of another type.
  VariableBatch batch(const std::vector<VariableRef>& refs, VarType t) const;

  /// fmi2SetupExperiment; the communication time starts at start_s.
  void setupExperiment(std::optional<double> tolerance, double start_s, std::optional<double> stop_s);
  void enterInitializationMode();
  /// Leaves initialisation (Model Exchange: and runs the event iteration, then continuous-time mode).
  virtual void exitInitializationMode();

  void setReal(const VariableRef& v, double value);
  void setInteger(const VariableRef& v, int value);
  void setBoolean(const VariableRef& v, bool value);
  /// A Real's value; NaN throws.
  double getReal(const VariableRef& v);
  int getInteger(const VariableRef& v);
  bool getBoolean(const VariableRef& v);

  /// One call over a batch: values[i] is the value of b.variables[i] (nothing is called for an
  /// empty batch). A failing status names the call and every variable of the batch (after
  /// fmi2Error the standard allows no further call that could single one out); a NaN read
  /// names the variable.
  void setReals(const VariableBatch& b, const double* values);
  void setIntegers(const VariableBatch& b, const int* values);
  void setBooleans(const VariableBatch& b, const fmi2Boolean* values);
  void getReals(const VariableBatch& b, double* values);
  void getIntegers(const VariableBatch& b, int* values);
  void getBooleans(const VariableBatch& b, fmi2Boolean* values);

  /// The current time [s] (communication point, or the integrator's time).
  double time() const { return time_s_; }
  const std::string& instanceName() const { return name_; }
  const LoadedFmu& fmu() const { return *fmu_; }

 protected:
  enum class State { kInstantiated, kInitialization, kStepping, kError, kFatal };
  /// Throws (naming `call` and, when given, the variable) unless s is fmi2OK/fmi2Warning; the
  /// message is built only on failure (called per variable and step).
  void check(fmi2Status s, const char* call, const std::string* variable = nullptr);
  [[noreturn]] void fail(const std::string& what_call, const std::string& what) const;
  /// The common checks of a step of h_s [s] from time().
  void checkStep(const char* call, double h_s) const;

 private:
  static void logMessage(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                         fmi2String category, fmi2String message, ...);
  void requireSet(const VariableRef& v, VarType t) const;
  void requireSet(const VariableBatch& b, VarType t) const;
  /// check() for a call over batch b: the message names every variable of b.
  void checkBatch(fmi2Status s, const char* call, const VariableBatch& b);

 protected:

  std::shared_ptr<const LoadedFmu> fmu_;
  const Fmi2Functions& f_;
  std::string name_;
  LogSink sink_;
  fmi2CallbackFunctions callbacks_{};  // address handed to the FMU: the object does not move
  fmi2Component c_ = nullptr;
  State state_ = State::kInstantiated;
  double time_s_ = 0.0;
  std::optional<double> stop_s_;
};

}  // namespace hbt::fmi
