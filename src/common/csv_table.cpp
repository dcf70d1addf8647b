#include "common/csv_table.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace hbt {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream is(line);
  while (std::getline(is, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

}  // namespace

std::string normaliseColumnName(const std::string& raw) {
  std::string s = trim(raw);
  const auto br = s.find('[');
  if (br != std::string::npos) s = trim(s.substr(0, br));
  std::string out;
  for (char c : s)
    if (c != '<' && c != '>' && c != ' ') out.push_back(c);
  return out;
}

CsvTable CsvTable::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "(file)", "cannot open file (missing or unreadable)");
  CsvTable t;
  t.path_ = path;
  std::string line;
  std::size_t lineNo = 0;
  bool haveHeader = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    auto cells = split(s);
    if (!haveHeader) {
      t.header_ = cells;
      t.cols_.assign(cells.size(), {});
      haveHeader = true;
      continue;
    }
    if (cells.size() != t.header_.size())
      throw InputError(path, "line " + std::to_string(lineNo),
                       "expected " + std::to_string(t.header_.size()) + " cells, found " +
                           std::to_string(cells.size()) + " (truncated or malformed row)");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string& cell = cells[c];
      char* end = nullptr;
      const double v = cell.empty() ? NAN : std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(v))
        throw InputError(path, normaliseColumnName(t.header_[c]),
                         "line " + std::to_string(lineNo) + ": '" + cell +
                             "' is not a finite number");
      t.cols_[c].push_back(v);
    }
    ++t.rows_;
  }
  if (!haveHeader) throw InputError(path, "(header)", "file is empty");
  if (t.rows_ == 0) throw InputError(path, "(rows)", "no data rows after the header");
  return t;
}

int CsvTable::find(const std::string& name) const {
  const std::string want = normaliseColumnName(name);
  for (std::size_t i = 0; i < header_.size(); ++i)
    if (normaliseColumnName(header_[i]) == want) return static_cast<int>(i);
  return -1;
}

const std::vector<double>& CsvTable::column(const std::string& name) const {
  const int i = find(name);
  if (i < 0) throw InputError(path_, name, "column missing from header");
  return cols_[static_cast<std::size_t>(i)];
}

void CsvTable::requireStrictlyIncreasing(const std::string& col) const {
  const auto& v = column(col);
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1]))
      throw InputError(path_, col, "values must be strictly increasing (row " +
                                       std::to_string(i + 1) + ")");
}

}  // namespace hbt
