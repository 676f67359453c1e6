#include "numerics/format.h"

#include <cmath>
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
  return ec == std::errc() ? std::string(buf, end) : fmt(v, "%.17g");  // 32 characters always suffice
}

}  // namespace tribo::numerics
