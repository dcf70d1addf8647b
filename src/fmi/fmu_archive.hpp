// An FMU file (FMI 2.0 section 2.3): a zip archive (libzip) with modelDescription.xml at its
// root, binaries/<platform>/<modelIdentifier>.so and an optional resources/ folder.
// The constructor checks the file (exists, is a regular file, is a zip, holds a well-formed FMI
// 2.0 modelDescription.xml) and keeps the parsed description; extractTo() writes the entries
// into a caller-given directory, in the archive's order (deterministic: the same archive gives
// the same files). Every rejection is an FmuError naming the file and what is wrong.
#pragma once
#include <string>
#include <vector>

#include "fmi/model_description.hpp"

namespace hbt::fmi {

/// The interface type an importer runs an FMU as.
enum class InterfaceType { kCoSimulation, kModelExchange };
const char* name(InterfaceType t);

class FmuArchive {
 public:
  explicit FmuArchive(const std::string& fmu_file);

  const std::string& file() const { return file_; }
  const ModelDescription& modelDescription() const { return md_; }
  /// The archive's entry names, in the archive's order.
  const std::vector<std::string>& entries() const { return entries_; }

  /// modelIdentifier of interface type t; FmuError if the FMU does not declare t.
  const std::string& modelIdentifier(InterfaceType t) const;
  /// "binaries/linux64/<modelIdentifier>.so" of interface type t; FmuError if the archive has
  /// no such entry.
  std::string binaryEntry(InterfaceType t) const;

  /// Writes every entry below dir (created if missing; existing files are overwritten). An entry
  /// whose path would leave dir (absolute, or with "..") is an FmuError.
  void extractTo(const std::string& dir) const;

 private:
  std::string readEntry(const std::string& entry) const;

  std::string file_;
  std::vector<std::string> entries_;
  ModelDescription md_;
};

}  // namespace hbt::fmi
