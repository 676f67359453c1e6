// The stationary surface of the mixed EHL contacts (lubrication/ehl_roughness.h): the profile's
// interpolation, its checks, and the pressure-flow coefficient at a face with boundary layers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "lubrication/ehl_roughness.h"

namespace tribo::lubrication {
namespace {

// validate()'s message for `r`, or "accepted".
std::string message(const EhlRoughness& r) {
  try {
    validate(r, "who");
  } catch (const std::invalid_argument& e) {
    return std::string(e.what());
  }
  return "accepted";
}

// Linear between the points (the midpoint of a 2 nm rise is 1 nm, to round-off), the end points
// themselves, and zero outside the profile.
TEST(EhlRoughness, HeightIsLinearBetweenPointsAndZeroOutside) {
  const EhlRoughness r{{-1e-4, 0.0, 2e-4}, {0.0, 2e-9, -4e-9}};
  EXPECT_NEAR(ridge_height_m(r, -5e-5), 1e-9, 1e-24);
  EXPECT_NEAR(ridge_height_m(r, 1e-4), -1e-9, 1e-24);
  EXPECT_EQ(ridge_height_m(r, 2e-4), -4e-9);
  EXPECT_EQ(ridge_height_m(r, -1e-4), 0.0);
  EXPECT_EQ(ridge_height_m(r, -1.1e-4), 0.0);
  EXPECT_EQ(ridge_height_m(r, 2.1e-4), 0.0);
}

// a cos(2πx/λ) at evenly spaced points from `from` to `to`: a crest at x = 0, a trough at λ/2.
TEST(EhlRoughness, CosineRidgesSampleTheWaviness) {
  const EhlRoughness r = cosine_ridges(-1e-4, 1e-4, 2e-8, 4e-5, 201);
  ASSERT_EQ(r.x_m.size(), 201u);
  EXPECT_EQ(r.x_m.front(), -1e-4);
  EXPECT_EQ(r.x_m.back(), 1e-4);
  EXPECT_NEAR(ridge_height_m(r, 0.0), 2e-8, 1e-22);
  EXPECT_NEAR(ridge_height_m(r, 2e-5), -2e-8, 1e-22);
  EXPECT_NEAR(r.x_m[1] - r.x_m[0], 1e-6, 1e-18);
  EXPECT_EQ(r.contact_film_m, EhlRoughness{}.contact_film_m);
  EXPECT_THROW(cosine_ridges(0.0, 1e-4, 1e-8, 1e-5, 1), std::invalid_argument);
}

TEST(EhlRoughness, BadProfileIsRejectedWithItsReason) {
  EXPECT_EQ(message({{0.0, 1e-3}, {0.0, 0.0}}), "accepted");
  EXPECT_NE(message({{0.0}, {0.0}}).find("who: the roughness profile needs at least two points"), std::string::npos);
  EXPECT_NE(message({{0.0, 1e-3}, {0.0}}).find("as many heights"), std::string::npos);
  EXPECT_NE(message({{0.0, 0.0}, {0.0, 1e-9}}).find("must increase, point 1"), std::string::npos);
  EXPECT_NE(message({{0.0, 1e-3}, {0.0, NAN}}).find("point 1 is not finite"), std::string::npos);
  EXPECT_NE(message({{0.0, 1e-3}, {0.0, 0.0}, 0.0}).find("contact_film_m must be positive"), std::string::npos);
  EXPECT_NE(message({{0.0, 1e-3}, {0.0, 0.0}, 5e-9, -1e-9}).find("contact_margin_m must be finite and not negative"),
            std::string::npos);
  EXPECT_NE(message({{0.0, 1e-3}, {0.0, 0.0}, 5e-9, 1e-9, 0.0}).find("hardness_Pa must be positive"), std::string::npos);
  EXPECT_NE(message({{0.0, 1e-3}, {0.0, 0.0}, 5e-9, 1e-9, NAN}).find("hardness_Pa must be positive"), std::string::npos);
}

// A map adds to the ridges, bilinear between its samples (exact for a plane), zero outside; a map may
// stand without ridges; a map too small, with a spacing that is not positive or a height that is not
// finite is refused.
TEST(EhlRoughness, HeightMapAddsToTheRidgesBilinearlyAndIsChecked) {
  EhlRoughness r{{-1.0, 1.0}, {1e-9, 1e-9}};
  EhlHeightMap m;
  m.x0_m = 0.0, m.y0_m = -1e-4, m.dx_m = 1e-5, m.dy_m = 2e-5;
  m.height_m.resize(3, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 3; ++i) m.height_m(i, j) = 1e-9 * (2.0 * i + 3.0 * j);  // a plane in the indices
  r.map = m;
  EXPECT_NEAR(surface_height_m(r, 1.5e-5, -1e-4 + 3e-5), 1e-9 + 1e-9 * (2.0 * 1.5 + 3.0 * 1.5), 1e-22);
  EXPECT_NEAR(surface_height_m(r, -1e-6, 0.0), 1e-9, 1e-24);  // outside the map: the ridges alone
  EhlRoughness alone;
  alone.map = m;
  EXPECT_EQ(message(alone), "accepted");
  alone.map->height_m.resize(1, 4);
  EXPECT_NE(message(alone).find("at least 2 x 2 samples"), std::string::npos);
  alone.map = m;
  alone.map->dy_m = 0.0;
  EXPECT_NE(message(alone).find("spacings positive"), std::string::npos);
  alone.map = m;
  alone.map->height_m(1, 1) = NAN;
  EXPECT_NE(message(alone).find("not finite"), std::string::npos);
}

// In contact below H_c + the margin, open at or above it.
TEST(EhlRoughness, ContactIsAFilmWithinTheMarginOfTheBoundaryLayers) {
  const EhlRoughness r{{0.0, 1.0}, {0.0, 0.0}, 5e-9, 1e-9};
  EXPECT_TRUE(in_contact(r, 3e-9));
  EXPECT_TRUE(in_contact(r, 5.9e-9));
  EXPECT_FALSE(in_contact(r, 6e-9));
}

// On smooth surfaces the face's ε is the mean of the nodes' c m³; with boundary layers the mean of c
// times the harmonic mean of m³: zero once either film has closed, c m³ where both are equal, and
// between the two nodes' values otherwise. The derivatives match central differences to 1e-7
// relative (a step of 1e-6 of each value: the truncation error is ~1e-12).
TEST(EhlRoughness, FaceFlowClosesWithEitherFilmAndCarriesItsDerivatives) {
  const FaceFlow smooth = face_flow(2.0, 3.0, 5.0, 7.0, false);
  EXPECT_DOUBLE_EQ(smooth.value, 0.5 * (2.0 * 3.0 + 5.0 * 7.0));
  EXPECT_DOUBLE_EQ(face_flow(2.0, 0.0, 5.0, 7.0, true).value, 0.0);
  EXPECT_DOUBLE_EQ(face_flow(2.0, 3.0, 5.0, 0.0, true).value, 0.0);
  EXPECT_DOUBLE_EQ(face_flow(0.0, 0.0, 5.0, 0.0, true).dm3_a, 0.0);
  EXPECT_DOUBLE_EQ(face_flow(2.0, 3.0, 2.0, 3.0, true).value, 6.0);
  const FaceFlow f = face_flow(2.0, 3.0, 5.0, 7.0, true);
  EXPECT_GT(f.value, 2.0 * 3.0);
  EXPECT_LT(f.value, 5.0 * 7.0);
  for (const bool layers : {false, true}) {
    const double v[4] = {2.0, 3.0, 5.0, 7.0};
    const FaceFlow at = face_flow(v[0], v[1], v[2], v[3], layers);
    const double analytic[4] = {at.dc_a, at.dm3_a, at.dc_b, at.dm3_b};
    for (int k = 0; k < 4; ++k) {
      double up[4] = {v[0], v[1], v[2], v[3]}, down[4] = {v[0], v[1], v[2], v[3]};
      const double step = 1e-6 * v[k];
      up[k] += step;
      down[k] -= step;
      const double numeric = (face_flow(up[0], up[1], up[2], up[3], layers).value - face_flow(down[0], down[1], down[2], down[3], layers).value) /
                             (2.0 * step);
      EXPECT_NEAR(analytic[k], numeric, 1e-7 * std::abs(numeric)) << "layers " << layers << ", derivative " << k;
    }
  }
}

}  // namespace
}  // namespace tribo::lubrication
