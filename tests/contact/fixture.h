// What the contact tests share: the effective modulus E* they load their half-spaces with.
#pragma once

namespace tribo::contact::fixture {

// E* = 1e11 Pa, of the order of steel on steel (E* = E / (2 (1 − ν²)) = 115 GPa for E = 210 GPa,
// ν = 0.3); every reference the tests compare with scales with it.
inline constexpr double kEStar = 1e11;

}  // namespace tribo::contact::fixture
