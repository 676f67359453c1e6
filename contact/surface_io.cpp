#include "contact/surface_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tribo::contact {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw std::invalid_argument("surface file '" + path.string() + "': " + why);
}

std::ifstream open(const std::filesystem::path& path, std::ios::openmode mode = std::ios::in) {
  std::ifstream in(path, mode);
  if (!in) fail(path, "cannot be opened");
  return in;
}

void check_finite(const std::filesystem::path& path, const Eigen::ArrayXXd& h) {
  if (h.size() == 0) fail(path, "holds no heights");
  if (!h.allFinite()) fail(path, "holds NaN or infinite heights");
}

// Splits a data line on whitespace and commas; returns false for blank and comment lines.
bool numbers_on_line(const std::filesystem::path& path, std::size_t line_no, const std::string& line,
                     std::vector<double>& out) {
  out.clear();
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos || line[first] == '#' || line[first] == '%') return false;
  std::string s = line;
  std::replace(s.begin(), s.end(), ',', ' ');
  std::istringstream is(s);
  std::string tok;
  while (is >> tok) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0') {
      fail(path, "line " + std::to_string(line_no) + ": '" + tok + "' is not a number");
    }
    out.push_back(v);
  }
  return !out.empty();
}

std::uint64_t byteswap64(std::uint64_t v) {
  std::uint64_t r = 0;
  for (int b = 0; b < 8; ++b) r |= ((v >> (8 * b)) & 0xffu) << (8 * (7 - b));
  return r;
}

std::uint32_t byteswap32(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

}  // namespace

Eigen::ArrayXXd read_npy(const std::filesystem::path& path) {
  std::ifstream in = open(path, std::ios::binary);
  char magic[8];
  if (!in.read(magic, 8) || std::memcmp(magic, "\x93NUMPY", 6) != 0) fail(path, "is not a .npy file");
  std::size_t header_len = 0;
  if (magic[6] == 1) {
    unsigned char b[2];
    if (!in.read(reinterpret_cast<char*>(b), 2)) fail(path, "truncated .npy header");
    header_len = b[0] | (static_cast<std::size_t>(b[1]) << 8);
  } else if (magic[6] == 2 || magic[6] == 3) {
    unsigned char b[4];
    if (!in.read(reinterpret_cast<char*>(b), 4)) fail(path, "truncated .npy header");
    header_len = b[0] | (static_cast<std::size_t>(b[1]) << 8) | (static_cast<std::size_t>(b[2]) << 16) |
                 (static_cast<std::size_t>(b[3]) << 24);
  } else {
    fail(path, "unsupported .npy version " + std::to_string(static_cast<int>(magic[6])));
  }
  if (header_len > (1u << 20)) fail(path, ".npy header too long");
  std::string header(header_len, '\0');
  if (!in.read(header.data(), static_cast<std::streamsize>(header_len))) fail(path, "truncated .npy header");

  std::smatch m;
  if (!std::regex_search(header, m, std::regex("'descr'\\s*:\\s*'([<>|=])([fi])(\\d+)'"))) {
    fail(path, ".npy header has no supported 'descr' (need float64 or float32)");
  }
  const char order = m[1].str()[0];
  const char type = m[2].str()[0];
  const int bytes = std::stoi(m[3].str());
  if (type != 'f' || (bytes != 8 && bytes != 4)) fail(path, "dtype must be float64 or float32");
  const bool big_endian_data = order == '>';
  const bool swap = big_endian_data != (std::endian::native == std::endian::big);
  const bool fortran = std::regex_search(header, std::regex("'fortran_order'\\s*:\\s*True"));
  if (!std::regex_search(header, m, std::regex("'shape'\\s*:\\s*\\(\\s*(\\d+)\\s*,\\s*(\\d+)\\s*,?\\s*\\)"))) {
    fail(path, ".npy array must be 2-D");
  }
  const Eigen::Index rows = std::stol(m[1].str()), cols = std::stol(m[2].str());
  if (rows < 1 || cols < 1) fail(path, ".npy array is empty");

  const auto count = static_cast<std::size_t>(rows * cols);
  std::vector<char> raw(count * static_cast<std::size_t>(bytes));
  if (!in.read(raw.data(), static_cast<std::streamsize>(raw.size()))) fail(path, "truncated .npy data");
  std::vector<double> values(count);
  for (std::size_t k = 0; k < count; ++k) {
    if (bytes == 8) {
      std::uint64_t u;
      std::memcpy(&u, raw.data() + 8 * k, 8);
      if (swap) u = byteswap64(u);
      values[k] = std::bit_cast<double>(u);
    } else {
      std::uint32_t u;
      std::memcpy(&u, raw.data() + 4 * k, 4);
      if (swap) u = byteswap32(u);
      values[k] = static_cast<double>(std::bit_cast<float>(u));
    }
  }
  Eigen::ArrayXXd h(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      h(i, j) = fortran ? values[static_cast<std::size_t>(i + j * rows)] : values[static_cast<std::size_t>(i * cols + j)];
    }
  }
  check_finite(path, h);
  return h;
}

Eigen::ArrayXXd read_ascii_matrix(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  std::vector<std::vector<double>> rows;
  std::vector<double> row;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!numbers_on_line(path, line_no, line, row)) continue;
    if (!rows.empty() && row.size() != rows.front().size()) {
      fail(path, "line " + std::to_string(line_no) + " has " + std::to_string(row.size()) + " values, expected " +
                     std::to_string(rows.front().size()));
    }
    rows.push_back(row);
  }
  if (rows.empty()) fail(path, "holds no heights");
  Eigen::ArrayXXd h(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.front().size()));
  for (Eigen::Index i = 0; i < h.rows(); ++i) {
    for (Eigen::Index j = 0; j < h.cols(); ++j) h(i, j) = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  }
  check_finite(path, h);
  return h;
}

Topography read_xyz(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  std::vector<std::array<double, 3>> points;
  std::vector<double> row;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!numbers_on_line(path, line_no, line, row)) continue;
    if (row.size() != 3) fail(path, "line " + std::to_string(line_no) + " must hold three columns x y z");
    points.push_back({row[0], row[1], row[2]});
  }
  if (points.empty()) fail(path, "holds no points");
  std::vector<double> xs, ys;
  for (const auto& p : points) {
    xs.push_back(p[0]);
    ys.push_back(p[1]);
  }
  auto unique_sorted = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  unique_sorted(xs);
  unique_sorted(ys);
  const auto nx = static_cast<Eigen::Index>(xs.size()), ny = static_cast<Eigen::Index>(ys.size());
  if (static_cast<std::size_t>(nx * ny) != points.size()) {
    fail(path, "points do not form a complete regular grid (" + std::to_string(points.size()) + " points, " +
                   std::to_string(nx) + " distinct x, " + std::to_string(ny) + " distinct y)");
  }
  auto spacing = [&](const std::vector<double>& v, const char* axis) {
    if (v.size() < 2) fail(path, std::string("needs at least two distinct ") + axis + " values");
    const double d = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
    for (std::size_t k = 1; k < v.size(); ++k) {
      if (std::abs(v[k] - v[k - 1] - d) > 1e-6 * d) fail(path, std::string(axis) + " values are not equally spaced");
    }
    return d;
  };
  const double dx = spacing(xs, "x"), dy = spacing(ys, "y");
  Topography t;
  t.heights_m.setConstant(nx, ny, std::numeric_limits<double>::quiet_NaN());
  for (const auto& p : points) {
    const auto i = static_cast<Eigen::Index>(std::lround((p[0] - xs.front()) / dx));
    const auto j = static_cast<Eigen::Index>(std::lround((p[1] - ys.front()) / dy));
    t.heights_m(i, j) = p[2];
  }
  check_finite(path, t.heights_m);
  t.lx_m = dx * static_cast<double>(nx);
  t.ly_m = dy * static_cast<double>(ny);
  return t;
}

Topography read_topography(const std::filesystem::path& path, double height_scale) {
  if (!(std::isfinite(height_scale) && height_scale > 0.0)) {
    throw std::invalid_argument("surface height scale must be positive and finite");
  }
  if (!std::filesystem::is_regular_file(path)) fail(path, "does not exist or is not a regular file");
  Topography t;
  const std::string ext = path.extension().string();
  if (ext == ".npy") {
    t.heights_m = read_npy(path);
  } else if (ext == ".xyz") {
    t = read_xyz(path);
  } else {
    t.heights_m = read_ascii_matrix(path);
  }
  t.heights_m *= height_scale;
  return t;
}

void write_npy(std::ostream& out, const Eigen::ArrayXXd& field) {
  static_assert(std::endian::native == std::endian::little, "write_npy writes little-endian float64");
  std::string header = "{'descr': '<f8', 'fortran_order': True, 'shape': (" + std::to_string(field.rows()) + ", " +
                       std::to_string(field.cols()) + "), }";
  // Magic (6) + version (2) + length (2) + header + '\n' must be a multiple of 64 bytes.
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  out.write("\x93NUMPY\x01\x00", 8);
  const auto len = static_cast<std::uint16_t>(header.size());
  const char len_bytes[2] = {static_cast<char>(len & 0xff), static_cast<char>(len >> 8)};
  out.write(len_bytes, 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  // Column-major storage is exactly numpy's Fortran order for shape (rows, cols).
  out.write(reinterpret_cast<const char*>(field.data()), static_cast<std::streamsize>(sizeof(double) * field.size()));
}

void write_npy(const std::filesystem::path& path, const Eigen::ArrayXXd& field) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  write_npy(out, field);
  if (!out.flush()) throw std::runtime_error("writing '" + path.string() + "' failed");
}

}  // namespace tribo::contact
