#include "apps/thesis_comparison.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "apps/output.h"
#include "rig/steady_sliding.h"

namespace tribo::cli {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Report values to 3 significant digits.
std::string fmt3(double v) { return fmt(v, "%.3g"); }

// Mean μ at the run's breakaways (all of them: a run that slides steadily after its first
// breakaway still shows where it left the locus).
double breakaway_mu(const rig::SweepPoint& p) {
  double sum = 0.0;
  int n = 0;
  for (const rig::Event& e : p.result.events) {
    if (e.kind != rig::EventKind::breakaway) continue;
    sum += e.mu;
    ++n;
  }
  return n > 0 ? sum / n : kNaN;
}

std::string regime_verdict(const std::string& tribo, const std::string& thesis) {
  return tribo == thesis ? "agrees" : "miss";
}

void add_regime_rows(std::vector<ComparisonRow>& rows, const rig::RigParameters& rig, const ThesisFigureRuns& runs) {
  const double stick_mu = breakaway_mu(runs.stick_slip);
  rows.push_back({"static friction at v = 2.8e-2 in/s", "Fig 5.2.1", "0.26", fmt3(stick_mu), "±10 %",
                  numeric_verdict(stick_mu, 0.26, 0.10), "mean mu at the run's breakaways"});
  rows.push_back({"regime at v = 2.8e-2 in/s", "Fig 5.2.1", "stick_slip", runs.stick_slip.observables.regime, "same regime",
                  regime_verdict(runs.stick_slip.observables.regime, "stick_slip"), ""});
  const double multi_mu = breakaway_mu(runs.multi_cycle);
  rows.push_back({"static friction of the multi-cycle slip trace (slower than Fig 5.2.1)", "Fig 5.2.2", "0.45",
                  fmt3(multi_mu), "±10 %", numeric_verdict(multi_mu, 0.45, 0.10), "mean mu at breakaways, v = 1e-4 in/s"});
  rows.push_back({"regime at v = 5.3 in/s", "Fig 5.2.8", "quasi_harmonic", runs.quasi_harmonic.observables.regime,
                  "same regime", regime_verdict(runs.quasi_harmonic.observables.regime, "quasi_harmonic"), ""});
  const double plateau = runs.quasi_harmonic.observables.mean_friction_N / rig.normal_load_N;
  rows.push_back({"kinetic friction at v = 5.3 in/s", "Fig 5.2.8", "0.15", fmt3(plateau), "±15 %",
                  numeric_verdict(plateau, 0.15, 0.15), "time-averaged friction / W over the analysis window"});
  // §5.2a (Fig 5.2.2): on the multi-cycle slip trace, the friction where the stable slip passes
  // zero relative velocity (viscous drag zero there) is μ ≈ 0.03 — "the load supported by the
  // film". Read where the thesis read it: at the reversals of the slow run's slips.
  const rig::RunObservables& slow = runs.multi_cycle.observables;
  const bool reversed = std::isfinite(slow.mu_at_reversal_mean);
  rows.push_back({"friction of stable slip at zero relative velocity", "§5.2a (Fig 5.2.2)", "0.03",
                  reversed ? fmt3(slow.mu_at_reversal_mean) : "", "±50 %",
                  reversed ? numeric_verdict(slow.mu_at_reversal_mean, 0.03, 0.5) : "miss",
                  reversed ? "mean mu at the " + std::to_string(slow.reversals) +
                                 " velocity matches a slip ran through, v = 1e-4 in/s"
                           : "no slip ran through a velocity match at v = 1e-4 in/s: no stable slip to read"});
}

// The Stribeck curve of the homogenised law over 1e-5 … 1 m/s (10 per decade); points whose film
// leaves the table end it.
std::vector<rig::SteadySliding> stribeck(const rig::HomogenisedBase& base) {
  std::vector<rig::SteadySliding> points;
  for (int i = 0; i <= 50; ++i) {
    try {
      points.push_back(rig::steady_sliding(base, std::pow(10.0, -5.0 + 0.1 * i)));
    } catch (const std::out_of_range&) {
      break;
    }
  }
  return points;
}

void add_film_rows(std::vector<ComparisonRow>& rows, const rig::HomogenisedBase& base) {
  const std::vector<rig::SteadySliding> curve = stribeck(base);
  if (curve.empty()) return;
  // Fig 5.2.8: the friction–velocity curve has its maximum at 1 in/s; an interior maximum of the
  // steady curve, within a factor 2 in speed, agrees.
  std::size_t arg = 0;
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (curve[i].mu > curve[arg].mu) arg = i;
  const bool interior = arg > 0 && arg + 1 < curve.size();
  const double u_max = curve[arg].speed_m_per_s;
  const bool near = interior && std::abs(std::log(u_max / kInch_m)) <= std::log(2.0);
  rows.push_back({"relative speed of the friction maximum", "Fig 5.2.8", fmt3(kInch_m), fmt3(u_max), "factor 2, interior",
                  near ? "agrees" : "miss",
                  interior ? "maximum of the steady-sliding mu(U)"
                           : "no interior maximum: steady mu(U) is largest at the end of 1e-5 … " +
                                 fmt3(curve.back().speed_m_per_s) + " m/s"});
  // Figs 5.2.3–5.2.6: the slip transient decays with slip distance, not time. The film's settling
  // distance U t_h at 1 and 10 in/s: exponent d ln(U t_h)/d ln U = 0 for slip distance, 1 for time.
  const rig::SteadySliding a = rig::steady_sliding(base, kInch_m), b = rig::steady_sliding(base, 10.0 * kInch_m);
  const auto distance = [](const rig::SteadySliding& s) { return s.speed_m_per_s * s.film_relaxation_time_s; };
  const double exponent = std::log(distance(b) / distance(a)) / std::log(10.0);
  const std::string variable = !std::isfinite(exponent) ? ""
                               : exponent < 0.25       ? "slip distance"
                               : exponent > 0.75       ? "time"
                                                       : "between";
  rows.push_back({"variable of the slip transient's decay", "Figs 5.2.3-5.2.6", "slip distance", variable,
                  "exponent < 0.25", variable.empty() ? "not evaluated" : (variable == "slip distance" ? "agrees" : "miss"),
                  "film settling distance U t_h: " + fmt3(distance(a)) + " m at 1 in/s, " +
                      fmt3(distance(b)) + " m at 10 in/s (exponent " + fmt(exponent, "%.2f") + ")"});
}

}  // namespace

double static_coefficient_at_rest(const rig::FrictionLaw& law, double normal_load_N, double load_rate_per_s) {
  std::vector<double> state(law.state_size());
  law.initial_state(state);
  rig::FrictionContext c;
  c.normal_load_N = normal_load_N;
  c.tangential_load_rate_per_s = load_rate_per_s;
  c.state = state;
  return law.static_limit_N(c) / normal_load_N;
}

int agreeing(const std::vector<ComparisonRow>& rows) {
  int n = 0;
  for (const ComparisonRow& r : rows) n += r.verdict == "agrees" ? 1 : 0;
  return n;
}

std::string numeric_verdict(double tribo, double thesis, double relative_tolerance) {
  if (!std::isfinite(tribo) || !std::isfinite(thesis) || thesis == 0.0) return "not evaluated";
  const double relative = tribo / thesis - 1.0;
  if (std::abs(relative) <= relative_tolerance) return "agrees";
  char buf[48];
  std::snprintf(buf, sizeof buf, "off by %+.0f %%", 100.0 * relative);
  return buf;
}

std::vector<ComparisonRow> compare_with_thesis(const rig::RigParameters& rig, const rig::FrictionLaw& law,
                                               const rig::HomogenisedBase* homogenised, const ThesisFigureRuns& runs) {
  std::vector<ComparisonRow> rows;
  // §5.1 / Fig 5.1.2: μs at the slowest load rates, 1e-4 1/s.
  const double upper = static_coefficient_at_rest(law, rig.normal_load_N, 1e-4);
  rows.push_back({"static friction, upper asymptote (load rate 1e-4 1/s)", "§5.1, Fig 5.1.2", "0.55", fmt3(upper), "±10 %",
                  numeric_verdict(upper, 0.55, 0.10), "the law's static limit at rest"});
  add_regime_rows(rows, rig, runs);
  if (homogenised) add_film_rows(rows, *homogenised);
  return rows;
}

}  // namespace tribo::cli
