// How a number — or a list of names — is printed in reports, labels and CSV fields: one rule for
// every library and command.
#pragma once

#include <string>
#include <vector>

namespace tribo::numerics {

// `v` printed with the printf `format` (one double conversion); "" for NaN or ±∞ (an observable
// that does not exist, e.g. the period of a run that never oscillates).
std::string fmt(double v, const char* format = "%.4g");

// `v` as the shortest decimal that reads back as the same double ("-2e-07", "0.1", "1e+300"; "nan",
// "inf", "-inf"): the numbers of error and status messages, where std::to_string's fixed six
// decimals print a height of -2e-7 m as "-0.000000".
std::string shortest(double v);

// `parts` with `separator` between them ("" for none): effect lists ("a+b"), names in prose ("a, b").
std::string join(const std::vector<std::string>& parts, const std::string& separator);

}  // namespace tribo::numerics
