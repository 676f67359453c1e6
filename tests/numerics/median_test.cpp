// numerics/median.h: the order statistic on samples whose median is known by counting.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "numerics/median.h"

namespace tribo::numerics {
namespace {

// Odd count: the middle value of the sorted sample, whatever the input order (7 values, the 4th
// smallest is 3). Exact: the median is one of the sample's values.
TEST(Median, OddSampleGivesItsMiddleValue) { EXPECT_EQ(median({9.0, -1.0, 3.0, 7.0, 0.5, 3.0, 12.0}), 3.0); }

// Even count: the upper of the two middle values (sorted 1, 2, 4, 8 → 4), not their mean (3) — a
// quantised record's median stays on a quantum.
TEST(Median, EvenSampleGivesTheUpperMiddleValue) { EXPECT_EQ(median({8.0, 1.0, 4.0, 2.0}), 4.0); }

// One gross outlier does not move it: 0.1 × (1 … 101) with the largest replaced by 1e300 keeps
// the 51st value, 5.1.
TEST(Median, AnOutlierDoesNotMoveIt) {
  std::vector<double> v;
  for (int i = 1; i <= 101; ++i) v.push_back(0.1 * i);
  v.back() = 1e300;
  EXPECT_DOUBLE_EQ(median(v), 5.1);
}

TEST(Median, EmptySampleIsRejected) { EXPECT_THROW(median({}), std::invalid_argument); }

}  // namespace
}  // namespace tribo::numerics
