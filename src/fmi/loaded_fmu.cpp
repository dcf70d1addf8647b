#include "fmi/loaded_fmu.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace hbt::fmi {

std::string fileUri(const std::string& absolute_path) {
  std::string uri = "file://";
  for (unsigned char c : absolute_path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      uri += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      uri += hex;
    }
  }
  return uri;
}

std::shared_ptr<const LoadedFmu> LoadedFmu::load(const std::string& fmu_file,
                                                 const std::string& extract_dir, InterfaceType t) {
  return std::shared_ptr<const LoadedFmu>(new LoadedFmu(fmu_file, extract_dir, t));
}

LoadedFmu::LoadedFmu(const std::string& fmu_file, const std::string& extract_dir, InterfaceType t)
    : archive_(fmu_file) {
  const std::string entry = archive_.binaryEntry(t);
  archive_.extractTo(extract_dir);
  const std::filesystem::path dir = std::filesystem::absolute(extract_dir).lexically_normal();
  dir_ = dir.string();
  resource_uri_ = fileUri((dir / "resources").string());
  library_ = std::make_unique<Fmi2Library>((dir / entry).string(), t, fmu_file);
}

}  // namespace hbt::fmi
