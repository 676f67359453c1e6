#include "rig/csv_table.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tribo::rig {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace

void fail_at(const std::filesystem::path& file, long line, const std::string& reason) {
  std::string where = file.string();
  if (line > 0) where += ":" + std::to_string(line);
  throw std::invalid_argument(where + ": " + reason);
}

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

int CsvTable::required(const std::string& name) const {
  const int c = column(name);
  if (c < 0) fail_at(file, 1, "missing required column '" + name + "'");
  return c;
}

double CsvTable::number(long line, const std::vector<std::string>& row, int c) const {
  const std::string& s = row[static_cast<std::size_t>(c)];
  const std::string& name = header[static_cast<std::size_t>(c)];
  if (s.empty()) fail_at(file, line, "empty value in column '" + name + "'");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0' || errno == ERANGE)
    fail_at(file, line, "column '" + name + "': '" + s + "' is not a number");
  if (!std::isfinite(v)) fail_at(file, line, "column '" + name + "': value is " + s + " (NaN and infinities are rejected)");
  return v;
}

CsvTable read_csv_table(const std::filesystem::path& file, const std::set<std::string>& known,
                        std::vector<std::string>& warnings) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec)) fail_at(file, 0, "not a regular file");
  std::ifstream in(file);
  if (!in) fail_at(file, 0, "cannot open file");
  CsvTable t;
  t.file = file;
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    if (t.header.empty()) {
      t.header = split(s);
      std::set<std::string> seen;
      for (const auto& h : t.header) {
        if (h.empty()) fail_at(file, number, "empty column name in header");
        if (!seen.insert(h).second) fail_at(file, number, "duplicate column '" + h + "'");
        if (!known.count(h)) warnings.push_back(file.string() + ": unknown column '" + h + "' ignored");
      }
      continue;
    }
    auto cells = split(s);
    if (cells.size() != t.header.size())
      fail_at(file, number, "expected " + std::to_string(t.header.size()) + " values, found " + std::to_string(cells.size()));
    t.rows.emplace_back(number, std::move(cells));
  }
  if (t.header.empty()) fail_at(file, 0, "empty file (no header)");
  if (t.rows.empty()) fail_at(file, 0, "no data rows");
  return t;
}

}  // namespace tribo::rig
