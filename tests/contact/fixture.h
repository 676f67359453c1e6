// What the contact tests share: the effective modulus E* they load their half-spaces with, and
// the thesis preset's composite surface (also for the homogenisation and cell tests built on it).
#pragma once

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

}  // namespace tribo::contact::fixture
