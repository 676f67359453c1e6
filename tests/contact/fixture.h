// What the contact tests share: the effective modulus E* they load their half-spaces with, and
// the thesis preset's composite surface (also for the homogenisation and cell tests built on it).
#pragma once

#include <cmath>

#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"

namespace tribo::contact::fixture {

// E* = 1e11 Pa, of the order of steel on steel (E* = E / (2 (1 − ν²)) = 115 GPa for E = 210 GPa,
// ν = 0.3); every reference the tests compare with scales with it.
inline constexpr double kEStar = 1e11;

// examples/thesis-steel.toml's [surface] and [domain]: σ 0.435 µm, self-affine H 0.8 between
// 62.5 and 15.6 µm, 1 mm, 128², seed 1.
inline GaussianSurfaceParams thesis_steel_surface() {
  GaussianSurfaceParams p;
  p.grid = 128;
  p.size_m = 1e-3;
  p.rms_height_m = 4.35e-7;
  p.hurst = 0.8;
  p.rolloff_wavelength_m = 6.25e-5;
  p.cutoff_wavelength_m = 1.5625e-5;
  p.seed = 1;
  return p;
}

// A sphere (R = 10 mm) pressed on a non-periodic n² grid to a Hertz contact radius of 0.25 mm,
// about 32 cells (normal_contact_test.cpp's coarse Hertz case, also the contact spots' reference).
struct CoarseHertz {
  Grid grid;
  double radius_m = 0.01, load_N = 0.0;
  NormalContactResult result;
};
inline CoarseHertz coarse_hertz(Eigen::Index n) {
  const double side = 1e-3 * static_cast<double>(n) / 128.0, a_target = 0.25e-3;
  CoarseHertz h;
  h.grid = Grid::patch(n, n, side, side);
  h.load_N = 4.0 * kEStar * std::pow(a_target, 3) / (3.0 * h.radius_m);
  ElasticHalfSpace hs(h.grid, kEStar, /*periodic=*/false);
  h.result = solve_normal_load(hs, sphere_gap(h.grid, h.radius_m), h.load_N);
  return h;
}

}  // namespace tribo::contact::fixture
