// The check the line and point contacts' capped solves share (ehl_line_mixed_slow_test.cpp,
// ehl_point_mixed_test.cpp): a capped contact reached by two routes — the cap lowered on the grid
// itself, and the nesting that lowers it on a coarser grid — is one discrete problem with one answer.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tribo::lubrication {

// Expects both converged, `lowered` through cap steps and `nested` through none on its own grid, the
// same pressures to `tolerance` of p_H, the same yielded nodes (those at `hardness_Pa`) and the load
// on them to `tolerance`; returns the largest pressure difference in units of p_H.
template <class Result>
double expect_one_capped_answer(const Result& lowered, const Result& nested, double hardness_Pa, double tolerance) {
  EXPECT_TRUE(lowered.converged) << lowered.message;
  EXPECT_TRUE(nested.converged) << nested.message;
  EXPECT_GT(lowered.continuation_steps, 5);
  EXPECT_EQ(nested.continuation_steps, 0);
  EXPECT_EQ(nested.pressure_Pa.size(), lowered.pressure_Pa.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(nested.pressure_Pa.size(), lowered.pressure_Pa.size()); ++k) {
    worst = std::max(worst, std::abs(nested.pressure_Pa[k] - lowered.pressure_Pa[k]) / lowered.hertz_pressure_Pa);
    EXPECT_EQ(nested.pressure_Pa[k] == hardness_Pa, lowered.pressure_Pa[k] == hardness_Pa) << "node " << k;
  }
  EXPECT_LT(worst, tolerance);
  EXPECT_EQ(nested.plastic_nodes, lowered.plastic_nodes);
  EXPECT_NEAR(nested.plastic_load_share, lowered.plastic_load_share, tolerance);
  return worst;
}

}  // namespace tribo::lubrication
