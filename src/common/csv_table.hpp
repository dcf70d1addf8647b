// Reader for the comma-separated data files of the twin (VECTO .vdri/.vmap/.vfld/.vtcc, WHTC,
// turbo maps, battery tables).
//
// The first non-comment line is the header; '#' starts a comment line. Column names are stored
// as written; lookup with column("<v>") or column("v") (VECTO angle brackets and a trailing
// "[unit]" are ignored when matching). Every numeric cell is checked: an empty, non-numeric, NaN
// or infinite cell, or a row with the wrong number of cells, raises hbt::InputError naming the
// file, the column and the line.
#pragma once
#include <string>
#include <vector>

namespace hbt {

class CsvTable {
 public:
  /// Reads and validates `path`. Throws InputError (missing file, empty, malformed, NaN).
  static CsvTable read(const std::string& path);

  const std::string& path() const { return path_; }
  std::size_t rows() const { return rows_; }
  const std::vector<std::string>& header() const { return header_; }
  bool has(const std::string& name) const { return find(name) >= 0; }
  /// The column `name`; throws InputError naming file and key if it is absent.
  const std::vector<double>& column(const std::string& name) const;
  /// Throws InputError unless `col` is strictly increasing (key = column name).
  void requireStrictlyIncreasing(const std::string& col) const;

 private:
  int find(const std::string& name) const;
  std::string path_;
  std::vector<std::string> header_;
  std::vector<std::vector<double>> cols_;
  std::size_t rows_ = 0;
};

/// "<v> [km/h]" -> "v": strips VECTO angle brackets, unit suffix in brackets and blanks.
std::string normaliseColumnName(const std::string& raw);

}  // namespace hbt
