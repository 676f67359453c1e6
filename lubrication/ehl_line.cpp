#include "lubrication/ehl_line.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "lubrication/ehl_newton.h"
#include "lubrication/reference/ehl_film.h"
#include "numerics/format.h"

namespace tribo::lubrication {
namespace {

using numerics::shortest;
constexpr double kPi = std::numbers::pi;

// ∫ ln|t| dt = t ln|t| − t (0 at t = 0).
double log_antiderivative(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }

// The discrete problem in Hertz units (header): unknowns P_1 … P_{N−2} and H0.
class LineProblem {
 public:
  LineProblem(const EhlLineContact& c, const EhlRoughness* rough, const PiezoviscousLubricant& l, const EhlLineOptions& o)
      : lub_(l), complementarity_(o.complementarity), n_(o.nodes), dx_((o.outlet_over_half_width - o.inlet_over_half_width) / (o.nodes - 1)) {
    b_ = reference::hertz_line_half_width_m(c.load_per_length_N_per_m, c.reduced_radius_m, c.reduced_modulus_Pa);
    ph_ = reference::hertz_line_peak_pressure_Pa(c.load_per_length_N_per_m, c.reduced_radius_m, c.reduced_modulus_Pa);
    radius_ = c.reduced_radius_m;
    x_.resize(n_);
    for (int i = 0; i < n_; ++i) x_(i) = o.inlet_over_half_width + i * dx_;
    // Deformation of P constant on each node's cell: −(1/π) ∫_{cell j} ln|X_i − S| dS.
    kernel_.resize(n_, n_);
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) {
        const double d = x_(i) - x_(j);
        kernel_(i, j) = -(log_antiderivative(d + 0.5 * dx_) - log_antiderivative(d - 0.5 * dx_)) / kPi;
      }
    rough_ = Eigen::VectorXd::Zero(n_);
    if (rough) {
      for (int i = 0; i < n_; ++i) rough_(i) = ridge_height_m(*rough, x_(i) * b_) / film_scale_m();
      floor_ = rough->contact_film_m / film_scale_m();
    }
  }

  int nodes() const { return n_; }
  int unknowns() const { return n_ - 1; }  // N − 2 pressures and H0
  int pressure_unknowns() const { return n_ - 2; }
  double dx() const { return dx_; }
  const Eigen::VectorXd& x() const { return x_; }
  double half_width_m() const { return b_; }
  double hertz_pressure_Pa() const { return ph_; }
  double film_scale_m() const { return b_ * b_ / radius_; }  // h = H b²/R
  double contact_floor() const { return floor_; }             // H_c, 0 without roughness
  bool rough() const { return floor_ > 0.0; }                  // (a profile's H_c is positive)

  // With a pressure cap (EhlRoughness::hardness_Pa, set_cap) an unknown q is the pressure below the
  // cap, P = min(q, P_cap), and above it the surface's plastic flow, the film raised by
  // K_self (q − P_cap) at its node (as the point contact's, ehl_point.cpp). Without a cap q = P.
  Eigen::VectorXd pressures(const Eigen::VectorXd& u) const {
    Eigen::VectorXd p = Eigen::VectorXd::Zero(n_);
    p.segment(1, n_ - 2) = u.head(n_ - 2).cwiseMin(cap_);
    return p;
  }
  void set_cap(double cap) const { cap_ = cap; }
  double cap() const { return cap_; }
  bool yields(double q) const { return q >= cap_; }
  // K_self: a node's deflection per unit pressure on its own strip (the same at every node).
  double self_compliance() const { return kernel_(1, 1); }
  bool any_yield(const Eigen::VectorXd& u) const {
    return std::any_of(u.data(), u.data() + (n_ - 2), [&](double q) { return yields(q); });
  }
  // ∂H/∂q by node and unknown at the branch of u: K's columns below the cap, K_self at the node where
  // the unknown yields (empty where none does: K itself).
  Eigen::MatrixXd yielding_kernel(const Eigen::VectorXd& u) const {
    if (!any_yield(u)) return {};
    Eigen::MatrixXd k = kernel_.middleCols(1, n_ - 2);
    for (int j = 0; j < n_ - 2; ++j)
      if (yields(u(j))) k.col(j).setZero(), k(j + 1, j) = kernel_(j + 1, j + 1);
    return k;
  }
  // A nodal field linearly interpolated at X = 0.
  double at_centre(const Eigen::VectorXd& v) const {
    const int i = std::clamp(static_cast<int>(std::floor(-x_(0) / dx_)), 0, n_ - 2);
    const double t = -x_(i) / dx_;
    return (1.0 - t) * v(i) + t * v(i + 1);
  }
  // The film's change for a change du of the unknowns from u (linear: H0 + K dq, K_self where u yields;
  // du is a step, never clipped at the cap).
  Eigen::VectorXd film_change(const Eigen::VectorXd& u, const Eigen::VectorXd& du) const {
    const Eigen::VectorXd change = any_yield(u) ? Eigen::VectorXd(yielding_kernel(u) * du.head(n_ - 2))
                                                : Eigen::VectorXd(kernel_.middleCols(1, n_ - 2) * du.head(n_ - 2));
    return Eigen::VectorXd::Constant(n_, du(n_ - 2)) + change;
  }
  Eigen::VectorXd film(const Eigen::VectorXd& u) const {
    Eigen::VectorXd h = (u(n_ - 2) + 0.5 * x_.array().square() - rough_.array()).matrix() + kernel_ * pressures(u);
    for (int j = 0; j < n_ - 2; ++j)
      if (yields(u(j))) h(j + 1) += kernel_(j + 1, j + 1) * (u(j) - cap_);
    return h;
  }

  // Pressures, film and the lubricant's state at every node, computed once per iterate and read by
  // the row scales and the residual alike.
  struct Nodal {
    Eigen::VectorXd p, h, rho, drho, eps, dlog_eps, w, mobile, coef;  // ε = coef · mobile³
    Eigen::MatrixXd film_by_unknown;  // ∂H/∂q (yielding_kernel; empty: K's interior columns)
    Eigen::VectorXd below_cap;        // ∂P/∂q by unknown: 1, or 0 where it yields
  };
  Nodal nodal(const Eigen::VectorXd& u, double lambda) const {
    Nodal s{pressures(u),        film(u),             Eigen::VectorXd(n_), Eigen::VectorXd(n_), Eigen::VectorXd(n_), Eigen::VectorXd(n_),
            Eigen::VectorXd(n_), Eigen::VectorXd(n_), Eigen::VectorXd(n_), yielding_kernel(u),  Eigen::VectorXd(n_ - 2)};
    for (int j = 0; j < n_ - 2; ++j) s.below_cap(j) = yields(u(j)) ? 0.0 : 1.0;
    for (int i = 0; i < n_; ++i) {
      const ViscosityAtPressure v = viscosity_ratio(lub_, s.p(i) * ph_);
      const DensityAtPressure r = density_ratio(lub_, s.p(i) * ph_);
      s.rho(i) = r.ratio;
      s.drho(i) = r.slope_per_Pa * ph_;
      // The pressure flow passes through the film above the boundary layers (H − H_c; all of it on
      // smooth surfaces): none where the film has closed to H_c — Hu & Zhu's reduced equation there.
      s.mobile(i) = std::max(s.h(i) - floor_, 0.0);
      s.coef(i) = s.rho(i) / (v.ratio * lambda);
      s.eps(i) = s.coef(i) * std::pow(s.mobile(i), 3);
      s.dlog_eps(i) = s.drho(i) / s.rho(i) - v.log_slope_per_Pa * ph_;  // ∂ ln ε/∂P_i at fixed H
      s.w(i) = s.rho(i) * s.h(i);
    }
    return s;
  }

  // Row scales c_i = 1/|∂R_i/∂P_i| (the Poiseuille and the deformation's wedge part of the
  // diagonal): c_i R_i is a pressure in units of p_H whether the film is thick (Poiseuille-dominated)
  // or thin and stiff (the Hertz zone, deformation-dominated). Frozen over a Newton step.
  Eigen::VectorXd row_scales(const Nodal& s) const {
    Eigen::VectorXd c(n_ - 2);
    for (int i = 1; i <= n_ - 2; ++i)
      c(i - 1) = 1.0 / (0.5 * (s.eps(i - 1) + 2.0 * s.eps(i) + s.eps(i + 1)) / (dx_ * dx_) +
                        wedge_diagonal() * s.rho(i) * std::abs(kernel_(i, i)) / dx_);
    return c;
  }

  // F at the nodal state s and, when `jacobian` is given, its (generalised) Jacobian, with the row
  // scales c. λ as in the header.
  using Jacobian = Eigen::MatrixXd;
  bool solve_step(Jacobian& jacobian, const Eigen::VectorXd& rhs, Eigen::VectorXd& step, std::string& why) const {
    return ehl::dense_step(jacobian, rhs, step, why);
  }
  Eigen::VectorXd residual(const Nodal& s, const Eigen::VectorXd& c, Eigen::MatrixXd* jacobian) const {
    const Eigen::VectorXd &p = s.p, &h = s.h, &rho = s.rho, &drho = s.drho, &dlog_eps = s.dlog_eps, &w = s.w, &mobile = s.mobile,
                          &coef = s.coef;
    const int m = unknowns(), np = n_ - 2;
    Eigen::VectorXd f(m);
    if (jacobian) jacobian->setZero(m, m);
    Eigen::RowVectorXd d_eps_p(np), d_w(np);
    for (int i = 1; i <= n_ - 2; ++i) {
      const auto m3 = [&](int k) { return std::pow(mobile(k), 3); };
      const FaceFlow fp = face_flow(coef(i), m3(i), coef(i + 1), m3(i + 1), rough());
      const FaceFlow fm = face_flow(coef(i - 1), m3(i - 1), coef(i), m3(i), rough());
      const double ep = fp.value, em = fm.value;
      const double gp = p(i + 1) - p(i), gm = p(i) - p(i - 1);
      const double poiseuille = (ep * gp - em * gm) / (dx_ * dx_);
      // The wedge d(ρ̄H)/dX at node i: second-order upwind on smooth surfaces; with roughness, where
      // films close, through the limited upwind faces, with its weights cw on w_{i−2} … w_{i+1}
      // (ehl_roughness.h limited_mass_face: the unlimited scheme, extrapolated from a converging
      // inlet over two nodes, would drive a contact's film through zero). First order at node 1.
      double wedge;
      std::array<double, 4> cw{};  // with roughness: ∂wedge/∂w_k, k = i − 2 … i + 1
      if (rough()) {
        const MassFace fo = limited_mass_face(w(i - 1), w(i), w(i + 1));
        const MassFace fi = i >= 2 ? limited_mass_face(w(i - 2), w(i - 1), w(i)) : MassFace{w(i - 1), 0.0, 1.0, 0.0};
        wedge = (fo.value - fi.value) / dx_;
        cw = {-fi.d_prev / dx_, (fo.d_prev - fi.d_here) / dx_, (fo.d_here - fi.d_next) / dx_, fo.d_next / dx_};
      } else if (i >= 2) {
        wedge = (3.0 * w(i) - 4.0 * w(i - 1) + w(i - 2)) / (2.0 * dx_);
      } else {
        wedge = (w(i) - w(i - 1)) / dx_;
      }
      const int row = i - 1;
      const double scale = c(row);
      const double r = -scale * (poiseuille - wedge);
      // Cavitation: P ≥ 0, −c R ≥ 0, P R = 0 as φ(P, −c R) = 0 (complementarity.h).
      const Ncp phi = ncp(complementarity_, p(i), r);
      f(row) = phi.value;
      if (!jacobian) continue;
      const double da = phi.da, db = phi.db;
      // A face's ε through node k's c and m³: ∂c_k/∂P_j = δ_kj c_k ∂ln ε_k/∂P_k, ∂m³_k/∂P_j = 3 m_k² K_kj
      // (m = H − H_c, 0 where closed); ∂(ρ̄H)_k/∂P_j = ρ̄_k K_kj + δ_kj ρ̄'_k H_k.
      // (∂/∂q: the film through s.film_by_unknown, a pressure's own terms times s.below_cap.)
      const Eigen::VectorXd& dp = s.below_cap;
      const auto dfilm = [&](int k) -> Eigen::RowVectorXd {
        if (s.film_by_unknown.size() == 0) return kernel_.row(k).segment(1, np);
        return s.film_by_unknown.row(k);
      };
      auto d_eps = [&](int k, double dc, double dm3) {
        Eigen::RowVectorXd d = (dm3 * 3.0 * mobile(k) * mobile(k)) * dfilm(k);
        if (k >= 1 && k <= n_ - 2) d(k - 1) += dc * coef(k) * dlog_eps(k) * dp(k - 1);
        return d;
      };
      auto d_mass = [&](int k) {
        Eigen::RowVectorXd d = rho(k) * dfilm(k);
        if (k >= 1 && k <= n_ - 2) d(k - 1) += drho(k) * h(k) * dp(k - 1);
        return d;
      };
      d_eps_p = gp * (d_eps(i, fp.dc_a, fp.dm3_a) + d_eps(i + 1, fp.dc_b, fp.dm3_b)) -
                gm * (d_eps(i - 1, fm.dc_a, fm.dm3_a) + d_eps(i, fm.dc_b, fm.dm3_b));
      // The wedge through ρ̄H at its nodes (∂(ρ̄H)_k/∂H0 = ρ̄_k for dw0). The smooth schemes' sums
      // are written out as they were before the limited one joined them: Newton's path on a light,
      // hydrodynamic contact (mixed_line_slow_test's film at a share of 1.5e-4) turns on their bits.
      double dw0 = 0.0;
      if (rough()) {
        d_w.setZero();
        for (int k = 0; k < 4; ++k)
          if (cw[k] != 0.0) d_w += cw[k] * d_mass(i - 2 + k), dw0 += cw[k] * rho(i - 2 + k);
      } else if (i >= 2) {
        d_w = (3.0 * d_mass(i) - 4.0 * d_mass(i - 1) + d_mass(i - 2)) / (2.0 * dx_);
        dw0 = (3.0 * rho(i) - 4.0 * rho(i - 1) + rho(i - 2)) / (2.0 * dx_);
      } else {
        d_w = (d_mass(i) - d_mass(i - 1)) / dx_;
        dw0 = (rho(i) - rho(i - 1)) / dx_;
      }
      Eigen::RowVectorXd d_poiseuille = d_eps_p / (dx_ * dx_);
      if (i + 1 <= n_ - 2) d_poiseuille(i) += ep / (dx_ * dx_) * dp(i);
      d_poiseuille(i - 1) -= (ep + em) / (dx_ * dx_) * dp(i - 1);
      if (i - 1 >= 1) d_poiseuille(i - 2) += em / (dx_ * dx_) * dp(i - 2);
      jacobian->row(row).head(np) = (-scale * db) * (d_poiseuille - d_w);
      (*jacobian)(row, row) += da * dp(row);
      // ∂/∂H0: ∂m³_k/∂H0 = 3 m_k².
      auto de0 = [&](int k, double dm3) { return dm3 * 3.0 * mobile(k) * mobile(k); };
      const double dpois0 = (gp * (de0(i, fp.dm3_a) + de0(i + 1, fp.dm3_b)) - gm * (de0(i - 1, fm.dm3_a) + de0(i, fm.dm3_b))) / (dx_ * dx_);
      (*jacobian)(row, np) = -scale * db * (dpois0 - dw0);
    }
    // Load balance: ΔX Σ P = π/2 (trapezoidal rule, P = 0 at both ends).
    f(np) = dx_ * p.sum() - 0.5 * kPi;
    if (jacobian) jacobian->row(np).head(np) = dx_ * s.below_cap.transpose();
    return f;
  }

 private:
  PiezoviscousLubricant lub_;
  Complementarity complementarity_;
  int n_;
  double dx_, b_ = 0.0, ph_ = 0.0, radius_ = 0.0;
  Eigen::VectorXd x_;
  Eigen::MatrixXd kernel_;
  // Roughness: the stationary surface's heights r at the nodes (H units, 0 for smooth surfaces) and
  // the boundary layers' H_c (0 for smooth surfaces).
  Eigen::VectorXd rough_;
  double floor_ = 0.0;
  mutable double cap_ = std::numeric_limits<double>::infinity();  // the pressure cap / p_H (set_cap)

  // The upwind wedge's weight on its own node: 3/2 second order, 1 first (with roughness).
  double wedge_diagonal() const { return rough() ? 1.0 : 1.5; }
};

void validate(const EhlLineContact& c, const EhlRoughness* rough, const EhlLineOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument(std::string("EHL line contact: ") + name + " must be positive and finite, got " + shortest(v));
  };
  positive(c.load_per_length_N_per_m, "load_per_length_N_per_m");
  positive(c.reduced_radius_m, "reduced_radius_m");
  positive(c.reduced_modulus_Pa, "reduced_modulus_Pa");
  positive(c.mean_speed_m_per_s, "mean_speed_m_per_s");
  if (!(o.inlet_over_half_width < -1.0) || !(o.outlet_over_half_width > 0.0) || !std::isfinite(o.inlet_over_half_width) ||
      !std::isfinite(o.outlet_over_half_width))
    throw std::invalid_argument("EHL line contact: the domain [" + shortest(o.inlet_over_half_width) + ", " +
                                shortest(o.outlet_over_half_width) + "] (in Hertz half widths) must start before −1 and end after 0");
  if (o.nodes < 11) throw std::invalid_argument("EHL line contact: nodes must be ≥ 11, got " + std::to_string(o.nodes));
  if (!(o.tolerance > 0.0)) throw std::invalid_argument("EHL line contact: tolerance must be positive, got " + shortest(o.tolerance));
  if (!rough) return;
  validate(*rough, "EHL line contact");
  if (rough->map) throw std::invalid_argument("EHL line contact: a roughness map is a point contact's (the line takes ridges)");
}

// The analytical start: H0 placing the central film at the larger of Martin's rigid film and
// Pan–Hamrock's EHL estimate, and a semi-ellipse of the load's area over the wider of the Hertz
// contact and the rigid film's pressure zone √(2 R h) (in a light, hydrodynamic contact the pressure
// spreads over many Hertz widths); Newton corrects both.
Eigen::VectorXd analytical_start(const LineProblem& problem, const EhlLineContact& contact, const PiezoviscousLubricant& lubricant) {
  const double radius = contact.reduced_radius_m, b = problem.half_width_m();
  const reference::LineContactGroups g =
      reference::line_contact_groups(contact.load_per_length_N_per_m, radius, contact.reduced_modulus_Pa,
                                     contact.mean_speed_m_per_s, lubricant.viscosity_Pa_s, lubricant.pressure_viscosity_per_Pa);
  const double h_start_m =
      std::max(reference::martin_minimum_film_m(contact.load_per_length_N_per_m, radius, contact.mean_speed_m_per_s,
                                                lubricant.viscosity_Pa_s),
               g.material > 0.0 ? reference::pan_hamrock_central_film(g) * radius : 0.0);
  const int np = problem.pressure_unknowns();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.unknowns());
  const double spread = std::max(1.0, std::sqrt(2.0 * radius * h_start_m) / b);
  for (int i = 1; i <= np; ++i) {
    const double s = problem.x()(i) / spread;
    u(i - 1) = std::sqrt(std::max(0.0, 1.0 - s * s)) / spread;
  }
  u(np) = 0.0;
  const double centre_offset = problem.at_centre(problem.film(u));  // H(0) with H0 = 0
  u(np) = h_start_m / problem.film_scale_m() - centre_offset;
  // Keep the starting film open everywhere (above the contact film with roughness).
  const double lowest = problem.film(u).minCoeff(), floor = problem.contact_floor();
  if (lowest <= floor) u(np) += 0.5 * h_start_m / problem.film_scale_m() + floor - lowest;
  return u;
}

// Grids of at least this many nodes start from the answer on a grid about half as fine (nested
// iteration): Newton then starts next to its answer, where from the analytical start a fine grid's
// thin films crawled (the thick film over boundary layers on 1601 nodes: 772 Newton steps).
constexpr int kNestedMinNodes = 801;

struct ElasticSolve {
  Eigen::VectorXd u;
  ehl::SolveOutcome outcome;
};

// The coarser grid's answer `c` on `coarse` interpolated onto `fine` (Hertz units): pressures linear
// in X between the coarse nodes (0 at both ends), H0 as it is; with a cap set on both, a node starts
// yielded only where both coarse nodes around it yield — its unknown then carries the plastic flow
// interpolated between theirs, q = P_cap + flow/K_self (the film's raise, K_self (q − P_cap), passes
// between grids, K_self not).
Eigen::VectorXd interpolate_start(const LineProblem& coarse, const Eigen::VectorXd& c, const LineProblem& fine) {
  const Eigen::VectorXd pc = coarse.pressures(c);
  const int np = fine.pressure_unknowns(), npc = coarse.pressure_unknowns();
  const double cap = fine.cap();
  Eigen::VectorXd start(fine.unknowns());
  for (int i = 1; i <= np; ++i) {
    const double at = (fine.x()(i) - coarse.x()(0)) / coarse.dx();
    const int k = std::clamp(static_cast<int>(std::floor(at)), 0, coarse.nodes() - 2);
    const double t = at - k;
    start(i - 1) = (1.0 - t) * pc(k) + t * pc(k + 1);
    const auto yielded = [&](int node) { return node >= 1 && node <= npc && coarse.yields(c(node - 1)); };
    if (std::isfinite(cap) && yielded(k) && yielded(k + 1)) {
      const double flow = coarse.self_compliance() * ((1.0 - t) * (c(k - 1) - cap) + t * (c(k) - cap));
      start(i - 1) = cap + flow / fine.self_compliance();
    }
  }
  start(np) = c(npc);
  return start;
}

// The contact at the cap `problem` holds (+∞: elastic). Grids of kNestedMinNodes and more start from
// the answer on a grid about half as fine, solved the same way — so with a hardness the cap is
// lowered (ehl::lower_cap) on the coarsest grid alone, and each finer grid's Newton starts at its
// coarser grid's capped answer with the cap set (examples/ehl-wavy-pin.toml with a 0.9 GPa hardness:
// 6.5 s → 1.35 s on 801 nodes, 62 s and 135 cap steps → 2.7 s on 1601, the same answers to 1e-13).
// Where that Newton or a coarser solve does not converge, this grid's elastic answer (nested, from
// the analytical start where that fails) and the cap lowered on it.
ElasticSolve solve_nested(const LineProblem& problem, const EhlLineContact& contact, const EhlRoughness* roughness,
                          const PiezoviscousLubricant& lubricant, const EhlLineOptions& options, double lambda) {
  const double cap = problem.cap();
  ElasticSolve out;
  int spent = 0;  // Newton iterations of the coarser grids and of a failed attempt from them
  const bool nested = options.start_from_coarser_grid && options.nodes >= kNestedMinNodes;
  if (nested) {
    EhlLineOptions coarse = options;
    coarse.nodes = (options.nodes + 1) / 2;
    const LineProblem coarse_problem(contact, roughness, lubricant, coarse);
    coarse_problem.set_cap(cap);
    const ElasticSolve c = solve_nested(coarse_problem, contact, roughness, lubricant, coarse, lambda);
    spent = c.outcome.iterations;
    if (c.outcome.newton.converged) {
      const Eigen::VectorXd start = interpolate_start(coarse_problem, c.u, problem);
      if (std::isfinite(cap)) {
        out.u = start;
        out.outcome.newton = ehl::newton(problem, lambda, out.u, options);
        out.outcome.iterations = out.outcome.newton.iterations;
      } else {
        out.outcome = ehl::solve_with_continuation(problem, lambda, start, out.u, options);
      }
      out.outcome.iterations += spent;
      if (out.outcome.newton.converged) return out;
      spent = out.outcome.iterations;
    }
  }
  if (std::isfinite(cap) && nested) {
    // The elastic answer on this grid (nested), then the cap lowered onto it.
    problem.set_cap(std::numeric_limits<double>::infinity());
    out = solve_nested(problem, contact, roughness, lubricant, options, lambda);
  } else {
    problem.set_cap(std::numeric_limits<double>::infinity());
    out.outcome = ehl::solve_with_continuation(problem, lambda, analytical_start(problem, contact, lubricant), out.u, options);
  }
  out.outcome.iterations += spent;
  // lower_cap leaves the cap where it stopped (its message says where) if it cannot reach the hardness.
  if (out.outcome.newton.converged && std::isfinite(cap))
    ehl::lower_cap(problem, lambda, cap, out.u, options, out.outcome);
  else
    problem.set_cap(cap);
  return out;
}

// Smooth (roughness null) or rough.
EhlLineResult solve_line(const EhlLineContact& contact, const EhlRoughness* roughness, const PiezoviscousLubricant& lubricant,
                         const EhlLineOptions& options) {
  validate(contact, roughness, options);
  validate(lubricant);
  const LineProblem problem(contact, roughness, lubricant, options);
  const double radius = contact.reduced_radius_m, b = problem.half_width_m(), ph = problem.hertz_pressure_Pa();
  const double lambda = 12.0 * lubricant.viscosity_Pa_s * contact.mean_speed_m_per_s * radius * radius / (b * b * b * ph);
  const int n = problem.nodes(), np = n - 2;

  EhlLineResult result;
  problem.set_cap(roughness ? roughness->hardness_Pa / ph : std::numeric_limits<double>::infinity());
  ElasticSolve nested = solve_nested(problem, contact, roughness, lubricant, options, lambda);
  Eigen::VectorXd& u = nested.u;
  ehl::SolveOutcome& solved = nested.outcome;
  const ehl::NewtonOutcome& outcome = solved.newton;
  result.iterations = solved.iterations;
  result.continuation_steps = solved.continuation_steps;

  const Eigen::VectorXd p = problem.pressures(u), h = problem.film(u);
  result.x_m.resize(n);
  result.pressure_Pa.resize(n);
  result.film_m.resize(n);
  for (int i = 0; i < n; ++i) {
    result.x_m[i] = problem.x()(i) * b;
    result.pressure_Pa[i] = p(i) * ph;
    result.film_m[i] = h(i) * problem.film_scale_m();
  }
  result.central_film_m = problem.at_centre(h) * problem.film_scale_m();
  result.minimum_film_m = h.minCoeff() * problem.film_scale_m();
  result.max_pressure_Pa = p.maxCoeff() * ph;
  result.hertz_half_width_m = b;
  result.hertz_pressure_Pa = ph;
  result.load_balance_error = (problem.dx() * p.sum() - 0.5 * kPi) / (0.5 * kPi);
  result.converged = outcome.converged;
  result.residual = outcome.residual;
  if (roughness) {
    double carried = 0.0, yielded = 0.0;
    result.in_contact.assign(static_cast<std::size_t>(n), false);
    for (int i = 1; i <= np; ++i) {
      if (in_contact(*roughness, result.film_m[static_cast<std::size_t>(i)]))
        result.in_contact[static_cast<std::size_t>(i)] = true, ++result.contact_nodes, carried += p(i);
      if (problem.yields(u(i - 1))) ++result.plastic_nodes, yielded += p(i);
    }
    result.contact_load_share = problem.dx() * carried / (0.5 * kPi);
    result.plastic_load_share = problem.dx() * yielded / (0.5 * kPi);
  }
  result.message = ehl::outcome_message(outcome, result.iterations);
  return result;
}

}  // namespace

EhlLineResult solve_ehl_line(const EhlLineContact& contact, const PiezoviscousLubricant& lubricant, const EhlLineOptions& options) {
  return solve_line(contact, nullptr, lubricant, options);
}

FittedLineInlet fit_inlet_to_film(const EhlLineContact& contact, const PiezoviscousLubricant& lubricant, const EhlLineOptions& given,
                                  double film_tolerance, double max_inlet) {
  if (!(film_tolerance > 0.0)) throw std::invalid_argument("EHL line inlet: the film tolerance must be positive, got " + shortest(film_tolerance));
  if (!(max_inlet < given.inlet_over_half_width))
    throw std::invalid_argument("EHL line inlet: the limit " + shortest(max_inlet) + " must lie before the given inlet " +
                                shortest(given.inlet_over_half_width));
  constexpr int kMaxNodes = 20001;
  const double spacing = (given.outlet_over_half_width - given.inlet_over_half_width) / (given.nodes - 1);
  FittedLineInlet out;
  out.options = given;
  out.result = solve_ehl_line(contact, lubricant, given);
  out.solves = 1;
  const EhlLineResult on_given = out.result;
  // Unsettled: given's options and its solve (the first) are returned, with why.
  const auto unsettled = [&](const std::string& why) {
    FittedLineInlet kept;
    kept.options = given;
    kept.result = on_given;
    kept.solves = out.solves;
    kept.message = why + "; the given inlet kept";
    return kept;
  };
  EhlLineOptions options = given;
  for (;;) {
    EhlLineOptions longer = options;
    longer.inlet_over_half_width = -1.0 + 1.5 * (options.inlet_over_half_width + 1.0);
    longer.nodes = 1 + static_cast<int>(std::lround((longer.outlet_over_half_width - longer.inlet_over_half_width) / spacing));
    if (longer.inlet_over_half_width < max_inlet || longer.nodes > kMaxNodes)
      return unsettled("the film still moved with the inlet at X = " + shortest(options.inlet_over_half_width) + " (the next, " +
                       shortest(longer.inlet_over_half_width) + " with " + std::to_string(longer.nodes) + " nodes, is past the limit)");
    const EhlLineResult next = solve_ehl_line(contact, lubricant, longer);
    ++out.solves;
    const EhlLineResult& last = out.result;
    // Two solves in a row that do not converge: not the inlet's doing (a film collapsing on too
    // coarse a grid, say), and longer domains would only cost more.
    if (!last.converged && !next.converged)
      return unsettled("the solves at X = " + shortest(options.inlet_over_half_width) + " and " + shortest(longer.inlet_over_half_width) +
                       " did not converge (" + next.message + ")");
    if (last.converged && next.converged &&
        std::abs(next.central_film_m - last.central_film_m) <= film_tolerance * next.central_film_m) {
      out.settled = true;
      out.message = "inlet at X = " + shortest(options.inlet_over_half_width) + ": the central film within " + shortest(film_tolerance) +
                    " of the one at " + shortest(longer.inlet_over_half_width);
      return out;
    }
    options = longer;
    out.options = longer;
    out.result = next;
  }
}

EhlLineResult solve_ehl_line(const EhlLineContact& contact, const EhlRoughness& roughness, const PiezoviscousLubricant& lubricant,
                             const EhlLineOptions& options) {
  return solve_line(contact, &roughness, lubricant, options);
}

}  // namespace tribo::lubrication
