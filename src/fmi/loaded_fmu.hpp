// An FMU ready to instantiate: its archive checked, extracted into a caller-given directory and
// its binary for one interface type loaded. Shared (std::shared_ptr) by the instances made from
// it, which outlive neither it nor its directory.
#pragma once
#include <memory>
#include <string>

#include "fmi/fmi2_library.hpp"
#include "fmi/fmu_archive.hpp"

namespace hbt::fmi {

class LoadedFmu {
 public:
  /// Checks fmu_file (FmuArchive), the binary entry of interface type t, extracts the FMU into
  /// extract_dir and loads the binary (Fmi2Library). Any rejection is an FmuError.
  static std::shared_ptr<const LoadedFmu> load(const std::string& fmu_file,
                                               const std::string& extract_dir, InterfaceType t);

  const std::string& file() const { return archive_.file(); }
  const ModelDescription& modelDescription() const { return archive_.modelDescription(); }
  const Fmi2Functions& functions() const { return library_->functions(); }
  InterfaceType interfaceType() const { return library_->interfaceType(); }
  /// The absolute extraction directory.
  const std::string& directory() const { return dir_; }
  /// The resources location handed to fmi2Instantiate (FMI 2.0 section 2.1.5): the URI
  /// (RFC 3986, scheme file, empty authority) of <directory>/resources without a trailing
  /// slash, as the standard's example writes it: "file:///tmp/x/resources".
  const std::string& resourceUri() const { return resource_uri_; }

 private:
  LoadedFmu(const std::string& fmu_file, const std::string& extract_dir, InterfaceType t);

  FmuArchive archive_;
  std::string dir_, resource_uri_;
  std::unique_ptr<Fmi2Library> library_;
};

/// "file://" + the absolute path, every byte other than an unreserved character (RFC 3986
/// section 2.3) or '/' percent-encoded.
std::string fileUri(const std::string& absolute_path);

}  // namespace hbt::fmi
