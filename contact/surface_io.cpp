#include "contact/surface_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
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

void check_count(const std::filesystem::path& path, std::size_t count) {
  if (count > kMaxSurfaceHeights) {
    fail(path, "holds more than " + std::to_string(kMaxSurfaceHeights) + " heights (the reader's limit)");
  }
}

// A token quoted in a message: cut short (a hostile file may hold a megabyte-long "number") and
// with control bytes escaped (a NUL would end what() early, others garble the terminal).
std::string shown(const std::string& s) {
  constexpr std::size_t kShown = 40;
  std::string out = "'";
  for (std::size_t k = 0; k < s.size() && k < kShown; ++k) {
    const auto c = static_cast<unsigned char>(s[k]);
    if (c < 0x20 || c == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + (s.size() > kShown ? "...'" : "'");
}

// std::getline with a bound: a file without line breaks must not become one string of its size.
// Reads in chunks with istream::getline (libstdc++ scans its buffer for '\n' rather than going
// byte by byte); the '\n' is consumed, not stored.
bool read_line(std::istream& in, std::string& line, const std::filesystem::path& path, std::size_t line_no) {
  line.clear();
  char buf[1 << 16];
  for (;;) {
    in.getline(buf, sizeof buf, '\n');
    const auto n = static_cast<std::size_t>(in.gcount());
    bool ended = true;
    if (in.eof()) {
      line.append(buf, n);
    } else if (in.fail()) {
      in.clear();  // the chunk filled up before the line ended
      line.append(buf, n);
      ended = false;
    } else {
      line.append(buf, n - 1);  // gcount counts the '\n'
    }
    if (line.size() > kMaxSurfaceLineBytes) {
      fail(path, "line " + std::to_string(line_no) + " is longer than " + std::to_string(kMaxSurfaceLineBytes) + " bytes");
    }
    if (ended) return !in.eof() || !line.empty();
  }
}

// Splits a data line on whitespace and commas; returns false for blank and comment lines.
bool numbers_on_line(const std::filesystem::path& path, std::size_t line_no, const std::string& line,
                     std::vector<double>& out) {
  out.clear();
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos || line[first] == '#' || line[first] == '%') return false;
  const auto separator = [](char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); };
  std::size_t pos = 0;
  std::string tok;
  while (pos < line.size()) {
    while (pos < line.size() && separator(line[pos])) ++pos;
    std::size_t end_tok = pos;
    while (end_tok < line.size() && !separator(line[end_tok])) ++end_tok;
    if (end_tok == pos) break;
    tok.assign(line, pos, end_tok - pos);
    pos = end_tok;
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    // The whole token must be the number (a NUL byte inside it would otherwise end it early).
    if (end != tok.c_str() + tok.size() || tok.empty()) {
      fail(path, "line " + std::to_string(line_no) + ": " + shown(tok) + " is not a number");
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

// The .npy header is a Python dict literal: {'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }.
// A small recursive-descent reader instead of std::regex, whose backtracking recurses once per
// character and overflows the stack on a long hostile header.
struct NpyHeader {
  std::string descr;
  bool fortran = false;
  std::vector<std::size_t> shape;
  bool has_descr = false, has_order = false, has_shape = false;
};

class NpyHeaderParser {
 public:
  NpyHeaderParser(const std::string& text, const std::filesystem::path& path) : s_(text), path_(path) {}

  NpyHeader parse() {
    NpyHeader h;
    expect('{');
    for (;;) {
      skip_space();
      if (peek() == '}') break;
      const std::string key = string_literal();
      expect(':');
      if (key == "descr" && !h.has_descr) {
        h.descr = string_literal();
        h.has_descr = true;
      } else if (key == "fortran_order" && !h.has_order) {
        h.fortran = boolean();
        h.has_order = true;
      } else if (key == "shape" && !h.has_shape) {
        h.shape = tuple();
        h.has_shape = true;
      } else {
        bad("unexpected or repeated key " + shown(key));
      }
      skip_space();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (peek() != '}') bad("expected ',' or '}'");
    }
    ++pos_;
    skip_space();
    if (pos_ != s_.size()) bad("text after the closing '}'");
    if (!h.has_descr || !h.has_order || !h.has_shape) bad("needs the keys 'descr', 'fortran_order' and 'shape'");
    return h;
  }

 private:
  [[noreturn]] void bad(const std::string& why) const {
    fail(path_, ".npy header: " + why + " (at byte " + std::to_string(pos_) + ")");
  }
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  void expect(char c) {
    skip_space();
    if (peek() != c) bad(std::string("expected '") + c + "'");
    ++pos_;
  }
  std::string string_literal() {
    skip_space();
    const char q = peek();
    if (q != '\'' && q != '"') bad("expected a quoted string");
    const auto close = s_.find(q, pos_ + 1);
    if (close == std::string::npos) bad("unterminated string");
    std::string out = s_.substr(pos_ + 1, close - pos_ - 1);
    pos_ = close + 1;
    return out;
  }
  bool boolean() {
    skip_space();
    if (s_.compare(pos_, 4, "True") == 0) {
      pos_ += 4;
      return true;
    }
    if (s_.compare(pos_, 5, "False") == 0) {
      pos_ += 5;
      return false;
    }
    bad("expected True or False");
  }
  std::vector<std::size_t> tuple() {
    expect('(');
    std::vector<std::size_t> dims;
    for (;;) {
      skip_space();
      if (peek() == ')') break;
      if (!std::isdigit(static_cast<unsigned char>(peek()))) bad("expected a dimension");
      std::size_t d = 0;
      while (std::isdigit(static_cast<unsigned char>(peek()))) {
        d = d * 10 + static_cast<std::size_t>(peek() - '0');
        // Larger than any readable array: stop before the digits overflow.
        if (d > kMaxSurfaceHeights) fail(path_, ".npy shape holds more than " + std::to_string(kMaxSurfaceHeights) + " heights");
        ++pos_;
      }
      dims.push_back(d);
      if (dims.size() > 32) bad("too many dimensions");
      skip_space();
      if (peek() == ',') {
        ++pos_;
      } else if (peek() != ')') {
        bad("expected ',' or ')' in the shape");
      }
    }
    ++pos_;
    return dims;
  }

  const std::string& s_;
  const std::filesystem::path& path_;
  std::size_t pos_ = 0;
};

}  // namespace

Eigen::ArrayXXd read_npy(std::istream& in, const std::filesystem::path& path) {
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

  const NpyHeader h = NpyHeaderParser(header, path).parse();
  const std::string& d = h.descr;
  if (d.size() < 3 || (d[0] != '<' && d[0] != '>' && d[0] != '=' && d[0] != '|') ||
      !(d.substr(1) == "f8" || d.substr(1) == "f4")) {
    fail(path, "dtype " + shown(d) + " is not supported (need float64 or float32)");
  }
  const int bytes = d[2] == '8' ? 8 : 4;
  const bool big_endian_data = d[0] == '>' || (d[0] == '=' && std::endian::native == std::endian::big);
  const bool swap = big_endian_data != (std::endian::native == std::endian::big);
  if (h.shape.size() != 2) fail(path, ".npy array must be 2-D (shape has " + std::to_string(h.shape.size()) + " dimensions)");
  const std::size_t rows = h.shape[0], cols = h.shape[1];
  if (rows < 1 || cols < 1) fail(path, ".npy array is empty");
  // Each factor is at most the limit, so the product cannot overflow 64 bits.
  check_count(path, rows * cols);
  const std::size_t count = rows * cols;

  // Read in bounded chunks: the shape is a claim of the file, the allocation follows the bytes
  // that actually arrive (a 100-byte file claiming 1e8 heights must not allocate 800 MB).
  const std::size_t total = count * static_cast<std::size_t>(bytes);
  std::vector<char> raw;
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  while (raw.size() < total) {
    const std::size_t n = std::min(kChunk, total - raw.size());
    const std::size_t at = raw.size();
    raw.resize(at + n);
    if (!in.read(raw.data() + at, static_cast<std::streamsize>(n))) {
      fail(path, "truncated .npy data (the shape needs " + std::to_string(total) + " bytes)");
    }
  }
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
  const auto nr = static_cast<Eigen::Index>(rows), nc = static_cast<Eigen::Index>(cols);
  Eigen::ArrayXXd a(nr, nc);
  for (Eigen::Index j = 0; j < nc; ++j) {
    for (Eigen::Index i = 0; i < nr; ++i) {
      a(i, j) = h.fortran ? values[static_cast<std::size_t>(i + j * nr)] : values[static_cast<std::size_t>(i * nc + j)];
    }
  }
  check_finite(path, a);
  return a;
}

Eigen::ArrayXXd read_npy(const std::filesystem::path& path) {
  std::ifstream in = open(path, std::ios::binary);
  return read_npy(in, path);
}

Eigen::ArrayXXd read_ascii_matrix(std::istream& in, const std::filesystem::path& path) {
  // One flat vector, row after row: a vector per row costs ~32 bytes of overhead for every line
  // of a one-column file.
  std::vector<double> values, row;
  std::size_t cols = 0, rows = 0;
  std::string line;
  std::size_t line_no = 0;
  while (read_line(in, line, path, line_no + 1)) {
    ++line_no;
    if (!numbers_on_line(path, line_no, line, row)) continue;
    if (rows > 0 && row.size() != cols) {
      fail(path, "line " + std::to_string(line_no) + " has " + std::to_string(row.size()) + " values, expected " +
                     std::to_string(cols));
    }
    cols = row.size();
    ++rows;
    check_count(path, values.size() + row.size());
    values.insert(values.end(), row.begin(), row.end());
  }
  if (rows == 0) fail(path, "holds no heights");
  Eigen::ArrayXXd h(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  for (Eigen::Index i = 0; i < h.rows(); ++i) {
    for (Eigen::Index j = 0; j < h.cols(); ++j) h(i, j) = values[static_cast<std::size_t>(i) * cols + static_cast<std::size_t>(j)];
  }
  check_finite(path, h);
  return h;
}

Eigen::ArrayXXd read_ascii_matrix(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  return read_ascii_matrix(in, path);
}

Topography read_xyz(std::istream& in, const std::filesystem::path& path) {
  std::vector<std::array<double, 3>> points;
  std::vector<double> row;
  std::string line;
  std::size_t line_no = 0;
  while (read_line(in, line, path, line_no + 1)) {
    ++line_no;
    if (!numbers_on_line(path, line_no, line, row)) continue;
    if (row.size() != 3) fail(path, "line " + std::to_string(line_no) + " must hold three columns x y z");
    // Grid positions become array indices below: a NaN or infinite x or y must stop here.
    if (!std::isfinite(row[0]) || !std::isfinite(row[1])) fail(path, "line " + std::to_string(line_no) + ": x and y must be finite");
    check_count(path, points.size() + 1);
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
  if (static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) != points.size()) {
    fail(path, "points do not form a complete regular grid (" + std::to_string(points.size()) + " points, " +
                   std::to_string(nx) + " distinct x, " + std::to_string(ny) + " distinct y)");
  }
  auto spacing = [&](const std::vector<double>& v, const char* axis) {
    if (v.size() < 2) fail(path, std::string("needs at least two distinct ") + axis + " values");
    const double d = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
    if (!(std::isfinite(d) && d > 0.0)) fail(path, std::string(axis) + " values span more than a double can hold");
    for (std::size_t k = 1; k < v.size(); ++k) {
      if (std::abs(v[k] - v[k - 1] - d) > 1e-6 * d) fail(path, std::string(axis) + " values are not equally spaced");
    }
    return d;
  };
  const double dx = spacing(xs, "x"), dy = spacing(ys, "y");
  Topography t;
  t.heights_m.setConstant(nx, ny, std::numeric_limits<double>::quiet_NaN());
  std::vector<bool> filled(points.size(), false);
  for (const auto& p : points) {
    const double fi = std::round((p[0] - xs.front()) / dx), fj = std::round((p[1] - ys.front()) / dy);
    // Equal spacing within 1e-6 keeps the indices in range; checked all the same, since an
    // index out of range would write outside the array.
    if (!(fi >= 0.0 && fi < static_cast<double>(nx) && fj >= 0.0 && fj < static_cast<double>(ny))) {
      fail(path, "a point falls outside the grid");
    }
    const auto i = static_cast<Eigen::Index>(fi), j = static_cast<Eigen::Index>(fj);
    const auto cell = static_cast<std::size_t>(i) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(j);
    if (filled[cell]) fail(path, "two points fall on the grid node (" + std::to_string(i) + ", " + std::to_string(j) + ")");
    filled[cell] = true;
    t.heights_m(i, j) = p[2];
  }
  check_finite(path, t.heights_m);
  t.lx_m = dx * static_cast<double>(nx);
  t.ly_m = dy * static_cast<double>(ny);
  if (!std::isfinite(t.lx_m) || !std::isfinite(t.ly_m)) fail(path, "the grid's sides overflow a double");
  return t;
}

Topography read_xyz(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  return read_xyz(in, path);
}

// ---- Instrument headers (measured maps): sizes and units stated in the file itself ----------

namespace {

// Metres per unit for the length units instruments write (µ as U+00B5 or U+03BC, or "u"); 0 if
// the unit is not a length.
double metres_per(std::string unit) {
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back()))) unit.pop_back();
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front()))) unit.erase(0, 1);
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\xc2\xb5m" || unit == "\xce\xbcm") return 1e-6;
  if (unit == "nm") return 1e-9;
  if (unit == "A" || unit == "\xc3\x85") return 1e-10;
  return 0.0;
}

double header_number(const std::filesystem::path& path, const std::string& text, const std::string& key) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(v) || v <= 0.0) fail(path, "header " + key + " " + shown(text) + " is not a positive number");
  return v;
}

// A count of rows or columns: a whole number no larger than the reader holds heights (a claim of
// 2.8e62 rows was cast to long for the mismatch message — undefined; found by fuzz_surface).
double header_count(const std::filesystem::path& path, const std::string& text, const std::string& key) {
  const double v = header_number(path, text, key);
  if (v != std::floor(v) || v > static_cast<double>(kMaxSurfaceHeights))
    fail(path, "header " + key + " " + shown(text) + " is not a whole number of at most " + std::to_string(kMaxSurfaceHeights));
  return v;
}

// "VALUE UNIT" (e.g. "3.69862e-007 m", "10.00 µm") in metres.
double header_length_m(const std::filesystem::path& path, const std::string& text, const std::string& key) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const double unit = metres_per(end);
  if (end == text.c_str() || !std::isfinite(v) || v <= 0.0 || unit == 0.0) {
    fail(path, "header " + key + " " + shown(text) + " is not a positive length with a unit (m, mm, um, nm)");
  }
  return v * unit;
}

// What a header states; 0 where it is silent.
struct AsciiHeader {
  double rows = 0, cols = 0;             // "h=ROWS w=COLS"
  double pixel_m = 0;                    // "pixel size=VALUE UNIT"
  double extent_rows_m = 0, extent_cols_m = 0;  // Gwyddion "# Height:" (rows) and "# Width:" (columns)
  double height_unit_m = 0;              // metres per stored height value
  std::string data_unit;                 // "data unit=" / "# Value units:", as written
};

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// Consumes one header line: a '#'/'%' comment (Gwyddion's "# Width: 10.00 µm" keys are read,
// other comments ignored), a blank line, or one of the "key=value" lines of the interferometer
// export ("h=650 w=650", "pixel size=...", "data unit=...", "height conversion factor (-> m)=...").
// Returns false at the first line that is none of these (the data).
bool header_line(const std::filesystem::path& path, const std::string& raw, AsciiHeader& hdr) {
  const std::string line = trimmed(raw);
  if (line.empty()) return true;
  if (line[0] == '#' || line[0] == '%') {
    const std::string body = trimmed(line.substr(1));
    const auto colon = body.find(':');
    if (colon == std::string::npos) return true;
    const std::string key = body.substr(0, colon), value = trimmed(body.substr(colon + 1));
    if (key == "Width") hdr.extent_cols_m = header_length_m(path, value, "Width");
    if (key == "Height") hdr.extent_rows_m = header_length_m(path, value, "Height");
    if (key == "Value units") hdr.data_unit = value;
    return true;
  }
  const auto eq = line.find('=');
  if (eq == std::string::npos || !std::isalpha(static_cast<unsigned char>(line[0]))) return false;
  const std::string key = trimmed(line.substr(0, eq)), value = trimmed(line.substr(eq + 1));
  if (key == "h") {  // "h=650 w=650"
    const auto w = value.find("w=");
    if (w == std::string::npos) fail(path, "header " + shown(line) + " must read h=ROWS w=COLUMNS");
    hdr.rows = header_count(path, value.substr(0, w), "h");
    hdr.cols = header_count(path, value.substr(w + 2), "w");
  } else if (key == "pixel size") {
    hdr.pixel_m = header_length_m(path, value, "pixel size");
  } else if (key == "data unit") {
    hdr.data_unit = value;
  } else if (key == "height conversion factor (-> m)") {
    hdr.height_unit_m = header_number(path, value, "height conversion factor");
  } else {
    fail(path, "unknown header line " + shown(line));
  }
  return true;
}

// Dektak exports begin with "Scan Parameters"; other .csv and text files are matrices.
bool is_dektak_csv(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  std::string first;
  return read_line(in, first, path, 1) && trimmed(first) == "Scan Parameters";
}

}  // namespace

Topography read_ascii_topography(std::istream& in, const std::filesystem::path& path) {
  AsciiHeader hdr;
  std::string line;
  std::size_t header_lines = 0;
  for (;;) {
    const std::streampos start = in.rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in);
    if (!read_line(in, line, path, header_lines + 1)) break;
    if (!header_line(path, line, hdr)) {
      if (start == std::streampos(-1) || in.rdbuf()->pubseekpos(start, std::ios::in) != start) {
        fail(path, "cannot step back to the first data line (stream not seekable)");
      }
      break;
    }
    ++header_lines;
  }
  Topography t;
  if (header_lines == 0) {
    t.heights_m = read_ascii_matrix(in, path);
  } else {  // the header's lines left blank, so that error messages keep the file's line numbers
    std::stringstream rest;
    rest << std::string(header_lines, '\n') << in.rdbuf();
    t.heights_m = read_ascii_matrix(rest, path);
  }
  const auto rows = static_cast<double>(t.heights_m.rows()), cols = static_cast<double>(t.heights_m.cols());
  if ((hdr.rows > 0 && hdr.rows != rows) || (hdr.cols > 0 && hdr.cols != cols)) {
    fail(path, "header says " + std::to_string(static_cast<long>(hdr.rows)) + " x " + std::to_string(static_cast<long>(hdr.cols)) +
                   " heights, the file holds " + std::to_string(t.heights_m.rows()) + " x " + std::to_string(t.heights_m.cols()));
  }
  if (hdr.pixel_m > 0) {
    t.lx_m = hdr.pixel_m * rows;
    t.ly_m = hdr.pixel_m * cols;
  }
  if (hdr.extent_rows_m > 0 || hdr.extent_cols_m > 0) {
    if (!(hdr.extent_rows_m > 0 && hdr.extent_cols_m > 0)) fail(path, "header gives only one of Width and Height");
    t.lx_m = hdr.extent_rows_m;
    t.ly_m = hdr.extent_cols_m;
  }
  if (hdr.height_unit_m == 0 && !hdr.data_unit.empty()) {
    hdr.height_unit_m = metres_per(hdr.data_unit);
    if (hdr.height_unit_m == 0) fail(path, "data unit " + shown(hdr.data_unit) + " needs a height conversion factor (-> m)");
  }
  if (hdr.height_unit_m > 0) {
    t.heights_m *= hdr.height_unit_m;
    t.height_unit_from_file = true;
  }
  return t;
}

Topography read_dektak_csv(std::istream& in, const std::filesystem::path& path) {
  std::string line;
  std::size_t line_no = 0;
  double length_m = 0.0, unit_m = 0.0;
  std::vector<double> heights;
  bool data = false;
  while (read_line(in, line, path, line_no + 1)) {
    ++line_no;
    const std::string s = trimmed(line);
    if (!data) {
      if (s.rfind("Length,", 0) == 0) length_m = header_length_m(path, s.substr(7), "Length");
      if (s.rfind("Lateral um,", 0) == 0) {
        const std::string column = trimmed(s.substr(11, s.find(',', 11) - 11));
        if (column == "Raw Micrometer" || column == "Normal Micrometer") unit_m = 1e-6;
        else if (column == "Raw Angstrom" || column == "Normal Angstrom") unit_m = 1e-10;
        else fail(path, "line " + std::to_string(line_no) + ": height column " + shown(column) + " has no known unit");
        data = true;
      }
      continue;
    }
    if (s.empty()) continue;
    const auto c1 = s.find(',');
    const std::string z = s.substr(c1 == std::string::npos ? s.size() : c1 + 1, s.find(',', c1 + 1) - (c1 + 1));
    char* end = nullptr;
    const double v = std::strtod(z.c_str(), &end);
    if (c1 == std::string::npos || end == z.c_str() || *end != '\0') {
      fail(path, "line " + std::to_string(line_no) + ": " + shown(s) + " is not 'lateral,height'");
    }
    check_count(path, heights.size() + 1);
    heights.push_back(v * unit_m);
  }
  if (!data) fail(path, "has no 'Lateral um,...' data header (not a Dektak export?)");
  if (!(length_m > 0.0)) fail(path, "has no scan Length in its header");
  Topography t;
  t.heights_m = Eigen::Map<const Eigen::ArrayXd>(heights.data(), static_cast<Eigen::Index>(heights.size()));
  check_finite(path, t.heights_m);
  t.lx_m = length_m;  // the scan length over its samples (Length / n per sample)
  t.ly_m = length_m / static_cast<double>(heights.size());  // a line one sample wide
  t.height_unit_from_file = true;
  return t;
}

Topography read_ascii_topography(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  return read_ascii_topography(in, path);
}

Topography read_dektak_csv(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  return read_dektak_csv(in, path);
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
  } else if (ext == ".csv" && is_dektak_csv(path)) {
    t = read_dektak_csv(path);
  } else {
    t = read_ascii_topography(path);
  }
  if (t.height_unit_from_file && height_scale != 1.0) {
    fail(path, "states its height unit in its header; a height scale would convert twice (leave it at 1)");
  }
  t.heights_m *= height_scale;
  if (!t.heights_m.allFinite()) fail(path, "heights overflow a double once multiplied by the height scale");
  return t;
}

namespace {

// A float64 .npy's magic, version, header length and header for `shape` ("(3, 4)", "(7,)").
void write_npy_header(std::ostream& out, const std::string& shape) {
  static_assert(std::endian::native == std::endian::little, "write_npy writes little-endian float64");
  std::string header = "{'descr': '<f8', 'fortran_order': True, 'shape': " + shape + ", }";
  // Magic (6) + version (2) + length (2) + header + '\n' must be a multiple of 64 bytes.
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  out.write("\x93NUMPY\x01\x00", 8);
  const auto len = static_cast<std::uint16_t>(header.size());
  const char len_bytes[2] = {static_cast<char>(len & 0xff), static_cast<char>(len >> 8)};
  out.write(len_bytes, 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
}

}  // namespace

void write_npy(std::ostream& out, const Eigen::ArrayXXd& field) {
  // The shape appended to a std::string, not "(" + …: GCC 12 warns falsely (-Wrestrict) on a literal + string&&.
  write_npy_header(out, std::string("(").append(std::to_string(field.rows())).append(", ").append(std::to_string(field.cols())).append(")"));
  // Column-major storage is exactly numpy's Fortran order for shape (rows, cols).
  out.write(reinterpret_cast<const char*>(field.data()), static_cast<std::streamsize>(sizeof(double) * field.size()));
}

void write_npy(std::ostream& out, const std::vector<double>& profile) {
  write_npy_header(out, std::string("(").append(std::to_string(profile.size())).append(",)"));
  out.write(reinterpret_cast<const char*>(profile.data()), static_cast<std::streamsize>(sizeof(double) * profile.size()));
}

void write_npy(const std::filesystem::path& path, const Eigen::ArrayXXd& field) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  write_npy(out, field);
  if (!out.flush()) throw std::runtime_error("writing '" + path.string() + "' failed");
}

}  // namespace tribo::contact
