// hbt_fmu_describe SPEC.yaml MSG_DIR PACKAGE_ROOT STAGE_DIR HEADER
// Writes STAGE_DIR/modelDescription.xml, copies the model's config and data files into
// STAGE_DIR/resources/ and writes the binary's variables header (fmu_description.hpp). Exit 1 with
// the error (file and key) on stderr.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "fmi/export/fmu_description.hpp"

namespace fs = std::filesystem;

namespace {

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path.string());
}

void copyInto(const fs::path& from, const fs::path& dir) {
  fs::copy_file(from, dir / from.filename(), fs::copy_options::overwrite_existing);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: hbt_fmu_describe SPEC.yaml MSG_DIR PACKAGE_ROOT STAGE_DIR HEADER\n";
    return 2;
  }
  try {
    using hbt::fmi::exported::FmuDescription;
    const FmuDescription d = FmuDescription::read(argv[1], argv[2], argv[3]);
    const fs::path root(argv[3]), stage(argv[4]);
    fs::create_directories(stage / "resources");
    writeFile(stage / "modelDescription.xml", d.modelDescriptionXml());
    copyInto(root / d.config_file, stage / "resources");
    for (const auto& f : d.config_files) copyInto(root / f, stage / "resources");
    for (const auto& f : d.data_files) copyInto(root / f, stage / "resources");
    fs::create_directories(fs::path(argv[5]).parent_path());
    writeFile(argv[5], d.variablesHeader());
  } catch (const std::exception& e) {
    std::cerr << "hbt_fmu_describe: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
