// The nonlinear method shared by the EHL solvers (ehl_line.h, ehl_point.h): Newton's method on the
// coupled system of pressures and the rigid-body film constant H0, a step limit that keeps every
// film positive, a backtracking line search on ‖F‖₂, and continuation in the speed parameter λ when
// Newton does not converge from the start. The Newton step's linear solve is the Problem's: the
// dense Jacobian of the elastic integral by LU (dense_step, LAPACK) or, for the point contact on
// large grids, GMRES on the applied Jacobian (ehl_point.cpp).
// Internal to lubrication/: a Problem provides
//   Nodal nodal(u, λ)                      the state at every node (its member h: the film)
//   VectorXd row_scales(const Nodal&)      c_i, frozen over a step
//   type Jacobian                          what residual() linearises into
//   VectorXd residual(const Nodal&, c, Jacobian*)
//   bool solve_step(Jacobian&, rhs, step, std::string& why)   step = J⁻¹ rhs, or false and why
//   VectorXd film_change(u, du)            the film's change for a step du from u (linearised)
//   double contact_floor()                 the film H_c at which surfaces touch (0: they never do)
//   void set_cap(double)                   the pressure cap (the hardness in the problem's pressure
//                                          unit, +∞: none; lower_cap)
//   int pressure_unknowns()                the pressures among the unknowns (first), then H0
// and Options the fields tolerance, max_newton_iterations and max_continuation_steps.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>

#include "numerics/dense_solve.h"
#include "numerics/format.h"

namespace tribo::lubrication::ehl {

// The dense step: LU of the Jacobian (overwritten by its factors).
inline bool dense_step(Eigen::MatrixXd& jacobian, const Eigen::VectorXd& rhs, Eigen::VectorXd& step, std::string& why) {
  if (numerics::dense_solve(jacobian, rhs, step)) return true;
  why = "the Newton system is singular";
  return false;
}

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;
  std::string why;
};

// Newton from u (updated in place). Converged when ‖F‖∞ ≤ tolerance and the last step moved no
// pressure by more than 10·tolerance·max(1, max P) — or, after a full step, when that step times
// the contraction rate over it (the pressures' error left, as CVODE's Newton test, Hindmarsh et al.,
// ACM TOMS 31, 2005: del · min(1, crate)) is: a quadratic step that cut ‖F‖∞ by 10⁶ needs no
// further step to show that it has settled. The rate is the slower of the residual's and the steps'
// (CVODE's crate is the steps'): where ‖F‖ falls faster than the error, the residual's alone
// declared a capped crawling ball converged with its pressures 1.7e-5 p_H off (2026-12-02).
// Stalled when three steps in a row, each cut short by the film limit (below), lowered ‖F‖₂ by
// less than 0.1 %.
template <class Problem, class Options>
NewtonOutcome newton(const Problem& problem, double lambda, Eigen::VectorXd& u, const Options& o) {
  NewtonOutcome out;
  typename Problem::Jacobian jac;
  auto state = problem.nodal(u, lambda);
  Eigen::VectorXd scales = problem.row_scales(state);
  Eigen::VectorXd f = problem.residual(state, scales, &jac);
  double norm = f.norm();
  const int np = problem.pressure_unknowns();
  int stalled = 0;  // consecutive steps that cut ‖F‖₂ by less than 0.1 %
  double previous_moved = 0.0;  // the last step's largest pressure change (0 before the first)
  for (int it = 0; it < o.max_newton_iterations; ++it) {
    Eigen::VectorXd step;
    if (!problem.solve_step(jac, -f, step, out.why)) break;
    if (!step.allFinite()) {
      out.why = "the Newton step is not finite";
      break;
    }
    // The step may change no film by more than half of itself: a full Newton step from a start far
    // from the solution closes the film in the contact, and from a collapsed film (ε ~ H³ → 0) the
    // iteration crawls.
    // With boundary layers H_c > 0 (mixed lubrication) a closing film may fall to H_c/2 in one step
    // (below H_c it passes no pressure flow, and ε ~ H³ cannot collapse), and one near H_c may open
    // by 2 H_c.
    const Eigen::VectorXd dh = problem.film_change(u, step);
    const double floor = problem.contact_floor();
    double t = 1.0;
    for (int i = 0; i < dh.size(); ++i) {
      double room = 0.5 * state.h(i);
      if (floor > 0.0) room = dh(i) < 0.0 ? (state.h(i) > floor ? state.h(i) - 0.5 * floor : room) : std::max(room, 2.0 * floor);
      if (std::abs(dh(i)) > room) t = std::min(t, room / std::abs(dh(i)));
    }
    const bool film_limited = t < 1.0;
    Eigen::VectorXd trial;
    auto trial_state = state;
    bool accepted = false;
    double trial_norm = norm;
    for (int k = 0; k < 30; ++k, t *= 0.5) {
      trial = u + t * step;
      trial_state = problem.nodal(trial, lambda);
      if (trial_state.h.minCoeff() <= 0.0) continue;
      trial_norm = problem.residual(trial_state, scales, nullptr).norm();
      if (std::isfinite(trial_norm) && trial_norm < (1.0 - 1e-4 * t) * norm) {
        accepted = true;
        break;
      }
    }
    ++out.iterations;
    if (!accepted) {
      out.why = "the line search found no decrease of the residual";
      break;
    }
    // A film driven to zero at a node halves the step limit at every step and ‖F‖ stands still:
    // the continuation (or the caller) is what can help, not the remaining iterations. (Steps cut
    // short by the line search alone — the minimum function's kinks — do not count.)
    stalled = film_limited && trial_norm > (1.0 - 1e-3) * norm ? stalled + 1 : 0;
    const double moved = (t * step.head(np)).template lpNorm<Eigen::Infinity>();
    const double before = f.template lpNorm<Eigen::Infinity>();
    u = trial;
    state = std::move(trial_state);
    scales = problem.row_scales(state);
    f = problem.residual(state, scales, &jac);
    norm = f.norm();
    out.residual = f.template lpNorm<Eigen::Infinity>();
    // The contraction: the residual's, or the steps' where that is slower — near a kink of the
    // limited wedge or of the minimum function ‖F‖ can fall 100-fold in a step that leaves the
    // pressures' error cut only 3-fold (measured on the capped crawling ball, 31²).
    double rate = 1.0;
    if (t == 1.0 && before > 0.0) rate = std::min(1.0, std::max(out.residual / before, previous_moved > 0.0 ? moved / previous_moved : 0.0));
    previous_moved = moved;
    if (out.residual <= o.tolerance &&
        moved * rate <= 10.0 * o.tolerance * std::max(1.0, u.head(np).template lpNorm<Eigen::Infinity>())) {
      out.converged = true;
      return out;
    }
    if (stalled == 3) {
      out.why = "Newton stalled (‖F‖ fell by less than 0.1 % a step for 3 steps: the film is driven to zero at a node, "
                "which at a high load usually means that the grid does not resolve the contact — refine it)";
      break;
    }
  }
  out.residual = f.template lpNorm<Eigen::Infinity>();
  if (out.why.empty()) out.why = "the iteration limit was reached";
  return out;
}

// The solvers' one-line summary of an outcome: "converged: ‖F‖∞ = … after N Newton iterations" or
// "not converged: why; ‖F‖∞ = …".
inline std::string outcome_message(const NewtonOutcome& n, int iterations) {
  return n.converged ? "converged: ‖F‖∞ = " + numerics::shortest(n.residual) + " after " + std::to_string(iterations) + " Newton iterations"
                     : "not converged: " + n.why + "; ‖F‖∞ = " + numerics::shortest(n.residual);
}

struct SolveOutcome {
  NewtonOutcome newton;  // the last Newton solve (at the target λ when it converged)
  int iterations = 0;    // Newton iterations, continuation steps included
  int continuation_steps = 0;
};

// Newton from `start` at λ; where it does not converge, continuation from a thinner film: λ lowered
// by decades from the start until Newton converges (the smaller λ, the closer the pressure to the
// Hertz start), then raised back to the target, the step halved (in log λ) on every failure. With
// asperity contact also the other way, from a thicker film down to the target (below).
// u returns the answer (the first Newton attempt's last iterate when nothing converged).
template <class Problem, class Options>
SolveOutcome solve_with_continuation(const Problem& problem, double lambda, const Eigen::VectorXd& start, Eigen::VectorXd& u,
                                     const Options& o) {
  SolveOutcome out;
  u = start;
  out.newton = newton(problem, lambda, u, o);
  out.iterations = out.newton.iterations;
  if (out.newton.converged) return out;
  const double log_target = std::log(lambda);
  // One continuation: λ moved away from the target by decades (`away` = −1: a thinner film, +1 a
  // thicker one) until Newton converges, then back, within `budget` solves (shared by both
  // directions); true when it reached the target (u its answer).
  const double floor = problem.contact_floor();
  int budget = o.max_continuation_steps;
  auto continuation = [&](double away, std::string& why) {
    double log_current = log_target, step = std::log(10.0);
    Eigen::VectorXd anchor;
    bool anchored = false, reached = false;
    int steps = 0;
    while (steps < budget && !anchored) {
      ++steps;
      log_current += away * step;
      anchor = start;
      const NewtonOutcome n = newton(problem, std::exp(log_current), anchor, o);
      out.iterations += n.iterations;
      anchored = n.converged;
    }
    while (anchored && !reached && steps < budget) {
      ++steps;
      const double next = away > 0.0 ? std::max(log_target, log_current - step) : std::min(log_target, log_current + step);
      Eigen::VectorXd trial = anchor;
      const NewtonOutcome n = newton(problem, std::exp(next), trial, o);
      out.iterations += n.iterations;
      if (n.converged) {
        anchor = trial;
        log_current = next;
        reached = next == log_target;
        if (reached) out.newton = n;
      } else {
        step *= 0.5;
      }
    }
    out.continuation_steps += steps;
    budget -= steps;
    if (reached) {
      u = anchor;
    } else if (floor == 0.0 || steps > 0) {
      // A smooth contact has one direction, which its words leave unnamed where nothing anchored.
      const std::string film = away > 0.0 ? "thicker" : "thinner";
      why += anchored ? " (continuation in λ from a " + film + " film stopped at λ = " + numerics::shortest(std::exp(log_current)) +
                            ", the target " + numerics::shortest(lambda) + ")"
                      : " (and at every λ of the continuation" + (floor == 0.0 ? std::string() : " from a " + film + " film") + ")";
    }
    return reached;
  };
  std::string why = out.newton.why;
  // With asperity contact (contact_floor() > 0) a film closing onto the surfaces is what a thinner
  // film cannot lead Newton to: the continuation is tried both ways, first from a thicker film where
  // the start's film is within 10 H_c of closing.
  const double first = floor > 0.0 && problem.nodal(start, lambda).h.minCoeff() < 10.0 * floor ? 1.0 : -1.0;
  if (!continuation(first, why) && floor > 0.0) continuation(-first, why);
  if (!out.newton.converged) out.newton.why = why;
  return out;
}

// Continuation in the hardness (EhlRoughness::hardness_Pa; `cap` in the problem's pressure unit):
// from the elastic answer u, the cap lowered from its peak pressure to `cap` geometrically, at most
// a tenth of the way (in the log) a solve, each Newton from the last answer — the yielded zone grows
// from the peak outwards and the contact widens, so each solve moves the active sets at their edges
// only (on the tests' ball at 0.8 p_H: 61² in 8 solves). A solve that does not converge is retried
// at half the stride, down to 1/320 of the way; the stride doubles again (up to a tenth) after a
// success. Adds to `out`'s counts; `out.newton` is the last solve.
template <class Problem, class Options>
void lower_cap(const Problem& problem, double lambda, double cap, Eigen::VectorXd& u, const Options& o, SolveOutcome& out) {
  const double peak = u.head(problem.pressure_unknowns()).maxCoeff();
  problem.set_cap(cap);
  if (!(peak > cap)) return;  // the cap does not bind
  constexpr double kLargest = 0.1, kSmallest = kLargest / 32.0;
  double done = 0.0, stride = kLargest;  // fractions of ln(peak/cap)
  while (done < 1.0) {
    const double next = std::min(1.0, done + stride), at = peak * std::pow(cap / peak, next);
    problem.set_cap(at);
    Eigen::VectorXd trial = u;
    const NewtonOutcome n = newton(problem, lambda, trial, o);
    out.iterations += n.iterations;
    ++out.continuation_steps;
    out.newton = n;
    if (n.converged) {
      u = trial, done = next, stride = std::min(2.0 * stride, kLargest);
      continue;
    }
    if (stride <= kSmallest) {
      out.newton.why += " (lowering the pressure cap from the elastic peak stopped at " + numerics::shortest(at / peak) +
                        " of it, the hardness " + numerics::shortest(cap / peak) + ")";
      u = trial;
      return;
    }
    stride *= 0.5;
  }
}

}  // namespace tribo::lubrication::ehl
