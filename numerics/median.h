// The sample median as the robust estimators of rig/ and gap/ use it: a record's noise from its
// median deviation, a record's sampling from its median spacing, a segment's speed.
#pragma once

#include <vector>

namespace tribo::numerics {

// The upper of the two middle values (the middle one for an odd count) — an order statistic of the
// sample itself, so a quantised record's median is one of its quanta. In O(n) (nth_element on the
// copy). An empty sample has none: std::invalid_argument.
double median(std::vector<double> sample);

}  // namespace tribo::numerics
