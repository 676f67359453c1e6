// NCP functions of the cavitation conditions: φ(a, b) = 0 ⇔ a ≥ 0, b ≥ 0, a b = 0, solved by
// semismooth Newton with an element of φ's B-subdifferential as its derivative. The Reynolds cells
// (reynolds.h) use a = p/p_s, b = 1 − ϑ (JFO); the EHL contacts (ehl_line.h, ehl_point.h) use
// a = P, b = −c R with R the Reynolds residual (Swift–Stieber).
#pragma once

#include <cmath>

namespace tribo::lubrication {

enum class Complementarity { minimum, fischer_burmeister };

struct Ncp {
  double value, da, db;  // φ and its partial derivatives
};

// Fischer–Burmeister φ = a + b − √(a² + b²): smooth away from a = b = 0 (so is the merit ‖F‖²
// of a line search); at the kink the element (1 − 1/√2, 1 − 1/√2).
inline Ncp fischer_burmeister(double a, double b) {
  const double r = std::hypot(a, b);
  if (r == 0.0) return {0.0, 1.0 - M_SQRT1_2, 1.0 - M_SQRT1_2};
  return {a + b - r, 1.0 - a / r, 1.0 - b / r};
}

// Minimum φ = min(a, b): its Newton step is the primal–dual active-set step (Hintermüller, Ito &
// Kunisch, SIAM J. Optim. 13, 2002) — each step splits the nodes into pressurised and cavitated
// and solves the flow balance exactly on that split, so Newton stays quadratic where the split has
// settled; Fischer–Burmeister's smoothing of the corner slows it to linear near a front where a
// and b are both small.
inline Ncp minimum_function(double a, double b) { return a < b ? Ncp{a, 1.0, 0.0} : Ncp{b, 0.0, 1.0}; }

inline Ncp ncp(Complementarity kind, double a, double b) {
  return kind == Complementarity::minimum ? minimum_function(a, b) : fischer_burmeister(a, b);
}

}  // namespace tribo::lubrication
