// The pipeline's candidate stages (pipeline.h): search, refinement, nested candidates and the pair.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "contact/junction_locus.h"
#include "gap/calibration.h"
#include "gap/laplace.h"
#include "gap/pipeline.h"
#include "gap/verdict.h"
#include "numerics/parallel.h"
#include "rig/friction_model.h"

namespace tribo::gap {
namespace {

// slip_transient's rate weakening β: its search starts mid-range (search_start), its thesis form
// holds it at the catalogue's default 0 (search).
const rig::ParameterSpec& rate_weakening() {
  const rig::ParameterSpec& beta = rig::effect_info("slip_transient").parameters[2];
  assert(beta.name == "rate_weakening" && beta.fit);
  return beta;
}

// Its ageing share f, not fitted: 0 is Ruina's slip law (the catalogue's default), 1 Dieterich's
// ageing law with b = β; the search tries both.
const rig::ParameterSpec& ageing_share() {
  const rig::ParameterSpec& f = rig::effect_info("slip_transient").parameters[4];
  assert(f.name == "ageing_share" && !f.fit && f.default_value == 0.0 && f.upper == 1.0);
  return f;
}

// Nested candidates: `general` reduces to `special` in a limit of its other parameters, where
// special.parameter = general's effect.parameter for each carried parameter. Thermal thinning with
// U_T far above the slip speeds is viscous friction with c = c0 (rig/effects/thermal_thinning.h);
// strain-rate hardening at m = 0 is the junction locus it implies (on a model without the locus,
// implied_effects), with that locus's own parameters.
struct Carried {
  const char *effect, *parameter, *special_parameter;
};
struct Nesting {
  const char *general, *special;
  Carried carried[2];
};
constexpr Nesting kNestings[] = {
    {"thermal_thinning", "viscous_friction", {{"thermal_thinning", "traction_coefficient_N_s_per_m", "coefficient_N_s_per_m"}, {}}},
    {"strain_rate_hardening", "rate_dependent_static",
     {{"rate_dependent_static", "mu_s_max", "mu_s_max"}, {"rate_dependent_static", "location_per_s", "location_per_s"}}}};

// A candidate from its fit over `space`: its residuals, gaps and standing.
Candidate candidate_from(const FitProblem& p, const Baseline& b, const std::vector<std::string>& effects,
                         const std::vector<FitParameter>& space, const FitResult& fitted, int comparisons) {
  const Comparison& comparison = *p.comparison;
  Candidate c;
  c.effects = effects;
  c.model = fitted.setup.model;
  c.rig = fitted.setup.rig;
  c.params = values(space, fitted.setup);
  // The law the search chose, stated where it is not the catalogue's default (it is not fitted).
  if (c.model.has("slip_transient") && c.model.get("slip_transient", ageing_share().name) != ageing_share().default_value)
    c.params["slip_transient." + ageing_share().name] = c.model.get("slip_transient", ageing_share().name);
  c.fit = fitted.termination;
  c.extra_parameters = static_cast<int>(
      std::count_if(space.begin(), space.end(), [](const FitParameter& q) { return q.target == FitParameter::Target::effect; }));
  c.residuals = comparison.residuals(comparison.predict(c.rig, c.model, p.options.seed));
  c.train_gap = breakdown(p.items, c.residuals, p.train).gap;
  const GapBreakdown held = breakdown(p.items, c.residuals, p.heldout);
  c.heldout_gap_after = held.gap;
  c.heldout_after_by_observable = held.by_observable;
  c.parameter_variance = parameter_variance_at(p, p.space_of(effects, true), fitted.setup, c.residuals);
  c.heldout_parameter_sd = rms_parameter_sd(c.parameter_variance, p.heldout);
  judge(p, b, comparisons, c);
  return c;
}

// Where a candidate's search starts: the baseline at its calibration with the effects added, placed
// where the data show them. Sets `read_off` when the start was read off the data.
FitSetup search_start(const FitProblem& p, const Baseline& b, const std::vector<std::string>& effects, bool& read_off) {
  FitSetup start = b.setup;
  const double median_v = p.median_v_m_per_s;
  const double phi = start.rig.stiffness_N_per_m * median_v / start.rig.normal_load_N;  // the data's median load rate
  const std::vector<std::string> with_implied = implied_effects(effects, p.model);
  const bool locus_fitted = std::count(with_implied.begin(), with_implied.end(), "rate_dependent_static") > 0;
  for (const auto& e : with_implied) {
    start.model.add(e);
    if ((e == "rate_and_state" || e == "slip_transient") && median_v > 0.0) {
      // Reference speed at the data's median driven speed (not fitted: another V0 only moves
      // the baseline μk, which is fitted), so the increments stay small where the data are.
      start.model.set(e, "reference_speed_m_per_s", std::clamp(median_v, 1e-9, 10.0));
    }
    if (e == "slip_transient") {
      // The rate weakening starts mid-range, not at its default 0 (the thesis form, a bound): the
      // grid holds it at its start, and there its profile fits never see the stable level's slope.
      // From β = 0 the development draw 20002 (Dieterich's ageing law) fitted β to the other bound
      // with μk at a fifth of the truth (train cost 0.0027); from mid-range, to the truth's
      // basin (cost 0.0010, β 0.018 against b − a 0.010).
      const rig::ParameterSpec& beta = rate_weakening();
      start.model.set(e, beta.name, 0.5 * (beta.fit->lower + beta.fit->upper));
      // Dieterich's ageing law with b = β (search: the slip law is searched too).
      start.model.set(e, ageing_share().name, ageing_share().upper);
    }
    if (e == "strain_rate_hardening" && phi > 0.0 && locus_fitted) {
      // Hardening referred to the median load rate, where the locus below starts; any other
      // reference only moves the fitted location. A locus the model gives keeps its own
      // reference: moved, the same m would shift μs at every rate (the first generator's
      // second-effect cases, whose truth hardens from the slowest rate: held-out shrink 38 %
      // against 63 % with the reference left alone, tests/gap/rate_hardening_test.cpp).
      start.model.set(e, "reference_load_rate_per_s", std::clamp(phi, 1e-6, 1e3));
    }
    if (e == "rate_dependent_static") {
      // Start the locus through the calibrated μs at the median load rate of the data.
      contact::JunctionLocus shape;
      const double mu_s_max = std::max(start.model.get("rate_dependent_static", "mu_s_max"), 1.2 * b.setup.model.baseline.mu_s);
      shape.sigma0_over_tau_i = contact::sigma0_over_tau_i_from_upper_asymptote(mu_s_max, shape.alpha);
      if (phi > 0.0 && b.setup.model.baseline.mu_s < mu_s_max) {
        start.model.set("rate_dependent_static", "mu_s_max", mu_s_max);
        start.model.set("rate_dependent_static", "location_per_s",
                        std::clamp(contact::location_through_point_per_s(shape, phi, b.setup.model.baseline.mu_s), 1e-5, 1e5));
      }
    }
  }
  // A velocity step shows the slip transient directly: a peak Δμ above the old level, then a
  // decay over a slip distance to a new steady level. Breakaway at μs = μk + Δμ_peak with the
  // whole excess decaying (a = 1) over the measured 1/e distance, and the stable level's fall per
  // e-fold of speed, β = −Δμ_ss / ln(V2/V1) (0 where it rises: the slip law's β is a weakening),
  // is where that fit starts too. With the mid-range β above in its place, this start's profile
  // cost on the basalt velocity step lost to a grid point that no fit left (held-out 1.52 against
  // 0.066 read off; docs/gap.md).
  const StepResponse& step = p.comparison->step_response();
  read_off = false;
  if (effects == std::vector<std::string>{"slip_transient"} && !start.model.baseline.kinetic && step.decay_distance_m > 0.0) {
    start.model.baseline.mu_s = start.model.baseline.mu_k + step.peak_rise;
    start.model.set("slip_transient", "amplitude", 1.0);
    start.model.set("slip_transient", "decay_distance_m", step.decay_distance_m);
    const rig::ParameterSpec& beta = rate_weakening();
    const double slope = step.stable_fall_per_efold();
    start.model.set("slip_transient", beta.name, std::isfinite(slope) ? std::clamp(slope, 0.0, beta.fit->upper) : 0.0);
    start.model.set("slip_transient", ageing_share().name, ageing_share().default_value);  // steady levels, no stick
    read_off = true;
  }
  // A slide-hold-slide test shows the healing directly: the re-slide peaks grow as
  // b ln(1 + t_h V/D_c) with the hold (calibration.h). The ageing law's fit starts there, with
  // the peaks all the healing's (μs = μk).
  if (effects == std::vector<std::string>{"rate_and_state"}) {
    if (const Healing h = healing_from_data(p.items, p.train); std::isfinite(h.b)) {
      start.model.baseline.mu_s = start.model.baseline.mu_k;
      start.model.set("rate_and_state", "b", std::min(h.b, 0.05));
      start.model.set("rate_and_state", "decay_distance_m", h.decay_distance_m);
      read_off = true;
    }
  }
  return start;
}

}  // namespace

void judge(const FitProblem& p, const Baseline& b, int comparisons, Candidate& c) {
  c.heldout_gap_before = b.heldout.gap;
  const Standing st = standing_of(p.items, c.residuals, c.parameter_variance, p.item_sd, p.train, b.lpd, b.heldout.gap, p.held_m, comparisons);
  c.evidence_nats = st.evidence.gain, c.evidence_se_nats = st.evidence.se;
  c.earns = st.earns;
}

bool ranks_above(const Candidate& a, const Candidate& b) {
  if (a.earns != b.earns) return a.earns;
  return a.evidence_nats > b.evidence_nats;
}

void rank(std::vector<Candidate>& cs) { std::stable_sort(cs.begin(), cs.end(), ranks_above); }

Candidate search(const FitProblem& p, const Baseline& b, const std::vector<std::string>& effects, std::uint64_t seed,
                 int comparisons) {
  bool read_off = false;
  const FitSetup start = search_start(p, b, effects, read_off);
  const std::vector<FitParameter> space = p.space_of(effects, false);
  std::vector<FitResult> forms{fit(*p.comparison, space, start, p.equal_w, p.options, seed, p.options.starts, p.search_base.size(),
                                   Resolution::search, read_off)};
  if (std::count(effects.begin(), effects.end(), "slip_transient") && !read_off) {
    // The slip transient's search starts at mid-range rate weakening (search_start), and the grid
    // holds β there. The thesis form, β = 0 (the catalogue's default), is a basin of its own that
    // a start at mid-range need not reach: development draw 1206 of the first generator (the
    // thesis form, amplitude 0.97, D_c 0.51 mm) searched from mid-range ended at β = 0.032,
    // amplitude 0.23 and μk 34 % above the truth, a train gap of 0.033, and squeeze_film was named
    // at 100 %. So the thesis form is fitted too, β held at 0: one Levenberg–Marquardt fit from
    // the catalogue's defaults, no grid. On 1206 it reaches 0.0037 (amplitude 0.97, D_c 0.50 mm;
    // the truth leaves 0.0033). The better of the two is kept, and a refinement frees β again.
    // With β free from 0 instead, the fit on Dieterich's ageing law (development draw 20002,
    // tests/gap/slip_law_test.cpp) ran to β 0.031 with μk 26 % above the ramp's end and beat the
    // mid-range search on train by a little, with a worse held-out gap (0.0164 against 0.014).
    // Not from a start read off a velocity step, whose steady levels before and after each step
    // show β's slope directly (and whose measured record, the slowest diagnosis, would pay the
    // second fit near its 5-min bar).
    const rig::ParameterSpec& beta = rate_weakening();
    FitSetup thesis_form = start;
    thesis_form.model.set("slip_transient", beta.name, beta.default_value);
    thesis_form.model.set("slip_transient", ageing_share().name, ageing_share().default_value);  // refined, β frees the slip law
    std::vector<FitParameter> without_beta;
    for (const FitParameter& q : space)
      if (!(q.effect == "slip_transient" && q.name == beta.name)) without_beta.push_back(q);
    const FitResult t = fit(*p.comparison, without_beta, thesis_form, p.equal_w, p.options, seed, 1, without_beta.size(), Resolution::search);
    // Both state laws are searched, Dieterich's ageing law with b = β (search_start) and Ruina's
    // slip law (kept against the thesis form by train cost, as before). The ageing law's transient
    // falls linearly, b per D_c, while far above the stable level, and its state heals with time as the slip
    // slows, where the slip law's does not move without slip. On the ageing-law draw 15044
    // (validation set 9532, since development data) the slip law's fit left 1.70 noise floors held
    // out and squeeze_film, which drains at rest and rebuilds over a slip distance, was named at
    // 98 %; the ageing law leaves 0.40. Either law fitted from where the other's search ended
    // stayed in that one's basin (15044 one way, development draw 20016 the other; docs/gap.md).
    // The laws are two forms of one candidate, judged as candidates are (rank): on 20016 the
    // ageing law's search fitted train better (0.019 against the slip law's refined 0.008 to come)
    // with parameters the held-out data could not place (evidence −4 nats), ranked below the
    // refinement's slots, and the slip law's basin was lost.
    FitSetup slip_law = start;
    slip_law.model.set("slip_transient", ageing_share().name, ageing_share().default_value);
    FitResult s = fit(*p.comparison, space, slip_law, p.equal_w, p.options, seed, p.options.starts, p.search_base.size(), Resolution::search);
    const double all_s = forms[0].termination.wall_s + t.termination.wall_s + s.termination.wall_s;  // the candidate's fit time counts all
    if (better_fit(t, s)) s = t;
    // An ageing search that ended at β = 0 is the thesis form: one family with the others.
    if (forms[0].setup.model.get("slip_transient", beta.name) > 0.0)
      forms.push_back(s);
    else if (!better_fit(forms[0], s))
      forms[0] = s;
    for (FitResult& f : forms) f.termination.wall_s = all_s;
  }
  std::vector<Candidate> judged;
  for (const FitResult& f : forms) judged.push_back(candidate_from(p, b, effects, space, f, comparisons));
  rank(judged);
  if (judged.size() > 1) judged.front().other_form = std::make_shared<const Candidate>(judged[1]);
  p.report("fitted " + verdict_name(effects));
  return judged.front();
}

std::vector<Candidate> search_singles(const FitProblem& p, const Baseline& b) {
  const int comparisons = static_cast<int>(p.candidates.size());
  std::vector<Candidate> singles(p.candidates.size());
  numerics::parallel_for(p.candidates.size(),
               [&](std::size_t k) { singles[k] = search(p, b, {p.candidates[k]}, p.options.seed * 7919 + k, comparisons); });
  rank(singles);
  return singles;
}

bool rebase(const FitProblem& p, const Calibration& cal, Baseline& b, std::vector<Candidate>& ranked, int comparisons) {
  const std::optional<FitResult> better = recalibrate(p, cal, b, ranked);
  if (!better) return false;
  b = baseline_at(p, *better);
  for (Candidate& c : ranked) judge(p, b, comparisons, c);
  rank(ranked);
  return true;
}

// The leading candidates are compared at convergence: continue their fits from where the
// search stopped, so that a nested effect (thermal thinning with a large U_T is viscous
// friction) does not win over a simpler one only because its search ran further.
Candidate refine(const FitProblem& p, const Baseline& b, const Candidate& c, int comparisons) {
  DiagnosisOptions refining = p.options;
  refining.max_iterations = std::max(20, p.options.max_iterations);
  const std::vector<FitParameter> space = p.space_of(c.effects, true);
  const FitResult r = fit(*p.comparison, space, FitSetup{c.rig, c.model}, p.equal_w, refining, p.options.seed, 1, space.size(),
                          Resolution::refine);
  Candidate refined = candidate_from(p, b, c.effects, space, r, comparisons);
  refined.fit.wall_s += c.fit.wall_s;  // the search's time too
  p.report("refined " + verdict_name(c.effects));
  return refined;
}

bool explains(const Candidate& c) { return c.evidence_nats > 0.0 || c.heldout_gap_after < c.heldout_gap_before; }

std::vector<Candidate> refine_leaders(const FitProblem& p, const Baseline& b, std::vector<Candidate> ranked, int comparisons) {
  // Four: the hardened locus (three parameters on a Coulomb model) fits static friction well enough
  // to rank third on data with a dynamic effect, and with three slots it pushed out the effect
  // itself (independent lift seed 306: the lift's search stops at its grid start, U½ = 0.63 mm/s,
  // where the cost is flat; refined, it moves to 1.4 mm/s and closes the gap). Five: a search holds
  // the rig where the calibration put it, and the calibration moves the rig to absorb what the
  // baseline lacks. Independent Eyring viscous force, development seed 404: the calibrated
  // stiffness 10 477 N/m (truth 10 130); held there, the viscous search ends at a train gap of
  // 0.0205 and ranks fifth (6.8 nats); refined with the rig free it moves the stiffness to
  // 10 068 N/m and leaves 0.0098 (25.5 nats, named at 99.5 %). Four slots had served until the
  // rig's one-step integration (35e7cf0) moved that calibration and pushed the viscous force from
  // fourth to fifth. On two threads the fifth refinement runs in a round of its own (development
  // medians 61 s rig, 75 s independent, against 65 and 70 s with four, on differently loaded cores).
  // Of those, only a search that explains something is refined: one that neither gains held-out
  // evidence nor cuts the held-out gap has nothing a refinement would judge at convergence, and
  // its refinement can be the diagnosis' slowest part (validation seed 9432, Kato ageing 14942:
  // the slip transient's refinement took 110 s, its rate state relaxing in ~10 µs while slipping,
  // and ended at -0.3 nats). Both development sets: the 48 verdicts and confidences the same to
  // the digit, wall time -3 % (rig) and -4 % (independent); 14942 the same verdict (docs/gap.md).
  // A leader's other form (the slip transient's other state law) is refined beside it, on the
  // same terms (it explains something against the baseline as it now stands), and the better of
  // the two kept: the search ranks the forms where neither has converged, and the one it puts
  // second may be the one that converges to the data (validation case 15094, Dieterich's ageing
  // law: the slip law's search ranked first and, refined, left 0.0208 held out, and squeeze_film
  // was named at 76 %; the ageing law's search, refined, leaves 0.0071; docs/gap.md). With five
  // leaders refined on two threads, a sixth refinement runs beside the fifth.
  struct Task {
    std::size_t leader;
    const Candidate* form;  // ranked[leader] or its other form, re-judged
    bool other;
  };
  std::vector<Candidate> others(std::min(kRefinedLeaders, ranked.size()));
  std::vector<Task> tasks;
  for (std::size_t k = 0; k < others.size(); ++k) {
    if (explains(ranked[k])) tasks.push_back({k, &ranked[k], false});
    if (!ranked[k].other_form) continue;
    others[k] = *ranked[k].other_form;
    judge(p, b, comparisons, others[k]);  // against the baseline rebase() may have moved
    if (explains(others[k])) tasks.push_back({k, &others[k], true});
  }
  std::vector<Candidate> refined(tasks.size());
  numerics::parallel_for(tasks.size(), [&](std::size_t i) { refined[i] = refine(p, b, *tasks[i].form, comparisons); });
  // In task order: a leader's own refinement comes before its other form's.
  for (std::size_t i = 0; i < tasks.size(); ++i)
    if (!tasks[i].other || ranks_above(refined[i], ranked[tasks[i].leader])) ranked[tasks[i].leader] = std::move(refined[i]);
  return ranked;
}

// Nested candidates (kNestings): when the general fit does better on train, the special one is
// refined again from the general fit's projection and kept if it then fits train better, so that
// it is judged at its own best rather than lose to its generalisation on search luck (selftest
// seed 3: the viscous search stopped at c = 33.7 N s/m, held-out gap 0.0045, while thermal
// thinning settled at U_T = 10 m/s, c0 = 34.6 N s/m, held-out gap 0.0015; independent seed 301,
// Kato ageing: the locus search stopped at a held-out gap of 0.0112 and the hardened locus, one
// parameter more, was named at 47 %; refined from its m = 0 projection the locus is named, 56 %).
std::vector<Candidate> nest(const FitProblem& p, const Baseline& b, std::vector<Candidate> singles, int comparisons) {
  const auto single = [&](const std::string& e) {
    return std::find_if(singles.begin(), singles.end(), [&](const Candidate& c) { return c.effects == std::vector<std::string>{e}; });
  };
  for (const Nesting& nesting : kNestings) {
    const auto general = single(nesting.general), special = single(nesting.special);
    if (general == singles.end() || special == singles.end() || !(general->train_gap < special->train_gap)) continue;
    Candidate from = *special;
    from.rig = general->rig;
    from.model.baseline = general->model.baseline;
    const std::vector<FitParameter> special_space = effect_parameters(nesting.special);
    for (const Carried& carried : nesting.carried) {
      if (!carried.effect) continue;
      // Into the special effect's fit range: the general one's parameter may lie beyond it (thermal
      // thinning's traction coefficient of 2.5e4 N s/m on the slide-hold-slide case, where viscous
      // friction's range ends at 1e4 N s/m, and the projection would not be a model at all).
      double value = general->model.get(carried.effect, carried.parameter);
      for (const FitParameter& q : special_space)
        if (q.name == carried.special_parameter) value = std::clamp(value, q.lower, q.upper);
      from.model.set(nesting.special, carried.special_parameter, value);
    }
    if (Candidate projected = refine(p, b, from, comparisons); projected.train_gap < special->train_gap) *special = projected;
  }
  rank(singles);
  return singles;
}

Candidate without_partner(const Candidate& member, const Candidate& pr) {
  Candidate from = member;
  from.rig = pr.rig;
  from.model.baseline = pr.model.baseline;
  for (auto& [name, values] : from.model.effects)
    if (const auto it = pr.model.effects.find(name); it != pr.model.effects.end()) values = it->second;
  if (pr.model.instrument) {
    if (from.model.instrument) {
      from.model.instrument = pr.model.instrument;
    } else {
      const double gain = pr.model.get(rig::kInstrument, "gain");
      from.model.baseline.mu_s *= gain, from.model.baseline.mu_k *= gain;
    }
  }
  return from;
}

std::vector<Candidate> reduce_pair(const FitProblem& p, const Baseline& b, std::vector<Candidate> singles, const Candidate& pr,
                                   int comparisons) {
  std::vector<std::size_t> members;
  for (std::size_t k = 0; k < singles.size(); ++k)
    if (singles[k].effects.size() == 1 && std::count(pr.effects.begin(), pr.effects.end(), singles[k].effects[0]) > 0 &&
        pr.train_gap < singles[k].train_gap)
      members.push_back(k);
  std::vector<Candidate> projected(members.size());
  numerics::parallel_for(members.size(), [&](std::size_t m) {
    projected[m] = refine(p, b, without_partner(singles[members[m]], pr), comparisons);
  });
  // refine() counts in the start's time, which without_partner copied from the single.
  for (std::size_t m = 0; m < members.size(); ++m)
    if (Candidate& single = singles[members[m]]; projected[m].train_gap < single.train_gap) single = std::move(projected[m]);
  rank(singles);
  return singles;
}

Paired pair(const FitProblem& p, const Baseline& b, std::vector<Candidate> singles, int comparisons, double noise_floor) {
  Paired out{std::move(singles), comparisons};
  if (out.candidates.size() < 2) return out;
  const Candidate& best = out.candidates.front();
  const double closed = best.heldout_gap_before > 0.0 ? 1.0 - best.heldout_gap_after / best.heldout_gap_before : 1.0;
  if (!(closed < p.options.pair_threshold && b.heldout.gap > 0.0)) return out;
  // Without a noise estimate (floor 0) every gap passes, so the pair is tried as it was before the gate.
  if (!beyond_noise(best.heldout_gap_after, noise_floor, p.options)) return out;
  // Nor unless each of the two explains something alone (explains()): a pair stands for two effects
  // at once, and each present effect, fitted alone, explains its part. In the 57 validation sets
  // kept (docs/gap-validation-seed*) 15 pairs had a member that explained nothing, and none was
  // named; 3 of the 45 others were. On 14942 (seed 9432) such a pair took 44 s of 120 s.
  if (!explains(best) || !explains(out.candidates[1])) return out;
  // Against the singles it must have decisive evidence over the simpler one (verdict_index()).
  out.comparisons = static_cast<int>(out.candidates.size()) + 1;
  for (Candidate& c : out.candidates) judge(p, b, out.comparisons, c);
  const std::vector<std::string> both{out.candidates[0].effects[0], out.candidates[1].effects[0]};
  Candidate paired = refine(p, b, search(p, b, both, p.options.seed * 7919 + 104729, out.comparisons), out.comparisons);
  out.candidates = reduce_pair(p, b, std::move(out.candidates), paired, out.comparisons);
  out.candidates.push_back(std::move(paired));
  rank(out.candidates);
  return out;
}

}  // namespace tribo::gap
