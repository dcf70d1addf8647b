// Error types shared by every model library.
//
// Every error raised while reading input names the file and the key (or column/line) at fault,
// so that a bad scenario is rejected with a readable message before the simulation starts.
#pragma once
#include <stdexcept>
#include <string>

namespace hbt {

/// Bad input: file + key (parameter name, CSV column, line) + what is wrong.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& key, const std::string& what)
      : std::runtime_error(file + ": key '" + key + "': " + what), file_(file), key_(key) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_, key_;
};

/// A model whose state became non-physical (NaN, negative density, collapsing time step...).
/// `where` names the model element (e.g. "pipe exh_manifold_1 cell 7"), `quantity` the variable.
class ModelDivergence : public std::runtime_error {
 public:
  ModelDivergence(const std::string& where, const std::string& quantity, const std::string& what)
      : std::runtime_error(where + ": " + quantity + ": " + what) {}
};

}  // namespace hbt
