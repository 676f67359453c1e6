// How a number that does not exist is written to JSON, and read back. JSON has no NaN or ∞, so an
// absent value — an observable a run never shows, a confidence that cannot be estimated, a film
// that was not solved — is null in every file tribo writes, and null reads back as NaN.
#pragma once

#include <nlohmann/json.hpp>

#include <vector>

namespace tribo::numerics {

// `v`, or null where it is NaN or ±∞.
nlohmann::json finite_or_null(double v);
// The same, element by element, as a JSON array.
nlohmann::json finite_or_null(const std::vector<double>& v);
// An array written by finite_or_null back to doubles, null as NaN. Throws nlohmann::json::exception
// on an element that is neither a number nor null.
std::vector<double> doubles_with_nans(const nlohmann::json& array);

}  // namespace tribo::numerics
