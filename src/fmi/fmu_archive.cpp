#include "fmi/fmu_archive.hpp"

#include <zip.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>

#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

namespace fs = std::filesystem;

const char* name(InterfaceType t) {
  return t == InterfaceType::kCoSimulation ? "CoSimulation" : "ModelExchange";
}

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }  // read-only: nothing to write back
};
using ZipPtr = std::unique_ptr<zip_t, ZipCloser>;

ZipPtr openZip(const std::string& file) {
  int err = 0;
  zip_t* z = zip_open(file.c_str(), ZIP_RDONLY, &err);
  if (!z) {
    zip_error_t e;
    zip_error_init_with_code(&e, err);
    const std::string what = zip_error_strerror(&e);
    zip_error_fini(&e);
    throw FmuError(file, "not a zip archive (" + what + ")");
  }
  return ZipPtr(z);
}

std::string readWhole(zip_t* z, zip_uint64_t index, const std::string& file, const std::string& entry) {
  zip_stat_t st;
  zip_file_t* f = nullptr;
  if (zip_stat_index(z, index, 0, &st) != 0 || !(f = zip_fopen_index(z, index, 0))) {
    throw FmuError(file, "cannot read " + entry + ": " + zip_strerror(z));
  }
  std::string data(static_cast<std::size_t>(st.size), '\0');
  const zip_int64_t n = zip_fread(f, data.data(), st.size);
  zip_fclose(f);
  if (n < 0 || static_cast<zip_uint64_t>(n) != st.size) {
    throw FmuError(file, "cannot read " + entry + ": truncated or corrupt entry");
  }
  return data;
}

}  // namespace

FmuArchive::FmuArchive(const std::string& fmu_file) : file_(fmu_file) {
  std::error_code ec;
  if (!fs::exists(fmu_file, ec)) throw FmuError(fmu_file, "no such file");
  if (!fs::is_regular_file(fmu_file, ec)) throw FmuError(fmu_file, "not a regular file");
  ZipPtr z = openZip(fmu_file);
  const zip_int64_t n = zip_get_num_entries(z.get(), 0);
  for (zip_int64_t i = 0; i < n; ++i) entries_.push_back(zip_get_name(z.get(), i, 0));
  if (std::find(entries_.begin(), entries_.end(), "modelDescription.xml") == entries_.end()) {
    throw FmuError(fmu_file, "no modelDescription.xml at the root of the archive");
  }
  md_ = ModelDescription::parse(readEntry("modelDescription.xml"), fmu_file);
}

std::string FmuArchive::readEntry(const std::string& entry) const {
  ZipPtr z = openZip(file_);
  const zip_int64_t i = zip_name_locate(z.get(), entry.c_str(), 0);
  if (i < 0) throw FmuError(file_, "no entry " + entry);
  return readWhole(z.get(), static_cast<zip_uint64_t>(i), file_, entry);
}

const std::string& FmuArchive::modelIdentifier(InterfaceType t) const {
  const auto& id = t == InterfaceType::kCoSimulation ? md_.coSimulationId() : md_.modelExchangeId();
  if (!id) throw FmuError(file_, std::string("modelDescription.xml has no <") + name(t) + ">");
  return *id;
}

std::string FmuArchive::binaryEntry(InterfaceType t) const {
  const std::string entry = "binaries/linux64/" + modelIdentifier(t) + ".so";
  if (std::find(entries_.begin(), entries_.end(), entry) == entries_.end()) {
    throw FmuError(file_, "no linux64 binary: the archive has no " + entry);
  }
  return entry;
}

void FmuArchive::extractTo(const std::string& dir) const {
  ZipPtr z = openZip(file_);
  const fs::path root = fs::absolute(dir);
  fs::create_directories(root);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const fs::path rel = fs::path(entries_[i]).lexically_normal();
    if (rel.is_absolute() || rel.empty() || *rel.begin() == "..") {
      throw FmuError(file_, "entry \"" + entries_[i] + "\" would be extracted outside " + dir);
    }
    const fs::path out = root / rel;
    if (entries_[i].back() == '/') {
      fs::create_directories(out);
      continue;
    }
    fs::create_directories(out.parent_path());
    const std::string data = readWhole(z.get(), i, file_, entries_[i]);
    std::ofstream f(out, std::ios::binary | std::ios::trunc);
    f.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!f) throw FmuError(file_, "cannot write " + out.string());
  }
}

}  // namespace hbt::fmi
