// numerics/format.h: how numbers and lists of names are printed in reports and messages.
#include "numerics/format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tribo::numerics {
namespace {

// A list of names is joined with its separator between the parts, never before the first or after
// the last: an effect list reads "a+b", names in prose "a, b", one part stands alone, none is "".
TEST(Join, PutsTheSeparatorBetweenThePartsOnly) {
  EXPECT_EQ(join({"squeeze_film", "viscous_friction"}, "+"), "squeeze_film+viscous_friction");
  EXPECT_EQ(join({"a", "b", "c"}, ", "), "a, b, c");
  EXPECT_EQ(join({"rate_dependent_static"}, ", "), "rate_dependent_static");
  EXPECT_EQ(join({}, "+"), "");
}

// The shortest decimal reads back as the same double (the message rule of format.h), where a fixed
// six decimals would print -2e-7 as "-0.000000"; fmt leaves a value that does not exist empty.
TEST(Format, ShortestReadsBackAndFmtLeavesNonFiniteValuesEmpty) {
  EXPECT_EQ(shortest(-2e-7), "-2e-07");
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(std::stod(shortest(1.0 / 3.0)), 1.0 / 3.0);
  EXPECT_EQ(fmt(0.123456, "%.3g"), "0.123");
  EXPECT_EQ(fmt(std::numeric_limits<double>::quiet_NaN()), "");
  EXPECT_EQ(fmt(std::numeric_limits<double>::infinity()), "");
}

}  // namespace
}  // namespace tribo::numerics
