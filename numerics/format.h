// How a number is printed in reports, labels and CSV fields — one rule for every library and
// command.
#pragma once

#include <string>

namespace tribo::numerics {

// `v` printed with the printf `format` (one double conversion); "" for NaN or ±∞ (an observable
// that does not exist, e.g. the period of a run that never oscillates).
std::string fmt(double v, const char* format = "%.4g");

}  // namespace tribo::numerics
