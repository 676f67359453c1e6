// A double printed with enough digits to read back the same value (for error messages that quote
// table entries and query points).
#pragma once

#include <limits>
#include <sstream>
#include <string>

namespace tribo::rig::internal {

inline std::string exact_decimal(double v) {
  std::ostringstream s;
  s.precision(std::numeric_limits<double>::max_digits10);
  s << v;
  return s.str();
}

}  // namespace tribo::rig::internal
