#include "numerics/format.h"

#include <cmath>
#include <cassert>
#include <charconv>
#include <cstdio>

namespace tribo::numerics {

std::string fmt(double v, const char* format) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string shortest(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  assert(ec == std::errc());  // the longest shortest form of a double has 24 characters
  return std::string(buf, end);
}

std::string join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : separator) + p;
  return out;
}

}  // namespace tribo::numerics
