#include "gap/diagnosis.h"

#include <ceres/ceres.h>
#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <mutex>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>

#include "contact/junction_locus.h"
#include "gap/calibration.h"
#include "gap/parallel.h"
#include "gap/refit.h"
#include "gap/report.h"
#include "gap/verdict.h"
#include "numerics/format.h"

namespace tribo::gap {
namespace {

// One fitted quantity, mapped to u ∈ [1, 2] for the optimiser (so a relative numeric-difference
// step is about 1 % of the range for every parameter); log-spaced when the range spans decades.
struct FitParameter {
  enum class Target { mu_s, mu_k_ratio, rig, effect } target;
  std::string effect, name;
  double lower = 0.0, upper = 1.0;
  bool log = false;
  int effect_index = 0;
  bool stated_constant = false;  // a rig constant the bundle gives with an uncertainty, refined within it

  double value(double u) const {
    const double w = std::clamp(u - 1.0, 0.0, 1.0);
    return log ? lower * std::pow(upper / lower, w) : lower + w * (upper - lower);
  }
  // Search starts lie below the upper bound, so that a forward difference (a step up) never
  // lands beyond it and sees no slope; at the lower bound the step goes into the box, and a
  // parameter whose default is that bound starts there — slip_transient's rate weakening at 0, the
  // thesis form (started at 2 % of its range, 0.001, the search on a stiff velocity-step machine
  // fell into a stick-slipping basin: tests/gap/velocity_step_test.cpp). Except rig keys, placed
  // where the calibration put them, bounds included: moved inside, a rig at its damping bound
  // would start a candidate fit from a different machine (one that stick-slips after a velocity
  // step where the calibrated one slides). A refinement
  // (`inside` false) continues a fit where it stopped, on a bound too: moved 2 % inside, it
  // started from a worse point than the search had found and could stop there — independent
  // selftest seed 403 (Dieterich–Ruina slip law), slip_transient's amplitude searched to its
  // physical bound 1 (the whole excess μs − μk present at onset), refined from 0.98 and stopped
  // after 0 iterations at a train gap of 0.0168; the same fit at amplitude 1 has 0.0134.
  double coordinate(double v, bool inside = true) const {
    v = std::clamp(v, lower, upper);
    const double w = log ? std::log(v / lower) / std::log(upper / lower) : (v - lower) / (upper - lower);
    return 1.0 + (target == Target::rig || !inside ? w : std::clamp(w, 0.0, 0.98));
  }
  std::string label() const {
    switch (target) {
      case Target::mu_s: return "baseline.mu_s";
      case Target::mu_k_ratio: return "baseline.mu_k";
      case Target::rig: return "rig." + name;
      case Target::effect: break;
    }
    return effect + "." + name;
  }
};

// The parameters of an effect the data can identify, with the ranges the catalogue gives them
// (ParameterSpec::fit); the others keep their values.
std::vector<FitParameter> effect_parameters(const std::string& effect) {
  std::vector<FitParameter> out;
  for (const rig::ParameterSpec& spec : rig::effect_info(effect).parameters) {
    if (!spec.fit) continue;
    FitParameter p;
    p.target = FitParameter::Target::effect;
    p.effect = effect;
    p.name = spec.name;
    p.lower = spec.fit->lower, p.upper = spec.fit->upper, p.log = spec.fit->log;
    out.push_back(p);
  }
  if (out.empty()) throw std::invalid_argument("gap: the catalogue gives effect '" + effect + "' no fitted parameter");
  return out;
}

// The effects a candidate's fit moves. strain_rate_hardening reshapes the junction locus that
// rate_dependent_static gives (catalogue: "implies the locus"); on a model without that locus it
// brings the locus's own fitted parameters, not the thesis defaults, so that it is judged as the
// locus with hardening — which reduces to rate_dependent_static at m = 0 — rather than as a
// hardening index on a static friction fixed elsewhere (independent Johnson–Cook seeds 302, 402
// fitted m alone to a held-out gap of 0.25–0.49, worse than no effect).
std::vector<std::string> implied_effects(const std::vector<std::string>& effects, const rig::FrictionModel& model) {
  std::vector<std::string> out;
  const bool locus = model.has("rate_dependent_static") || std::count(effects.begin(), effects.end(), "rate_dependent_static");
  for (const auto& e : effects) {
    if (e == "strain_rate_hardening" && !locus) out.push_back("rate_dependent_static");
    out.push_back(e);
  }
  return out;
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

struct Setup {
  rig::RigParameters rig;
  rig::FrictionModel model;
};

// Damping ratio ζ = r / (2 √(k M)): the rig's damping when stiffness and mass are fitted too, so
// that the bounds stay inside the under-damped range the rig accepts whatever k becomes.
double damping_ratio(const rig::RigParameters& rig) {
  return rig.damping_N_s_per_m / (2.0 * std::sqrt(rig.stiffness_N_per_m * rig.mass_kg));
}
void set_damping_ratio(rig::RigParameters& rig, double zeta) {
  rig.damping_N_s_per_m = zeta * 2.0 * std::sqrt(rig.stiffness_N_per_m * rig.mass_kg);
}

void apply(const std::vector<FitParameter>& space, const std::vector<double>& u, Setup& s) {
  double ratio = s.model.baseline.mu_s > 0.0 ? s.model.baseline.mu_k / s.model.baseline.mu_s : 1.0;
  double zeta = damping_ratio(s.rig);
  bool fit_zeta = false;
  for (std::size_t i = 0; i < space.size(); ++i) {
    const FitParameter& p = space[i];
    const double v = p.value(u[i]);
    switch (p.target) {
      case FitParameter::Target::mu_s: s.model.baseline.mu_s = v; break;
      case FitParameter::Target::mu_k_ratio: ratio = v; break;
      case FitParameter::Target::rig:
        if (p.name == "stiffness_N_per_m") s.rig.stiffness_N_per_m = v;
        if (p.name == "damping_N_s_per_m") s.rig.damping_N_s_per_m = v;
        if (p.name == "mass_kg") s.rig.mass_kg = v;
        if (p.name == "damping_ratio") zeta = v, fit_zeta = true;
        break;
      case FitParameter::Target::effect: s.model.set(p.effect, p.name, v); break;
    }
  }
  if (fit_zeta) set_damping_ratio(s.rig, zeta);  // after k and M, whatever their order in the space
  if (!s.model.baseline.kinetic) s.model.baseline.mu_k = std::min(ratio, 1.0) * s.model.baseline.mu_s;
}

double rig_value(const rig::RigParameters& rig, const std::string& key) {
  if (key == "stiffness_N_per_m") return rig.stiffness_N_per_m;
  if (key == "damping_N_s_per_m") return rig.damping_N_s_per_m;
  if (key == "damping_ratio") return damping_ratio(rig);
  return rig.mass_kg;
}

// The value a parameter has in a setup (μk itself for the fitted ratio μk/μs, as reported).
double current(const FitParameter& p, const Setup& s) {
  switch (p.target) {
    case FitParameter::Target::mu_s: return s.model.baseline.mu_s;
    case FitParameter::Target::mu_k_ratio: return s.model.baseline.mu_k;
    case FitParameter::Target::rig: return rig_value(s.rig, p.name);
    case FitParameter::Target::effect: break;
  }
  rig::FrictionModel m = s.model;
  m.add(p.effect);
  return m.get(p.effect, p.name);
}

std::vector<double> coordinates(const std::vector<FitParameter>& space, const Setup& s, bool inside) {
  std::vector<double> u;
  for (const FitParameter& p : space) {
    const double v = current(p, s);
    const bool ratio = p.target == FitParameter::Target::mu_k_ratio;
    u.push_back(p.coordinate(ratio ? (s.model.baseline.mu_s > 0.0 ? v / s.model.baseline.mu_s : 1.0) : v, inside));
  }
  return u;
}

struct Cost {
  const Comparison* comparison;
  const std::vector<FitParameter>* space;
  const Setup* start;
  std::vector<int> train;
  std::vector<double> w;
  std::uint64_t seed;
  std::vector<bool> needed;

  std::vector<double> fixed_tail;  // trailing coordinates held fixed (profile fits)

  bool operator()(double const* const* parameters, double* residuals) const {
    Setup s = *start;
    std::vector<double> u(parameters[0], parameters[0] + space->size() - fixed_tail.size());
    u.insert(u.end(), fixed_tail.begin(), fixed_tail.end());
    apply(*space, u, s);
    std::vector<double> r;
    try {
      r = comparison->residuals(comparison->predict(s.rig, s.model, seed, nullptr, &needed));
    } catch (const std::invalid_argument&) {
      r.assign(comparison->items().size(), 1.0);
    }
    for (std::size_t k = 0; k < train.size(); ++k) residuals[k] = w[static_cast<std::size_t>(train[k])] * r[static_cast<std::size_t>(train[k])];
    return true;
  }
};

struct FitResult {
  Setup setup;
  double cost = 0.0;
  FitTermination termination;  // of the start that won
};

// How finely the least-squares steps resolve the cost. Searching: forward differences with a step
// of 1 % of the coordinate, coarse enough to see through the small jumps of event-based
// observables. Refining: central differences with a 0.2 % step and a tighter stop, to place a
// fit from the right basin at its minimum (a biased gradient leaves it short by a fraction of the
// step, which on data at the noise level decides between nested candidates).
enum class Resolution { search, refine };
constexpr double kSearchStep = 0.01;  // the search's difference step in the coordinates u ∈ [1, 2]
// Levenberg–Marquardt iterations of the baseline's profile fit at each grid point (it starts from
// the previous point's fit: continuation). These fits are three quarters of a diagnosis' time (the
// foreign control: 191 of 250 CPU-s in the candidates), but fewer place the searches elsewhere:
// with two, the slip-law fit stopped at amplitude 0.979 short of its reset bound
// (tests/gap/slip_law_test.cpp) and the velocity step's baseline settled where its misses moved
// from the transient to the steady scatter; a 4 × 4 grid named the quick set's lift thermal thinning.
constexpr int kProfileIterations = 3;

// Least squares over the items of positive weight w_i (the training items), residual w_i r_i.
FitResult fit(const Comparison& c, const std::vector<FitParameter>& space, const Setup& start, const std::vector<double>& w,
              const DiagnosisOptions& o, std::uint64_t seed, int starts, std::size_t randomised_from,
              Resolution resolution = Resolution::search, bool start_read_off_data = false) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<int> train;
  std::vector<bool> train_mask(w.size());
  for (std::size_t i = 0; i < w.size(); ++i)
    if ((train_mask[i] = w[i] > 0.0)) train.push_back(static_cast<int>(i));
  if (space.empty()) {  // nothing to fit: the start as it is, its cost as Ceres would count it
    FitResult as_is{start, 0.0, {"nothing to fit", 0, 0, 0.0}};
    const Cost cost{&c, &space, &start, train, w, o.seed, train_mask, {}};
    std::vector<double> r(train.size());
    const double* none = nullptr;
    cost(&none, r.data());
    for (double x : r) as_is.cost += 0.5 * x * x;
    return as_is;
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(1.0, 2.0);
  FitResult best{start, std::numeric_limits<double>::infinity(), {}};
  // Solves for the leading coordinates with the trailing `tail` fixed; returns the final cost.
  auto solve = [&](std::vector<double>& u, const std::vector<double>& tail, int iterations) {
    const bool refine = resolution == Resolution::refine;
    ceres::NumericDiffOptions nd;
    nd.relative_step_size = refine ? 0.002 : kSearchStep;
    Cost* functor = new Cost{&c, &space, &start, train, w, o.seed, train_mask, tail};
    ceres::DynamicCostFunction* cost =
        refine ? static_cast<ceres::DynamicCostFunction*>(
                     new ceres::DynamicNumericDiffCostFunction<Cost, ceres::CENTRAL>(functor, ceres::TAKE_OWNERSHIP, nd))
               : new ceres::DynamicNumericDiffCostFunction<Cost, ceres::FORWARD>(functor, ceres::TAKE_OWNERSHIP, nd);
    cost->AddParameterBlock(static_cast<int>(u.size()));
    cost->SetNumResiduals(static_cast<int>(train.size()));
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, u.data());
    for (int i = 0; i < static_cast<int>(u.size()); ++i) {
      problem.SetParameterLowerBound(u.data(), i, 1.0);
      problem.SetParameterUpperBound(u.data(), i, 2.0);
    }
    ceres::Solver::Options so;
    so.max_num_iterations = iterations;
    so.linear_solver_type = ceres::DENSE_QR;
    so.logging_type = ceres::SILENT;
    so.num_threads = 1;
    so.function_tolerance = refine ? 1e-6 : 1e-4;  // |Δcost|/cost
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    return std::make_pair(summary.final_cost,
                          FitTermination{ceres::TerminationTypeToString(summary.termination_type),
                                         std::max(0, static_cast<int>(summary.iterations.size()) - 1), iterations});
  };
  // Starts: the best points of a coarse grid over the effect's coordinates (up to two), each with
  // the baseline parameters re-fitted (a short profile fit): the baseline co-adapts with the
  // effect, and friction observables are only piecewise smooth, so a local method needs a basin.
  // The grid is coarse against a narrow valley, so the next-best points start fits too.
  // An effect with more coordinates keeps the others at `start` on the grid (the catalogue lists
  // the two that shape it most first). Without a grid (no effect coordinates) the first start is
  // `start` and the others are random points in the bounds. With `start_read_off_data`, `start`
  // joins the grid.
  std::vector<std::pair<double, std::vector<double>>> grid;
  const std::vector<double> initial = coordinates(space, start, resolution == Resolution::search);
  const std::size_t dims = space.size() - randomised_from, grid_dims = std::min<std::size_t>(dims, 2);
  if (grid_dims >= 1 && randomised_from > 0) {
    const std::vector<double> levels = grid_dims == 1 ? std::vector<double>{1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9}
                                                      : std::vector<double>{1.1, 1.3, 1.5, 1.7, 1.9};
    std::vector<std::size_t> idx(grid_dims, 0);
    // Along the first coordinate the baseline starts from the previous point's fit (continuation):
    // an effect that takes away much of the friction needs the baseline far from its calibration.
    const std::vector<double> lead0(initial.begin(), initial.begin() + static_cast<long>(randomised_from));
    std::vector<double> previous = lead0;
    while (true) {
      std::vector<double> tail(initial.begin() + static_cast<long>(randomised_from), initial.end()), lead = idx[0] == 0 ? lead0 : previous;
      for (std::size_t d = 0; d < grid_dims; ++d) tail[d] = levels[idx[d]];
      const double cu = solve(lead, tail, kProfileIterations).first;
      previous = lead;
      lead.insert(lead.end(), tail.begin(), tail.end());
      grid.emplace_back(cu, lead);
      std::size_t d = 0;
      while (d < grid_dims && ++idx[d] == levels.size()) idx[d++] = 0;
      if (d == grid_dims) break;
    }
    // A start read off the data competes with the grid points on the same terms.
    if (start_read_off_data) {
      std::vector<double> lead = lead0, tail(initial.begin() + static_cast<long>(randomised_from), initial.end());
      const double cu = solve(lead, tail, kProfileIterations).first;
      lead.insert(lead.end(), tail.begin(), tail.end());
      grid.emplace_back(cu, lead);
    }
    std::stable_sort(grid.begin(), grid.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }
  for (int k = 0; k < starts; ++k) {
    std::vector<double> u = initial;
    if (static_cast<std::size_t>(k) < grid.size()) {
      u = grid[static_cast<std::size_t>(k)].second;
    } else if (k > 0) {
      for (std::size_t i = randomised_from; i < u.size(); ++i) u[i] = uniform(rng);
    }
    const auto [final_cost, termination] = solve(u, {}, o.max_iterations);
    if (final_cost < best.cost) {
      best.cost = final_cost;
      best.termination = termination;
      best.setup = start;
      apply(space, u, best.setup);
    }
  }
  best.termination.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return best;
}

// Whether the options calibrate a rig key over its wide range (the damping counts as calibrated
// when its ratio ζ is).
bool calibrates(const DiagnosisOptions& o, const std::string& key) {
  const auto named = [&](const std::string& k) { return std::count(o.calibrate_rig.begin(), o.calibrate_rig.end(), k) > 0; };
  return named(key) || (key == "damping_N_s_per_m" && named("damping_ratio"));
}

// The baseline's parameters: μs, μk/μs, the rig keys nobody gives (calibrate_rig, wide ranges) and
// the rig constants the bundle gives with a stated relative uncertainty u, refined within ± u of
// the stated value (a rig known to a few per cent must not make a mechanism out of its
// own constants' error) — unless the options calibrate that key anyway.
std::vector<FitParameter> baseline_space(const rig::FrictionModel& model, const rig::RigParameters& rig, const DiagnosisOptions& o,
                                         const std::map<std::string, double>& relative_uncertainty) {
  std::vector<FitParameter> space;
  FitParameter p;
  // A homogenised base (law.json) computes its friction from the surfaces: it has no μs, μk to fit.
  if (!model.baseline.homogenised) {
    p.target = FitParameter::Target::mu_s;
    p.lower = 0.01, p.upper = 1.5;
    space.push_back(p);
  }
  if (!model.baseline.homogenised && !model.baseline.kinetic) {
    p.target = FitParameter::Target::mu_k_ratio;
    p.lower = 0.05, p.upper = 1.0;
    space.push_back(p);
  }
  for (const std::string& key : o.calibrate_rig) {
    const double v = rig_value(rig, key);
    p.target = FitParameter::Target::rig;
    p.name = key;
    p.lower = v / 100.0, p.upper = v * 100.0, p.log = true;
    // ζ from nearly undamped (the thesis rig: 8.5e-3) to just under critical (the rig's limit).
    if (key == "damping_ratio") p.lower = 1e-3, p.upper = 0.9;
    space.push_back(p);
  }
  for (const auto& [key, u] : relative_uncertainty) {
    if (calibrates(o, key)) continue;
    const double v = rig_value(rig, key);
    if (!(v > 0.0 && u > 0.0 && u < 1.0)) throw std::invalid_argument("gap: rig key '" + key + "' cannot be refined around " + numerics::shortest(v));
    p.target = FitParameter::Target::rig;
    p.name = key;
    p.lower = v * (1.0 - u), p.upper = v * (1.0 + u), p.log = false;
    p.stated_constant = true;
    space.push_back(p);
  }
  return space;
}

std::map<std::string, double> values(const std::vector<FitParameter>& space, const Setup& s) {
  std::map<std::string, double> out;
  for (const FitParameter& p : space) out[p.label()] = current(p, s);
  return out;
}

// A fit the bootstrap refits (diagnosis.h step 4): its search coordinates (the rig held where
// the fit put it), where it stopped, and the residuals it left.
struct Fitted {
  std::vector<FitParameter> space;
  Setup setup;
  const std::vector<double>* residuals;
  std::vector<double> weights;  // its refits' least-squares weights, positive on the training items
};

// Each fit refitted to `samples` redraws of the training items within their noise (measured
// value + noise_r_i z_i), linearised about where it stopped (gap/refit.h) with the Jacobian the
// search's own difference step gives — forward, backward at the upper bound. Returns, per redraw,
// the residuals of every fit on every item. The redraws are a stream of their own (the held-out
// redraws are the bootstrap's), drawn for every item so that a redraw does not depend on the split.
std::vector<std::vector<std::vector<double>>> refitted_residuals(const Comparison& c, const std::vector<Fitted>& fits,
                                                                 const std::vector<bool>& train, const std::vector<double>& noise_r,
                                                                 int samples, std::uint64_t seed) {
  const std::size_t n = train.size();
  // Each fit's coordinates where it stopped, and the task that simulates it there.
  std::vector<std::vector<double>> at_fit;
  std::vector<std::size_t> centre_task;
  std::vector<std::pair<std::size_t, std::size_t>> tasks;  // (fit, coordinate); coordinate = size: at the fit itself
  for (std::size_t f = 0; f < fits.size(); ++f) {
    at_fit.push_back(coordinates(fits[f].space, fits[f].setup, false));
    for (std::size_t j = 0; j <= fits[f].space.size(); ++j) tasks.emplace_back(f, j);
    centre_task.push_back(tasks.size() - 1);
  }
  // Simulates fit f at coordinates u: its residuals on every item, empty where it cannot be simulated.
  const auto residuals_at = [&](std::size_t f, const std::vector<double>& u) {
    Setup s = fits[f].setup;
    apply(fits[f].space, u, s);
    try {
      return c.residuals(c.predict(s.rig, s.model, seed));
    } catch (const std::invalid_argument&) {
      return std::vector<double>{};
    }
  };
  std::vector<std::vector<double>> at(tasks.size());
  std::vector<double> step(tasks.size(), 0.0);
  parallel_for(tasks.size(), [&](std::size_t t) {
    const auto [f, j] = tasks[t];
    std::vector<double> u = at_fit[f];
    if (j < u.size()) step[t] = u[j] + kSearchStep <= 2.0 ? kSearchStep : -kSearchStep, u[j] += step[t];
    at[t] = residuals_at(f, u);  // empty: that column stays 0
  });
  // Each fit linearised; each direction whose redraw steps reach past the difference step is
  // probed two standard deviations of its step away (clipped to the box), and kept when the
  // training residuals change there as J predicts, within half (refit.h).
  struct Probe {
    std::size_t fit;
    Eigen::Index direction;
    Eigen::VectorXd du;
  };
  std::vector<Probe> probes;
  std::vector<LinearisedRefit> linear;
  for (std::size_t f = 0; f < fits.size(); ++f) {
    const std::size_t p = fits[f].space.size(), first = centre_task[f] - p;
    const std::vector<double>& centre = at[centre_task[f]];
    const std::vector<double>& u = at_fit[f];
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(p));
    for (std::size_t j = 0; j < p; ++j)
      if (!at[first + j].empty() && !centre.empty())
        for (std::size_t i = 0; i < n; ++i)
          J(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (at[first + j][i] - centre[i]) / step[first + j];
    std::vector<double> below, above;
    for (double x : u) below.push_back(x - 1.0), above.push_back(2.0 - x);
    linear.emplace_back(std::move(J), *fits[f].residuals, fits[f].weights, below, above);
    const Eigen::VectorXd sd = linear[f].step_std(noise_r);
    for (Eigen::Index k = 0; k < sd.size(); ++k) {
      // Within the difference step J is the secant the fit itself follows; probing shorter steps
      // would read the simulation's own roughness (event timing, the integration tolerance).
      if (!(2.0 * sd(k) > kSearchStep)) continue;
      Eigen::VectorXd du = 2.0 * sd(k) * linear[f].directions().col(k);
      for (Eigen::Index j = 0; j < du.size(); ++j) du(j) = std::clamp(u[static_cast<std::size_t>(j)] + du(j), 1.0, 2.0) - u[static_cast<std::size_t>(j)];
      probes.push_back({f, k, du});
    }
  }
  std::vector<char> linear_enough(probes.size(), 0);  // 0 also where the fit or the probe cannot be simulated
  parallel_for(probes.size(), [&](std::size_t q) {
    const Probe& pr = probes[q];
    const std::vector<double>& centre = at[centre_task[pr.fit]];
    std::vector<double> u = at_fit[pr.fit];
    for (std::size_t j = 0; j < u.size(); ++j) u[j] += pr.du(static_cast<Eigen::Index>(j));
    const std::vector<double> r = centre.empty() ? std::vector<double>{} : residuals_at(pr.fit, u);
    if (r.empty()) return;
    const Eigen::VectorXd predicted = linear[pr.fit].predicted_change(pr.du);
    Eigen::VectorXd miss(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) miss(static_cast<Eigen::Index>(i)) = r[i] - centre[i] - predicted(static_cast<Eigen::Index>(i));
    linear_enough[q] = linear[pr.fit].train_norm(miss) <= 0.5 * linear[pr.fit].train_norm(predicted);
  });
  for (std::size_t q = 0; q < probes.size(); ++q)
    if (!linear_enough[q]) linear[probes[q].fit].drop(probes[q].direction);
  std::mt19937_64 rng(seed ^ 0x5851f42d4c957f2dULL);
  std::normal_distribution<double> z;
  std::vector<double> shift(n, 0.0);
  std::vector<std::vector<std::vector<double>>> out(static_cast<std::size_t>(samples));
  for (auto& sample : out) {
    for (std::size_t i = 0; i < n; ++i) {
      const double zi = z(rng);
      shift[i] = train[i] ? noise_r[i] * zi : 0.0;
    }
    for (const LinearisedRefit& l : linear) sample.push_back(l.residuals(shift));
  }
  return out;
}

// Lets the predictions' parallel runs (Comparison::predict) inside the candidates' parallel fits
// have threads of their own while the diagnosis runs: when one fit is left running alone — the
// longest refinement, the pair — its runs use both cores instead of one (independent seed 307:
// 126 → 109 s on 2 cores, the same CPU time and result). Restores the caller's setting.
class NestedParallelism {
 public:
  NestedParallelism() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(std::max(levels_, 2)); }
  ~NestedParallelism() { omp_set_max_active_levels(levels_); }
  NestedParallelism(const NestedParallelism&) = delete;
  NestedParallelism& operator=(const NestedParallelism&) = delete;

 private:
  int levels_;
};

// Why the model cannot take the effect (rig::validate's reason), empty when it can: a homogenised
// law's table holds the static-friction locus, so rate_dependent_static and strain_rate_hardening
// cannot go on it.
std::string inadmissible_reason(const rig::FrictionModel& model, const std::string& effect) {
  rig::FrictionModel with = model;
  for (const std::string& e : implied_effects({effect}, model)) with.add(e);
  try {
    rig::validate(with);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

std::vector<std::string> default_candidates(const rig::FrictionModel& model, const std::string& kind) {
  std::vector<std::string> names;
  for (const auto& e : rig::effect_catalogue())
    if (!model.has(e.name) && (e.diagnosed_in.empty() || std::count(e.diagnosed_in.begin(), e.diagnosed_in.end(), kind)) &&
        inadmissible_reason(model, e.name).empty())
      names.push_back(e.name);
  return names;
}

std::string DiagnosisOptions::invalid_reason() const {
  if (starts < 1) return "starts must be at least 1";
  if (max_iterations < 1) return "max_iterations must be at least 1";
  if (!(unexplained_floors > 1.0)) return "unexplained_floors must exceed 1";
  if (bootstrap_samples < 0) return "bootstrap_samples must not be negative";
  if (refit_leaders < 0) return "refit_leaders must not be negative";
  for (const auto& k : calibrate_rig)
    if (k != "stiffness_N_per_m" && k != "damping_N_s_per_m" && k != "damping_ratio" && k != "mass_kg")
      return "cannot calibrate rig key '" + k + "'";
  for (const auto& e : candidates) rig::effect_info(e);
  return "";
}


rig::RigParameters apply_bundle_rig(const ExperimentBundle& b, rig::RigParameters rig) {
  if (b.mass_kg) rig.mass_kg = *b.mass_kg;
  if (b.stiffness_N_per_m) rig.stiffness_N_per_m = *b.stiffness_N_per_m;
  if (b.damping_N_s_per_m) rig.damping_N_s_per_m = *b.damping_N_s_per_m;
  if (b.normal_load_N) rig.normal_load_N = *b.normal_load_N;
  if (b.slider_radius_m) rig.slider_radius_m = *b.slider_radius_m;
  return rig;
}

Diagnosis diagnose(const ExperimentBundle& bundle, const rig::RigParameters& model_rig, const rig::FrictionModel& model,
                   const DiagnosisOptions& o) {
  if (const std::string why = o.invalid_reason(); !why.empty()) throw std::invalid_argument("gap options: " + why);
  const NestedParallelism nested;
  rig::validate(model_rig);
  rig::validate(model);
  for (const std::string& e : o.candidates)  // before any work: the defaults leave such effects out
    if (const std::string why = inadmissible_reason(model, e); !why.empty())
      throw std::invalid_argument("gap: candidate '" + e + "' cannot be added to this model: " + why);
  const Comparison comparison(bundle, model_rig);
  Diagnosis d;
  d.items = comparison.items();
  d.integration_tolerance = comparison.integration_tolerance();
  const std::size_t n = d.items.size();
  std::vector<bool> train(n);
  d.heldout.resize(n);
  d.has_heldout = comparison.units() >= 2;
  for (std::size_t i = 0; i < n; ++i) {
    d.heldout[i] = d.has_heldout ? d.items[i].unit % 2 == 1 : true;
    train[i] = d.has_heldout ? !d.heldout[i] : true;
  }
  for (const Item& it : d.items) d.measured.push_back(it.measured);
  // The data's own noise in gap units, and the floor it puts under any model's held-out gap.
  const std::vector<double> noise_r = comparison.relative_noise();
  d.verdict.noise_floor = breakdown(d.items, noise_r, d.heldout).gap;
  const std::vector<double> item_sd = item_noise(d.items, noise_r);
  auto lap = [mark = std::chrono::steady_clock::now()]() mutable {  // seconds since the last lap
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - mark).count();
    mark = now;
    return s;
  };
  std::mutex progress_mutex;
  auto report = [&](const std::string& what) {
    if (!o.progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    o.progress(what);
  };

  // 1. Calibration of the model's own parameters.
  const std::vector<FitParameter> base_space = baseline_space(model, model_rig, o, bundle.relative_uncertainty);
  for (const FitParameter& p : base_space)
    if (p.stated_constant) d.rig_relative_uncertainty[p.name] = bundle.relative_uncertainty.at(p.name);
  // Two starts: the model's own values and a guess read off the data (μs from the friction
  // maxima or static points, μk midway between maxima and minima as in Coulomb stick-slip).
  Setup guess{model_rig, model};
  {
    const FrictionLevels levels = friction_levels_from_data(d.items, {model.baseline.mu_s, model.baseline.mu_k});
    guess.model.baseline.mu_s = levels.mu_s;
    guess.model.baseline.mu_k = levels.mu_k;
    // A machine nobody describes: its stiffness from the elastic rise after a velocity step, and
    // half-critical damping (a servo-driven load point is far from the thesis rig's ζ ≈ 0.01).
    const double k_read = comparison.step_response().loading_stiffness_N_per_m;
    if (calibrates(o, "stiffness_N_per_m") && std::isfinite(k_read)) guess.rig.stiffness_N_per_m = k_read;
    if (calibrates(o, "damping_ratio")) set_damping_ratio(guess.rig, 0.5);
  }
  DiagnosisOptions calibration = o;
  calibration.max_iterations = std::max(50, 2 * o.max_iterations);  // few parameters: converge fully, so no
                                                                    // candidate wins by mere recalibration
  // Multi-start, each start searched, and the best refined (central differences, tighter stop)
  // to where its gradient vanishes: the search's forward 1 % step stops short on the kinks of
  // event-based observables (a foreign Coulomb control: CONVERGENCE after 2 iterations, μs 2 %
  // below the truth, the period of every run 10 % short, and the rest blamed on a mechanism).
  // Starts: the model's values, the levels read off the data, and that reading with the excess
  // μs − μk 20 % smaller and larger (the amplitude and period of stick-slip scale with it).
  const bool fits_friction = !model.baseline.homogenised;
  std::vector<Setup> starts{Setup{model_rig, model}};
  if (fits_friction) starts.push_back(guess);
  if (fits_friction && !model.baseline.kinetic)
    for (double f : {0.8, 1.2}) {
      Setup s = guess;
      const double mu_k = s.model.baseline.mu_k, excess = s.model.baseline.mu_s - mu_k;
      s.model.baseline.mu_s = std::clamp(mu_k + f * excess, 0.011, 1.49);
      starts.push_back(s);
    }
  auto calibrate = [&](const std::vector<double>& w) {
    std::vector<FitResult> from_start(starts.size());
    parallel_for(starts.size(), [&](std::size_t k) {
      from_start[k] = fit(comparison, base_space, starts[k], w, calibration, o.seed, 1, base_space.size());
    });
    FitResult best = from_start.front();
    double searched_s = 0.0;
    for (const FitResult& f : from_start) {
      searched_s += f.termination.wall_s;
      if (f.cost < best.cost) best = f;
    }
    if (FitResult refined = fit(comparison, base_space, best.setup, w, calibration, o.seed, 1, base_space.size(), Resolution::refine);
        refined.cost <= best.cost)
      best = refined;
    best.termination.wall_s += searched_s;
    return best;
  };
  // First with every observable weighing the same (no model has claimed an error yet), then again
  // weighed by the likelihood at the scale that fit leaves (likelihood_weights, verdict.h), with
  // the first answer as one more start; the re-calibration and the baseline's bootstrap refits use
  // those weights, the candidates' fits equal shares (DiagnosisOptions::fit_weights).
  const std::vector<double> equal_w = weights(d.items, train);
  FitResult calibrated = calibrate(equal_w);
  std::vector<double> fit_w = equal_w;  // the baseline's
  if (o.fit_weights == FitWeights::likelihood) {
    fit_w = likelihood_weights(d.items, comparison.residuals(comparison.predict(calibrated.setup.rig, calibrated.setup.model, o.seed)),
                               item_sd, train);
    const double first_s = calibrated.termination.wall_s;
    starts.push_back(calibrated.setup);
    calibrated = calibrate(fit_w);
    calibrated.termination.wall_s += first_s;
  }
  d.calibration.starts = static_cast<int>(starts.size());
  {
    std::map<std::string, std::pair<double, int>> scale;
    for (std::size_t i = 0; i < n; ++i)
      if (fit_w[i] > 0.0) scale[d.items[i].observable].first += 1.0 / (fit_w[i] * fit_w[i]), ++scale[d.items[i].observable].second;
    for (const auto& [observable, acc] : scale) d.calibration.fit_scale_by_observable[observable] = std::sqrt(acc.first / acc.second);
  }
  d.stage_times.calibration_s = lap();
  const std::vector<bool> all(n, true);
  const Multiplicity held_m = multiplicity(d.heldout);
  std::vector<double> baseline_lpd;
  double calibrated_cost = calibrated.cost;
  auto set_baseline = [&](const FitResult& f) {
    d.calibrated = f.setup.model;
    d.rig = f.setup.rig;
    d.calibrated_params = values(base_space, f.setup);
    d.calibration_fit = f.termination;
    d.baseline_simulated = comparison.predict(d.rig, d.calibrated, o.seed);
    d.baseline_residuals = comparison.residuals(d.baseline_simulated);
    d.calibration.train_gap = breakdown(d.items, d.baseline_residuals, train).gap;
    d.baseline = breakdown(d.items, d.baseline_residuals, all);
    d.baseline_heldout = breakdown(d.items, d.baseline_residuals, d.heldout);
    d.best_simulated = d.baseline_simulated;
    baseline_lpd = log_density(d.baseline_residuals, predictive(d.items, d.baseline_residuals, item_sd, train));
    calibrated_cost = f.cost;
  };
  set_baseline(calibrated);
  d.calibration.train_noise_floor = breakdown(d.items, noise_r, train).gap;
  report("baseline calibration: train gap " + numerics::fmt(d.calibration.train_gap, "%.3g") + ", " +
         numerics::fmt(d.calibration.train_floors(), "%.3g") + " noise floors");
  // The candidates the data are searched over (decisive() in verdict.h): the singles, then a pair.
  int comparisons = 1;
  auto judge = [&](Candidate& c) {
    c.heldout_gap_before = d.baseline_heldout.gap;
    const Standing st = standing_of(d.items, c.residuals, item_sd, train, baseline_lpd, d.baseline_heldout.gap, held_m, comparisons);
    c.evidence_nats = st.evidence.gain, c.evidence_se_nats = st.evidence.se;
    c.earns = st.earns;
  };

  // 2. Candidates.
  const std::vector<std::string> names = o.candidates.empty() ? default_candidates(model, bundle.kind) : o.candidates;
  comparisons = static_cast<int>(names.size());
  // The candidates' searches hold the rig where the calibration put it — the stated constants and
  // the keys calibrated over wide ranges alike: three more coordinates would triple a search's
  // cost, and a search free to move the machine wanders to rigs that are slow to integrate (a
  // 1e6 N/m spring at ζ = 0.001 rings at 160 Hz through a 118-s velocity-step record). The
  // leaders' refinements, the pair and the re-calibration free them again, so the candidates
  // are compared with the machine at its best.
  std::vector<FitParameter> search_base;
  std::copy_if(base_space.begin(), base_space.end(), std::back_inserter(search_base),
               [](const FitParameter& p) { return p.target != FitParameter::Target::rig; });
  auto space_of = [&](const std::vector<std::string>& effects, bool with_rig) {
    std::vector<FitParameter> space = with_rig ? base_space : search_base;
    for (const auto& e : implied_effects(effects, model))
      for (FitParameter p : effect_parameters(e)) space.push_back(p);
    return space;
  };
  auto candidate_from = [&](const std::vector<std::string>& effects, const std::vector<FitParameter>& space, const FitResult& fitted) {
    Candidate c;
    c.effects = effects;
    c.model = fitted.setup.model;
    c.rig = fitted.setup.rig;
    c.params = values(space, fitted.setup);
    c.fit = fitted.termination;
    c.extra_parameters = static_cast<int>(
        std::count_if(space.begin(), space.end(), [](const FitParameter& p) { return p.target == FitParameter::Target::effect; }));
    c.residuals = comparison.residuals(comparison.predict(c.rig, c.model, o.seed));
    c.train_gap = breakdown(d.items, c.residuals, train).gap;
    const GapBreakdown held = breakdown(d.items, c.residuals, d.heldout);
    c.heldout_gap_after = held.gap;
    c.heldout_after_by_observable = held.by_observable;
    judge(c);
    return c;
  };
  const double median_v = [&] {
    std::vector<double> v;
    for (const Item& it : d.items) v.push_back(it.v_m_per_s);
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  }();
  auto evaluate = [&](const std::vector<std::string>& effects, std::uint64_t seed) {
    Setup start{d.rig, d.calibrated};
    const double phi = d.rig.stiffness_N_per_m * median_v / d.rig.normal_load_N;  // the data's median load rate
    const std::vector<std::string> with_implied = implied_effects(effects, model);
    const bool locus_fitted = std::count(with_implied.begin(), with_implied.end(), "rate_dependent_static") > 0;
    for (const auto& e : with_implied) {
      start.model.add(e);
      if ((e == "rate_and_state" || e == "slip_transient") && median_v > 0.0) {
        // Reference speed at the data's median driven speed (not fitted: another V0 only moves
        // the baseline μk, which is fitted), so the increments stay small where the data are.
        start.model.set(e, "reference_speed_m_per_s", std::clamp(median_v, 1e-9, 10.0));
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
        const double mu_s_max = std::max(start.model.get("rate_dependent_static", "mu_s_max"), 1.2 * d.calibrated.baseline.mu_s);
        shape.sigma0_over_tau_i = contact::sigma0_over_tau_i_from_upper_asymptote(mu_s_max, shape.alpha);
        if (phi > 0.0 && d.calibrated.baseline.mu_s < mu_s_max) {
          start.model.set("rate_dependent_static", "mu_s_max", mu_s_max);
          start.model.set("rate_dependent_static", "location_per_s",
                          std::clamp(contact::location_through_point_per_s(shape, phi, d.calibrated.baseline.mu_s), 1e-5, 1e5));
        }
      }
    }
    // A velocity step shows the slip transient directly: a peak Δμ above the old level, then a
    // decay over a slip distance. Breakaway at μs = μk + Δμ_peak with the whole excess decaying
    // (a = 1) over the measured 1/e distance is where that fit starts too.
    const StepResponse& step = comparison.step_response();
    bool read_off = false;
    if (effects == std::vector<std::string>{"slip_transient"} && !start.model.baseline.kinetic && step.decay_distance_m > 0.0) {
      start.model.baseline.mu_s = start.model.baseline.mu_k + step.peak_rise;
      start.model.set("slip_transient", "amplitude", 1.0);
      start.model.set("slip_transient", "decay_distance_m", step.decay_distance_m);
      read_off = true;
    }
    // A slide-hold-slide test shows the healing directly: the re-slide peaks grow as
    // b ln(1 + t_h V/D_c) with the hold (calibration.h). The ageing law's fit starts there, with
    // the peaks all the healing's (μs = μk).
    if (effects == std::vector<std::string>{"rate_and_state"}) {
      if (const Healing h = healing_from_data(d.items, train); std::isfinite(h.b)) {
        start.model.baseline.mu_s = start.model.baseline.mu_k;
        start.model.set("rate_and_state", "b", std::min(h.b, 0.05));
        start.model.set("rate_and_state", "decay_distance_m", h.decay_distance_m);
        read_off = true;
      }
    }
    const std::vector<FitParameter> space = space_of(effects, false);
    const FitResult r = fit(comparison, space, start, equal_w, o, seed, o.starts, search_base.size(), Resolution::search, read_off);
    Candidate c = candidate_from(effects, space, r);
    report("fitted " + verdict_name(effects));
    return c;
  };
  // The leading candidates are compared at convergence: continue their fits from where the
  // search stopped, so that a nested effect (thermal thinning with a large U_T is viscous
  // friction) does not win over a simpler one only because its search ran further.
  DiagnosisOptions refining = o;
  refining.max_iterations = std::max(20, o.max_iterations);
  auto refine = [&](const Candidate& c) {
    const std::vector<FitParameter> space = space_of(c.effects, true);
    const FitResult r = fit(comparison, space, Setup{c.rig, c.model}, equal_w, refining, o.seed, 1, space.size(), Resolution::refine);
    Candidate refined = candidate_from(c.effects, space, r);
    refined.fit.wall_s += c.fit.wall_s;  // the search's time too
    report("refined " + verdict_name(c.effects));
    return refined;
  };

  std::vector<Candidate> singles(names.size());
  parallel_for(names.size(), [&](std::size_t k) { singles[k] = evaluate({names[k]}, o.seed * 7919 + k); });
  d.stage_times.candidates_s = lap();
  auto better = [](const Candidate& a, const Candidate& b) {
    if (a.earns != b.earns) return a.earns;
    return a.evidence_nats > b.evidence_nats;
  };
  std::stable_sort(singles.begin(), singles.end(), better);
  // A fair baseline: re-calibrate it from the baseline parameters the best candidates settled on,
  // so that no effect wins only because its fit also found better μs, μk than the calibration.
  bool recalibrated = false;
  {
    std::vector<FitResult> from_leader(std::min<std::size_t>(singles.size(), 3));
    parallel_for(from_leader.size(), [&](std::size_t k) {
      Setup from{singles[k].rig, model};
      from.model.baseline = singles[k].model.baseline;
      from_leader[k] = fit(comparison, base_space, from, fit_w, calibration, o.seed, 1, base_space.size());
    });
    for (const FitResult& f : from_leader)  // in the leaders' order, as a serial loop would take them
      if (f.cost < calibrated_cost) set_baseline(f), recalibrated = true;
  }
  if (recalibrated) {
    for (Candidate& c : singles) judge(c);
    std::stable_sort(singles.begin(), singles.end(), better);
  }
  d.stage_times.recalibration_s = lap();
  // Four: the hardened locus (three parameters on a Coulomb model) fits static friction well enough
  // to rank third on data with a dynamic effect, and with three slots it pushed out the effect
  // itself (independent lift seed 306: the lift's search stops at its grid start, U½ = 0.63 mm/s,
  // where the cost is flat; refined, it moves to 1.4 mm/s and closes the gap). On two threads the
  // fourth refinement runs beside the third.
  constexpr std::size_t kRefined = 4;
  parallel_for(std::min(kRefined, singles.size()), [&](std::size_t k) { singles[k] = refine(singles[k]); });
  // Nested candidates (kNestings): when the general fit does better on train, the special one is
  // refined again from the general fit's projection and kept if it then fits train better, so that
  // it is judged at its own best rather than lose to its generalisation on search luck (selftest
  // seed 3: the viscous search stopped at c = 33.7 N s/m, held-out gap 0.0045, while thermal
  // thinning settled at U_T = 10 m/s, c0 = 34.6 N s/m, held-out gap 0.0015; independent seed 301,
  // Kato ageing: the locus search stopped at a held-out gap of 0.0112 and the hardened locus, one
  // parameter more, was named at 47 %; refined from its m = 0 projection the locus is named, 56 %).
  const auto single = [&](const std::string& e) {
    return std::find_if(singles.begin(), singles.end(), [&](const Candidate& c) { return c.effects == std::vector<std::string>{e}; });
  };
  for (const Nesting& nest : kNestings) {
    const auto general = single(nest.general), special = single(nest.special);
    if (general == singles.end() || special == singles.end() || !(general->train_gap < special->train_gap)) continue;
    Candidate from = *special;
    from.rig = general->rig;
    from.model.baseline = general->model.baseline;
    const std::vector<FitParameter> special_space = effect_parameters(nest.special);
    for (const Carried& p : nest.carried) {
      if (!p.effect) continue;
      // Into the special effect's fit range: the general one's parameter may lie beyond it (thermal
      // thinning's traction coefficient of 2.5e4 N s/m on the slide-hold-slide case, where viscous
      // friction's range ends at 1e4 N s/m, and the projection would not be a model at all).
      double value = general->model.get(p.effect, p.parameter);
      for (const FitParameter& q : special_space)
        if (q.name == p.special_parameter) value = std::clamp(value, q.lower, q.upper);
      from.model.set(nest.special, p.special_parameter, value);
    }
    if (Candidate projected = refine(from); projected.train_gap < special->train_gap) *special = projected;
  }
  std::stable_sort(singles.begin(), singles.end(), better);
  d.candidates = singles;
  if (singles.size() >= 2) {
    const Candidate& best = singles.front();
    const double closed = best.heldout_gap_before > 0.0 ? 1.0 - best.heldout_gap_after / best.heldout_gap_before : 1.0;
    if (closed < o.pair_threshold && d.baseline_heldout.gap > 0.0) {
      // Against the singles it must have decisive evidence over the simpler one (verdict_index()).
      comparisons = static_cast<int>(singles.size()) + 1;
      for (Candidate& c : d.candidates) judge(c);
      d.candidates.push_back(refine(evaluate({singles[0].effects[0], singles[1].effects[0]}, o.seed * 7919 + 104729)));
      std::stable_sort(d.candidates.begin(), d.candidates.end(), better);
    }
  }

  d.stage_times.refinement_s = lap();

  // Localization: share of the baseline's squared residuals by observable, phase and speed class.
  d.localization = localize(d.items, d.baseline_residuals);

  // 3. Verdict.
  const Candidate* chosen = nullptr;
  {
    std::vector<Standing> standing;
    for (const Candidate& c : d.candidates)
      standing.push_back(standing_of(d.items, c.residuals, item_sd, train, baseline_lpd, d.baseline_heldout.gap, held_m, comparisons));
    const Decision decision = decide(d.candidates, standing, held_m, o, d.baseline_heldout.gap, d.verdict.noise_floor);
    if (decision.index >= 0) chosen = &d.candidates[static_cast<std::size_t>(decision.index)];
    for (int k : indistinguishable(standing, decision.index, held_m))
      d.verdict.indistinguishable.push_back(verdict_name(d.candidates[static_cast<std::size_t>(k)].effects));
    d.verdict.unexplained = decision.unexplained;
  }
  d.verdict.heldout_gap_before = d.baseline_heldout.gap;
  if (chosen) {
    d.verdict.effects = chosen->effects;
    d.verdict.heldout_gap_after = chosen->heldout_gap_after;
    d.best_simulated = comparison.predict(chosen->rig, chosen->model, o.seed);
  } else {
    d.verdict.heldout_gap_after = d.baseline_heldout.gap;
  }
  d.verdict.remaining_floors = d.verdict.noise_floor > 0.0 ? d.verdict.heldout_gap_after / d.verdict.noise_floor
                                                           : std::numeric_limits<double>::quiet_NaN();
  {
    const std::vector<double>& remaining = chosen ? chosen->residuals : d.baseline_residuals;
    std::vector<double> held(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      if (d.heldout[i]) held[i] = remaining[i];
    if (const std::vector<Localization> l = localize(d.items, held); !l.empty())
      d.verdict.remaining_where = l.front().observable + " (" + l.front().where + ", worst " + l.front().worst_item + ")";
  }
  {
    // 4. Confidence, with the leaders refitted on training data measured again within their noise:
    // a cut that a fit found only in this draw of the training noise does not survive its redraws.
    const int chosen_index = chosen ? static_cast<int>(chosen - d.candidates.data()) : -1;
    std::vector<std::size_t> leaders;
    if (chosen) leaders.push_back(static_cast<std::size_t>(chosen_index));
    for (std::size_t k = 0; k < d.candidates.size() && leaders.size() < static_cast<std::size_t>(o.refit_leaders); ++k)
      if (static_cast<int>(k) != chosen_index) leaders.push_back(k);
    bool train_noise = false;
    for (std::size_t i = 0; i < n; ++i) train_noise = train_noise || (train[i] && noise_r[i] > 0.0);
    std::vector<Refit> refits;
    if (train_noise && o.refit_leaders > 0 && o.bootstrap_samples > 0) {
      std::vector<Fitted> fits{{search_base, Setup{d.rig, d.calibrated}, &d.baseline_residuals, fit_w}};
      for (std::size_t k : leaders) {
        const Candidate& c = d.candidates[k];
        fits.push_back({space_of(c.effects, false), Setup{c.rig, c.model}, &c.residuals, equal_w});
      }
      const auto redrawn = refitted_residuals(comparison, fits, train, noise_r, o.bootstrap_samples, o.seed);
      report("linearised the leaders' refits");
      for (const auto& sample : redrawn) {
        Refit& r = refits.emplace_back();
        r.baseline = sample[0];
        for (std::size_t k = 0; k < leaders.size(); ++k) r.candidates[leaders[k]] = sample[k + 1];
      }
      d.verdict.refitted.push_back("baseline");
      for (std::size_t k : leaders) d.verdict.refitted.push_back(verdict_name(d.candidates[k].effects));
    }
    const std::string name = verdict_name(d.verdict);
    const Confidence fixed = bootstrap_confidence(d.items, d.heldout, noise_r, d.baseline_residuals, d.candidates, chosen_index, name, o);
    const Confidence c =
        refits.empty() ? fixed : bootstrap_confidence(d.items, d.heldout, noise_r, d.baseline_residuals, d.candidates, chosen_index, name, o, refits);
    d.verdict.confidence = c.agreement;
    d.verdict.confidence_fixed_fits = fixed.agreement;
    d.verdict.heldout_gap_after_std = c.heldout_gap_after_std;
  }
  d.stage_times.confidence_s = lap();

  d.verdict.conclusion = conclusion(d, chosen);
  return d;
}

const Candidate* verdict_candidate(const Diagnosis& d) {
  if (d.verdict.effects.empty()) return nullptr;
  for (const Candidate& c : d.candidates)
    if (c.effects == d.verdict.effects) return &c;
  return nullptr;
}

}  // namespace tribo::gap
