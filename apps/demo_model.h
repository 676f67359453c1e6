// The friction model `tribo demo` runs: the thesis rig, steel on steel, lubricated with white
// mineral oil (DESIGN §5), with the effects that reproduce the thesis' regimes (chapter V):
//   rate_dependent_static  μs(φ̇) through 0.26 at 2.8e-2 in/s, asymptote 0.55   (§5.1)
//   slip_transient         decay with slip distance after breakaway            (§5.2a)
//   squeeze_film           film-borne load near U = 0, multi-cycle slip         (§5.2a)
//   thermal_thinning       traction hump (U_T = 2 in/s) falling into quasi-harmonic oscillation (§5.2b–c)
//   viscous_friction       c = 22 N s/m: film shear that bounds the quasi-harmonic limit cycle (3.2.1)
// over a solid kinetic coefficient μk = 0.12 (restoring force after two slip cycles, §5.2a).
// The values were chosen by sweeping `tribo rig` until the regimes fell at the thesis' speeds:
// multi-cycle slip at high μs, stick-slip with μs = 0.26 at 2.8e-2 in/s, quasi-harmonic at 5.3 in/s.
#pragma once

#include "rig/friction_model.h"

namespace tribo::cli {

rig::FrictionModel thesis_demo_model();

}  // namespace tribo::cli
