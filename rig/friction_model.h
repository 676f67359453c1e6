// A friction model as data: the baseline law plus named effects with parameter values. The
// catalogue (effect names, parameters, units, bounds, defaults) is the single source of truth
// for the config reader, the documentation and the gap diagnosis' fitter.
//
// Effects (DESIGN §8; equations in docs/friction-effects.md and in each effect's source):
//   rate_dependent_static  μs from the load rate φ̇ via the junction locus, thesis (3.1.22)–(3.1.24)
//   strain_rate_hardening  σ0 = κ φ̇^m modifies that locus, thesis (5.1.2)
//   slip_transient         friction decays with slip distance after slip onset, thesis §5.2a
//   rate_and_state         Dieterich–Ruina a ln(V/V0) + b ln(V0θ/D_c), ageing law: speed steps and
//                          log-time healing of static friction (Dieterich 1979, Ruina 1983)
//   viscous_friction       F += c U, viscous shear of the film, thesis (3.2.1)
//   squeeze_film           a film carries load near U = 0, thesis (3.2.2), Appendix III
//   hydrodynamic_lift      rugosity lift unloads the solid contact as U rises, thesis §5.2a
//   thermal_thinning       viscous traction with η falling as the film heats, (3.2.3)–(3.2.5), (5.2.2)
// and, not a friction effect but catalogued alike (configs list it, the diagnosis fits it):
//   instrument             gain, phase lag, sensor lag, noise of the measured friction, thesis §4.2–4.3
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/junction_locus.h"
#include "rig/effect.h"
#include "rig/friction_law.h"
#include "rig/kinetic_laws.h"

namespace tribo::rig {

struct EffectInfo {
  std::string name;
  std::string summary;
  std::string thesis_reference;
  std::vector<ParameterSpec> parameters;
  // Experiment kinds (gap/bundle.h) whose data the diagnosis tries it on; empty: every kind.
  std::vector<std::string> diagnosed_in = {};
  // Effects of another mechanism that runs at constant driven speed and one normal load cannot tell
  // this one's from, whatever form fits best: there they act through the same channel; a hold or a
  // change of the load parts them (the diagnosis shares its confidence between them, gap/verdict.h).
  std::vector<std::string> alike_at_constant_speed = {};
  // Effects this one acts through and brings to a model that lacks them: strain-rate hardening
  // reshapes the junction locus of rate_dependent_static, so on a model without the locus it is
  // added — and fitted — with the locus's own parameters, not a static friction fixed elsewhere.
  std::vector<std::string> implies = {};
};

// All effects of the catalogue, in a fixed order.
const std::vector<EffectInfo>& effect_catalogue();
// Throws std::invalid_argument listing the known names when `name` is not one.
const EffectInfo& effect_info(const std::string& name);
// The same, or nullptr when `name` is not in the catalogue.
const EffectInfo* find_effect_info(const std::string& name);
// `effects` with those they imply (EffectInfo::implies) that neither they nor `present` hold, each
// just before the effect implying it: what adding `effects` to a model with `present` adds. Names
// not in the catalogue imply nothing.
std::vector<std::string> with_implied_effects(const std::vector<std::string>& effects, const std::vector<std::string>& present);

class HomogenisedBase;  // rig/homogenised_law.h

struct BaselineLaw {
  double mu_s = 0.3;
  double mu_k = 0.2;                                  // used when `kinetic` is null
  std::shared_ptr<const KineticCurve> kinetic;        // optional velocity-dependent μk(U)
  // Optional homogenised base from law.json (rig/homogenised_law.h). When set it replaces μs, μk
  // and `kinetic`: the law integrates [h̄, ΔT] and the effects compose on N_s(h̄) (effect.h).
  // rate_dependent_static and strain_rate_hardening are then rejected: the table has the locus.
  std::shared_ptr<const HomogenisedBase> homogenised;
};

// The catalogue name of the measuring instrument (rig/instrument.h).
inline constexpr const char* kInstrument = "instrument";

struct FrictionModel {
  BaselineLaw baseline;
  // Friction effect name → parameter values in the order of its catalogue entry.
  std::map<std::string, std::vector<double>> effects;
  // The measuring instrument's parameter values (catalogue order), when the model has one. Apart
  // from `effects`: it acts on the reading, never on the law the rig integrates.
  std::optional<std::vector<double>> instrument;

  // By catalogue name, an effect or kInstrument alike.
  bool has(const std::string& name) const;
  // Adds an effect (or the instrument) with its default parameters (no-op if present).
  void add(const std::string& name);
  // Named parameter access, "name.parameter"; throws std::invalid_argument for unknown names.
  double get(const std::string& name, const std::string& parameter) const;
  void set(const std::string& name, const std::string& parameter, double value);

 private:
  const std::vector<double>* values_of(const std::string& name) const;
};

// The traditional model the diagnosis starts from: constant μs and μk, no effects (DESIGN §8).
FrictionModel coulomb(double mu_s, double mu_k);

// Checks names, counts and bounds; throws std::invalid_argument naming effect.parameter.
void validate(const FrictionModel& model);

// The static-friction locus a model's rate_dependent_static / strain_rate_hardening effects imply
// (catalogue defaults for parameters the model leaves out); nullopt when it has neither.
std::optional<contact::JunctionLocus> junction_locus(const FrictionModel& model);

// The law the rig integrates. Immutable and thread-safe: build one per parameter set.
std::shared_ptr<const FrictionLaw> make_friction_law(const FrictionModel& model);

}  // namespace tribo::rig
