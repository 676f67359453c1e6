#include "numerics/format.h"

#include <cmath>
#include <cstdio>

namespace tribo::numerics {

std::string fmt(double v, const char* format) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace tribo::numerics
