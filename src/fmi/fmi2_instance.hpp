// One instance of an FMI 2.0 Co-Simulation FMU (FMI 2.0 chapter 4), driven as the standard's
// state machine wants it: instantiate (resources location = LoadedFmu::resourceUri(), the
// callbacks below) -> setupExperiment (tolerance, start, stop) -> enter/exit initialisation ->
// set inputs, doStep(h), get outputs ... -> terminate and free (destructor).
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

class CsInstance {
 public:
  /// Instantiates fmu (loaded as Co-Simulation) as instance_name; FmuError if fmi2Instantiate
  /// returns NULL (its log messages, in sink, say why).
  CsInstance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name, LogSink sink);
  ~CsInstance();
  CsInstance(const CsInstance&) = delete;
  CsInstance& operator=(const CsInstance&) = delete;

  /// A variable of type t the importer may set: causality input, or a parameter whose
  /// variability is fixed or tunable. FmuError naming the variable otherwise.
  VariableRef settable(const std::string& name, VarType t) const;
  /// A variable of type t the importer may read (any causality). FmuError naming it otherwise.
  VariableRef gettable(const std::string& name, VarType t) const;

  /// fmi2SetupExperiment; the communication time starts at start_s.
  void setupExperiment(std::optional<double> tolerance, double start_s, std::optional<double> stop_s);
  void enterInitializationMode();
  void exitInitializationMode();

  void setReal(const VariableRef& v, double value);
  void setInteger(const VariableRef& v, int value);
  void setBoolean(const VariableRef& v, bool value);
  /// A Real's value; NaN throws.
  double getReal(const VariableRef& v);
  int getInteger(const VariableRef& v);
  bool getBoolean(const VariableRef& v);

  /// fmi2DoStep from time() over h_s [s] > 0; time() advances by h_s. A step beyond the stop
  /// time given to setupExperiment throws before calling the FMU.
  void doStep(double h_s);
  /// The current communication point [s].
  double time() const { return time_s_; }
  const std::string& instanceName() const { return name_; }
  const LoadedFmu& fmu() const { return *fmu_; }

 private:
  enum class State { kInstantiated, kInitialization, kStepping, kError, kFatal };
  static void logMessage(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                         fmi2String category, fmi2String message, ...);
  void check(fmi2Status s, const std::string& call);
  void requireSet(const VariableRef& v, VarType t) const;
  [[noreturn]] void fail(const std::string& what_call, const std::string& what) const;

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
