// The pipeline's last stages (pipeline.h): the verdict's choice and its bootstrap confidence with
// the leaders refitted on redrawn training data.
#include <Eigen/Dense>

#include <algorithm>
#include <random>

#include "gap/laplace.h"
#include "gap/pipeline.h"
#include "gap/refit.h"
#include "numerics/parallel.h"

namespace tribo::gap {
namespace {

// A fit the bootstrap refits (diagnosis.h step 4): its search coordinates (the rig held where
// the fit put it), where it stopped, and the residuals it left.
struct Fitted {
  std::vector<FitParameter> space;
  FitSetup setup;
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
  std::vector<FitPoint> points;
  for (const Fitted& f : fits) points.push_back({f.space, f.setup});
  const std::vector<Linearisation> at = linearise(c, points, seed);
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
    const std::vector<double>& u = at[f].u;
    std::vector<double> below, above;
    for (double x : u) below.push_back(x - 1.0), above.push_back(2.0 - x);
    linear.emplace_back(at[f].jacobian, *fits[f].residuals, fits[f].weights, below, above);
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
  numerics::parallel_for(probes.size(), [&](std::size_t q) {
    const Probe& pr = probes[q];
    const std::vector<double>& centre = at[pr.fit].centre;
    std::vector<double> u = at[pr.fit].u;
    for (std::size_t j = 0; j < u.size(); ++j) u[j] += pr.du(static_cast<Eigen::Index>(j));
    const std::vector<double> r = centre.empty() ? std::vector<double>{} : residuals_at(c, points[pr.fit], u, seed);
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

}  // namespace

Choice choose(const FitProblem& p, const Baseline& b, const std::vector<Candidate>& candidates, int comparisons, double noise_floor) {
  std::vector<Standing> standing;
  for (const Candidate& c : candidates)
    standing.push_back(standing_of(p.items, c.residuals, c.parameter_variance, p.item_sd, p.train, b.lpd, b.heldout.gap, p.held_m, comparisons));
  const Decision decision = decide(candidates, standing, p.held_m, p.options, b.heldout.gap, noise_floor);
  Choice out;
  out.index = decision.index;
  out.unexplained = decision.unexplained;
  out.tentative = decision.tentative;
  for (int k : indistinguishable(standing, decision.index, p.held_m))
    out.indistinguishable.push_back(verdict_name(candidates[static_cast<std::size_t>(k)].effects));
  return out;
}

// Step 4: the leaders refitted on training data measured again within their noise — a cut that a
// fit found only in this draw of the training noise does not survive its redraws.
ConfidenceStage confidence(const FitProblem& p, const Calibration& cal, const Baseline& b, const std::vector<Candidate>& candidates,
                           int chosen, const std::string& verdict) {
  const DiagnosisOptions& o = p.options;
  std::vector<std::size_t> leaders;
  if (chosen >= 0) leaders.push_back(static_cast<std::size_t>(chosen));
  for (std::size_t k = 0; k < candidates.size() && leaders.size() < static_cast<std::size_t>(o.refit_leaders); ++k)
    if (static_cast<int>(k) != chosen) leaders.push_back(k);
  bool train_noise = false;
  for (std::size_t i = 0; i < p.items.size(); ++i) train_noise = train_noise || (p.train[i] && p.noise_r[i] > 0.0);
  ConfidenceStage out;
  std::vector<Refit> refits;
  if (train_noise && o.refit_leaders > 0 && o.bootstrap_samples > 0) {
    std::vector<Fitted> fits{{p.search_base, b.setup, &b.residuals, cal.weights}};
    for (std::size_t k : leaders) {
      const Candidate& c = candidates[k];
      fits.push_back({p.space_of(c.effects, false), FitSetup{c.rig, c.model}, &c.residuals, p.equal_w});
    }
    const auto redrawn = refitted_residuals(*p.comparison, fits, p.train, p.noise_r, o.bootstrap_samples, o.seed);
    p.report("linearised the leaders' refits");
    for (const auto& sample : redrawn) {
      Refit& r = refits.emplace_back();
      r.baseline = sample[0];
      for (std::size_t k = 0; k < leaders.size(); ++k) r.candidates[leaders[k]] = sample[k + 1];
    }
    out.refitted.push_back("baseline");
    for (std::size_t k : leaders) out.refitted.push_back(verdict_name(candidates[k].effects));
  }
  out.fixed = bootstrap_confidence(p.items, p.heldout, p.noise_r, b.residuals, b.parameter_variance, candidates, chosen, verdict, o);
  out.with_refits = refits.empty() ? out.fixed
                                   : bootstrap_confidence(p.items, p.heldout, p.noise_r, b.residuals, b.parameter_variance, candidates, chosen, verdict, o, refits);
  return out;
}

}  // namespace tribo::gap
