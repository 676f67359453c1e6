// The plane-strain elastic-plastic cylinder (contact/reference/capped_cylinder.h) against its limits:
// Hertz's line contact where the cap does not bind, the fully plastic width where it binds everywhere.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/reference/capped_cylinder.h"

namespace tribo::contact {
namespace {

constexpr double kCylinderEStar_Pa = 1.154e11, kCylinderRadius_m = 0.01, kCylinderLoad_N_per_m = 1e5;

// Hertz (Johnson (4.43), (4.45)): b = √(4 w R/(π E*)), p0 = 2 w/(π b). 400 strips over ±3 b, each
// 0.015 b: the half width to one strip (2 %) — the strips are in or out — and the peak, averaged
// over the central strip of an elliptical profile, to 0.1 %.
TEST(CappedCylinderReference, WithoutTheCapItIsHertzsLineContact) {
  const double b = std::sqrt(4.0 * kCylinderLoad_N_per_m * kCylinderRadius_m / (std::numbers::pi * kCylinderEStar_Pa)), p0 = 2.0 * kCylinderLoad_N_per_m / (std::numbers::pi * b);
  const auto c = reference::capped_cylinder_contact(kCylinderLoad_N_per_m, kCylinderRadius_m, kCylinderEStar_Pa, 10.0 * p0, 400);
  EXPECT_NEAR(c.contact_half_width_m / b, 1.0, 0.02);
  EXPECT_NEAR(c.peak_pressure_Pa / p0, 1.0, 1e-3);
  EXPECT_EQ(c.plastic_half_width_m, 0.0);
  for (double x : {-0.8 * b, -0.5 * b, 0.0, 0.3 * b, 0.7 * b})
    EXPECT_NEAR(reference::pressure_at_Pa(c, x) / p0, std::sqrt(1.0 - x * x / (b * b)), 5e-3) << "x/b = " << x / b;
}

// A cap far below p0 (0.02 p0): the contact is plastic but for its edge strips, its half width the
// load over twice the cap, w/(2 p_cap), to 2 %; at 0.8 p0 the plastic zone lies inside the contact.
TEST(CappedCylinderReference, FarBelowHertzsPeakTheContactIsFullyPlastic) {
  const double b = std::sqrt(4.0 * kCylinderLoad_N_per_m * kCylinderRadius_m / (std::numbers::pi * kCylinderEStar_Pa)), p0 = 2.0 * kCylinderLoad_N_per_m / (std::numbers::pi * b);
  const double cap = 0.02 * p0;
  const auto plastic = reference::capped_cylinder_contact(kCylinderLoad_N_per_m, kCylinderRadius_m, kCylinderEStar_Pa, cap, 400);
  EXPECT_NEAR(plastic.contact_half_width_m / (kCylinderLoad_N_per_m / (2.0 * cap)), 1.0, 0.02);
  EXPECT_DOUBLE_EQ(plastic.peak_pressure_Pa, cap);
  const auto partly = reference::capped_cylinder_contact(kCylinderLoad_N_per_m, kCylinderRadius_m, kCylinderEStar_Pa, 0.8 * p0, 400);
  EXPECT_GT(partly.plastic_half_width_m, 0.3 * b);
  EXPECT_LT(partly.plastic_half_width_m, partly.contact_half_width_m);
  EXPECT_GT(partly.contact_half_width_m, b);  // the capped load spreads wider
}

}  // namespace
}  // namespace tribo::contact
