#include "numerics/json_numbers.h"

#include <cmath>
#include <limits>

namespace tribo::numerics {

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json finite_or_null(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const double x : v) a.push_back(finite_or_null(x));
  return a;
}

std::vector<double> doubles_with_nans(const nlohmann::json& array) {
  std::vector<double> v;
  for (const auto& x : array) v.push_back(x.is_null() ? std::numeric_limits<double>::quiet_NaN() : x.get<double>());
  return v;
}

}  // namespace tribo::numerics
