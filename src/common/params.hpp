// Declarative parameter binding shared by every model library and node.
//
// A model declares its parameters once (key, reference to the field, unit, allowed range, doc):
//
//   void declare(hbt::ParamSet& ps) {
//     ps.add("mass_kg", mass_kg, "kg", 1000.0, 60000.0, "curb mass");
//   }
//
// and a ParamSource (a flat key -> value map, filled from rosparam by the node or directly by a
// test) is applied with hbt::applyParams(). Errors name the source file and the key: a value of
// the wrong type, NaN/inf, a value out of range, and any key present in the source that the
// model does not know (typos must not be ignored silently).
//
// Required keys: every key describes the real bus and must be in its file when the product
// reads it (hbt::requireKeys, called by every configuration path of the nodes): a key removed
// from a file is an error naming file and key, never a silent built-in default. A default that
// is right for every bus is declared as such, with its source, right after its add():
//     ps.add("max_steps", max_steps, "-", 10, 1e6, "CVODE steps per model step");
//     ps.intendedDefault("CVODE's own default order of magnitude");
// Tests may apply partial sources (applyParams alone does not require keys).
#pragma once
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace hbt {

using ParamValue = std::variant<bool, double, std::string, std::vector<double>>;

/// Flat map "group/key" -> value, plus the file it came from (for error messages).
struct ParamSource {
  std::string file = "(parameters)";
  std::map<std::string, ParamValue> values;
  void set(const std::string& key, ParamValue v) { values[key] = std::move(v); }
};

class ParamSet {
 public:
  /// Declares a key (required in files: requireKeys) bound to `ref`, whose value is its default.
  void add(const std::string& key, double& ref, const std::string& unit, double min, double max,
           const std::string& doc);
  void add(const std::string& key, bool& ref, const std::string& doc);
  void add(const std::string& key, std::string& ref, const std::string& doc);
  void add(const std::string& key, std::vector<double>& ref, const std::string& unit, double min,
           double max, const std::string& doc);
  void add(const std::string& key, int& ref, const std::string& unit, int min, int max,
           const std::string& doc);

  /// Marks the key added last as an intended default (its current value is right for every bus):
  /// requireKeys lets a file leave it out. `source` says why (cited in describeParams).
  void intendedDefault(const std::string& source);

  /// Prefix prepended to keys added afterwards ("vehicle/" ...); "" to clear.
  void setPrefix(const std::string& prefix) { prefix_ = prefix; }

  struct Entry {
    std::string key, unit, doc;
    std::variant<double*, bool*, std::string*, std::vector<double>*, int*> ref;
    double min = 0.0, max = 0.0;
    std::string default_source;  // non-empty: an intended default (intendedDefault), else required
  };
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::string prefix_;
  std::vector<Entry> entries_;
};

/// Sections of a participant's YAML that its participant reads, not its model: cosim/ (the step
/// protocol's keys) and diagnostics/ (its warning thresholds), src/cosim/participant.hpp.
inline const std::vector<std::string> kParticipantSections = {"cosim/", "diagnostics/"};

/// Applies `src` to the declared fields. Keys of `src` that start with one of `ignore_prefixes`
/// are not reported as unknown (e.g. parameters consumed by the node itself), nor are those of a
/// kParticipantSections section of which `ps` declares no key (a model reading its participant's
/// file; the reader of that section declares its keys, so a misspelt one is named). Throws
/// InputError.
void applyParams(const ParamSet& ps, const ParamSource& src,
                 const std::vector<std::string>& ignore_prefixes = {});

/// Throws InputError(src.file, key) for the first declared key that `src` lacks and that is not
/// an intended default: the product's configuration paths call it after applyParams (which names a
/// misspelt key as unknown first). Keys
/// starting with one of `set_elsewhere` come from another file or the scenario (required there).
void requireKeys(const ParamSet& ps, const ParamSource& src, const std::vector<std::string>& set_elsewhere = {});

/// One line per parameter: "key [unit] = value  # doc" (for --help output and reports).
std::string describeParams(const ParamSet& ps);

/// One parameter as a model was configured with it: the file it was read from (or would have
/// been), the key, the value (text: %.17g numbers, [a, b] lists), its unit, and whether the file
/// set it (false: the model's default).
struct ResolvedParam {
  std::string file, key, value, unit;
  bool from_file = false;
};

/// While a ParamCapture is alive, every applyParams() on the same thread appends the resolved
/// value of each declared key to it (a participant wraps its configure() in one and writes the
/// list beside the bag: what the run really used). Captures nest: the innermost one receives.
class ParamCapture {
 public:
  ParamCapture();
  ~ParamCapture();
  ParamCapture(const ParamCapture&) = delete;
  ParamCapture& operator=(const ParamCapture&) = delete;
  const std::vector<ResolvedParam>& params() const { return params_; }
  void add(ResolvedParam p) { params_.push_back(std::move(p)); }

 private:
  std::vector<ResolvedParam> params_;
  ParamCapture* outer_ = nullptr;
};

}  // namespace hbt
