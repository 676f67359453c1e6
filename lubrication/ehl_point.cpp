#include "lubrication/ehl_point.h"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "contact/grid.h"
#include "contact/halfspace.h"
#include "lubrication/ehl_newton.h"
#include "lubrication/linear_solver.h"
#include "lubrication/reference/ehl_point_film.h"
#include "numerics/format.h"
#include "numerics/gmres.h"

namespace tribo::lubrication {
namespace {

using numerics::shortest;

// ∫∫ dS dT / √(S² + T²) over [0, s] × [0, t] and its signed extension: F(s, t) = s asinh(t/|s|) +
// t asinh(s/|t|) (each term 0 where its factor is), so ∂²F/∂s∂t = 1/r.
double inverse_distance_antiderivative(double s, double t) {
  return (s == 0.0 ? 0.0 : s * std::asinh(t / std::abs(s))) + (t == 0.0 ? 0.0 : t * std::asinh(s / std::abs(t)));
}

// The wedge term on rough surfaces: through limited upwind faces (second order where the film is
// smooth: the answer's), or first-order upwind — the start a coarser grid gives a finer one in the
// nested iteration. On the coarse grids of a rough map crawling (17², 33² under a 129² solve) Newton
// stalled with the limited wedge at every λ of the continuation and each finer grid fell back to its
// own continuation (examples/ehl-rough-ball-map.toml 12 s, capped at 0.7 GPa 50 s); with first-order
// starts 2 s and 3 s, the same answer (2026-12-02).
enum class RoughWedge { limited, first_order };

// The discrete problem in Hertz units (header): unknowns P at the interior nodes, then H0.
class PointProblem {
 public:
  PointProblem(const EhlPointContact& c, const EhlRoughness* rough, const PiezoviscousLubricant& l, const EhlPointOptions& o,
               bool dense, RoughWedge wedge)
      : lub_(l), complementarity_(o.complementarity), dense_(dense), wedge_(wedge), krylov_(o.krylov), tolerance_(o.tolerance), nx_(o.nodes_x), ny_(o.nodes_y), dx_((o.outlet_over_radius - o.inlet_over_radius) / (o.nodes_x - 1)),
        dy_(2.0 * o.side_over_radius / (o.nodes_y - 1)), symmetric_(o.symmetric_in_y), first_row_(symmetric_ ? o.nodes_y / 2 : 1) {
    a_ = reference::hertz_point_radius_m(c.load_N, c.reduced_radius_m, c.reduced_modulus_Pa);
    ph_ = reference::hertz_point_peak_pressure_Pa(c.load_N, c.reduced_radius_m, c.reduced_modulus_Pa);
    radius_ = c.reduced_radius_m;
    x_.resize(nx_);
    y_.resize(ny_);
    for (int i = 0; i < nx_; ++i) x_(i) = o.inlet_over_radius + i * dx_;
    for (int j = 0; j < ny_; ++j) y_(j) = -o.side_over_radius + j * dy_;
    // Deformation (2/π²) ∫∫_cell 1/r of P constant on each interior node's cell, a function of the
    // node offsets alone.
    Eigen::MatrixXd offset(nx_, ny_);
    const double hx = 0.5 * dx_, hy = 0.5 * dy_;
    for (int di = 0; di < nx_; ++di)
      for (int dj = 0; dj < ny_; ++dj) {
        const double s = di * dx_, t = dj * dy_;
        offset(di, dj) = 2.0 / (std::numbers::pi * std::numbers::pi) *
                         (inverse_distance_antiderivative(s + hx, t + hy) - inverse_distance_antiderivative(s + hx, t - hy) -
                          inverse_distance_antiderivative(s - hx, t + hy) + inverse_distance_antiderivative(s - hx, t - hy));
      }
    if (dense_) {
      // A node and its mirror image share an unknown: its column holds both cells' deflections.
      kernel_.setZero(nx_ * ny_, interior());
      for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i)
          for (int l = 1; l <= ny_ - 2; ++l)
            for (int k = 1; k <= nx_ - 2; ++k) kernel_(node(i, j), unknown(k, l)) += offset(std::abs(i - k), std::abs(j - l));
    } else {
      // The same operator by FFT: contact/'s non-periodic half-space is Love's cell integral times
      // 1/(π E*), so E* = π/2 gives the (2/π²) ∫∫ 1/r here. The preconditioner keeps its near field.
      halfspace_ = std::make_unique<contact::ElasticHalfSpace>(contact::Grid::patch(nx_, ny_, nx_ * dx_, ny_ * dy_),
                                                               0.5 * std::numbers::pi, false, 1);
      const int reach = o.preconditioner_reach;
      std::vector<Eigen::Triplet<double>> near;
      for (int l = 1; l <= ny_ - 2; ++l)
        for (int k = 1; k <= nx_ - 2; ++k)
          for (int j = std::max(0, l - reach); j <= std::min(ny_ - 1, l + reach); ++j)
            for (int i = std::max(0, k - reach); i <= std::min(nx_ - 1, k + reach); ++i)
              near.emplace_back(node(i, j), unknown(k, l), offset(std::abs(i - k), std::abs(j - l)));  // mirrors summed
      near_kernel_.resize(nx_ * ny_, interior());
      near_kernel_.setFromTriplets(near.begin(), near.end());
    }
    self_ = offset(0, 0);
    rigid_.resize(nx_ * ny_);
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) rigid_(node(i, j)) = 0.5 * (x_(i) * x_(i) + y_(j) * y_(j));
    if (rough) {
      // The surface's heights lower the film (H units).
      for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) rigid_(node(i, j)) -= surface_height_m(*rough, x_(i) * a_, y_(j) * a_) / film_scale_m();
      floor_ = rough->contact_film_m / film_scale_m();
    }
    // The load row ΔXΔY Σ P over every interior node: an unknown counts once more for its mirror.
    load_weights_.resize(interior());
    for (int j = first_row_; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i) load_weights_(unknown(i, j)) = dx_ * dy_ * (symmetric_ && mirror(j) != j ? 2.0 : 1.0);
  }

  // Pressure unknowns: the interior nodes of the rows first_row_ … ny − 2 (all interior rows, or
  // with EhlPointOptions::symmetric_in_y the upper half and the centre row); a row below stands
  // for its mirror image ny − 1 − j.
  int interior() const { return (nx_ - 2) * (ny_ - 1 - first_row_); }
  int unknowns() const { return interior() + 1; }
  int pressure_unknowns() const { return interior(); }
  int node(int i, int j) const { return i + nx_ * j; }
  int mirror(int j) const { return ny_ - 1 - j; }
  int unknown(int i, int j) const { return (i - 1) + (nx_ - 2) * ((j < first_row_ ? mirror(j) : j) - first_row_); }
  bool inside(int i, int j) const { return i >= 1 && i <= nx_ - 2 && j >= 1 && j <= ny_ - 2; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }
  const Eigen::VectorXd& x() const { return x_; }
  const Eigen::VectorXd& y() const { return y_; }
  double radius_m() const { return a_; }
  double hertz_pressure_Pa() const { return ph_; }
  double film_scale_m() const { return a_ * a_ / radius_; }  // h = H a²/R

  // With a pressure cap (EhlRoughness::hardness_Pa, set_cap) an unknown q is the pressure below the
  // cap, P = min(q, P_cap), and above it the surface's plastic flow, the film raised by
  // K_self (q − P_cap) at its node — K_self the deflection of a node's own cell per unit pressure,
  // so that q moves the film alike on both sides. The map is continuous: a node yields and keeps its
  // flow balance (the film its neighbours bring in sets the flow), and Newton's rows stay the same
  // rows. Without a cap q = P.
  Eigen::VectorXd pressures(const Eigen::VectorXd& u) const {
    Eigen::VectorXd p = Eigen::VectorXd::Zero(nx_ * ny_);
    for (int j = 1; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i) p(node(i, j)) = std::min(u(unknown(i, j)), cap_);
    return p;
  }
  void set_cap(double cap) const { cap_ = cap; }
  double cap() const { return cap_; }
  bool yields(double q) const { return q >= cap_; }  // the unknown's pressure at the cap
  // The interior pressures of the unknowns q: min(q, P_cap).
  Eigen::VectorXd capped(const Eigen::VectorXd& interior_q) const { return interior_q.cwiseMin(cap_); }
  // The films' change from the unknowns' interior part v at the branch of u: K (v where u is below
  // the cap) + K_self (v where it yields), at each node.
  Eigen::VectorXd film_from(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const {
    Eigen::VectorXd below = v;
    for (int k = 0; k < interior(); ++k)
      if (yields(u(k))) below(k) = 0.0;
    Eigen::VectorXd out = deflection(below);
    add_plastic_flow([&](int k) { return yields(u(k)); }, [&](int k) { return v(k); }, out);
    return out;
  }
  // K_self · amount(k) added to the film at every node whose unknown k yields (`yielded(k)`; a mirror
  // image too: it shares the unknown).
  template <class Yielded, class Amount>
  void add_plastic_flow(Yielded&& yielded, Amount&& amount, Eigen::VectorXd& film) const {
    for (int j = 1; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i)
        if (const int k = unknown(i, j); yielded(k)) film(node(i, j)) += self_ * amount(k);
  }
  // A nodal field bilinearly interpolated at X = Y = 0.
  double at_centre(const Eigen::VectorXd& v) const {
    const int i = std::clamp(static_cast<int>(std::floor(-x_(0) / dx_)), 0, nx_ - 2);
    const int j = std::clamp(static_cast<int>(std::floor(-y_(0) / dy_)), 0, ny_ - 2);
    const double s = -x_(i) / dx_, t = -y_(j) / dy_;
    return (1 - s) * (1 - t) * v(node(i, j)) + s * (1 - t) * v(node(i + 1, j)) + (1 - s) * t * v(node(i, j + 1)) +
           s * t * v(node(i + 1, j + 1));
  }
  // The elastic part of the film at every node for interior pressures P (the kernel's product).
  Eigen::VectorXd deflection(const Eigen::VectorXd& interior_p) const {
    if (dense_) return kernel_ * interior_p;
    Eigen::ArrayXXd p = Eigen::ArrayXXd::Zero(nx_, ny_), d(nx_, ny_);
    for (int l = 1; l <= ny_ - 2; ++l)
      for (int k = 1; k <= nx_ - 2; ++k) p(k, l) = interior_p(unknown(k, l));
    halfspace_->displacement(p, d);
    return d.reshaped();  // column-major: node (i, j) at i + nx j
  }
  double contact_floor() const { return floor_; }  // H_c, 0 without roughness (smooth surfaces never touch)
  double self_compliance() const { return self_; }  // K_self: a node's own cell's deflection per unit pressure
  bool rough() const { return floor_ > 0.0; }      // (a profile's H_c is positive)
  Eigen::VectorXd film_change(const Eigen::VectorXd& u, const Eigen::VectorXd& du) const {
    return Eigen::VectorXd::Constant(nx_ * ny_, du(interior())) + film_from(u, du.head(interior()));
  }
  Eigen::VectorXd film(const Eigen::VectorXd& u) const {
    Eigen::VectorXd h = (Eigen::VectorXd::Constant(nx_ * ny_, u(interior())) + rigid_) + deflection(capped(u.head(interior())));
    add_plastic_flow([&](int k) { return yields(u(k)); }, [&](int k) { return u(k) - cap_; }, h);
    return h;
  }

  struct Nodal {
    Eigen::VectorXd p, h, rho, drho, eps, dlog_eps, w, mobile, coef;  // ε = coef · mobile³
    std::vector<bool> yielded;  // by unknown: q at or above the cap
  };
  Nodal nodal(const Eigen::VectorXd& u, double lambda) const {
    const int n = nx_ * ny_;
    Nodal s{pressures(u),       film(u),            Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n),
            Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n), std::vector<bool>(interior())};
    for (int k = 0; k < interior(); ++k) s.yielded[static_cast<std::size_t>(k)] = yields(u(k));
    for (int k = 0; k < n; ++k) {
      const ViscosityAtPressure v = viscosity_ratio(lub_, s.p(k) * ph_);
      const DensityAtPressure r = density_ratio(lub_, s.p(k) * ph_);
      s.rho(k) = r.ratio;
      s.drho(k) = r.slope_per_Pa * ph_;
      // The pressure flow passes through the film above the boundary layers (all of it on smooth
      // surfaces): none where the film has closed to H_c — Hu & Zhu's reduced equation there.
      s.mobile(k) = std::max(s.h(k) - floor_, 0.0);
      s.coef(k) = s.rho(k) / (v.ratio * lambda);
      s.eps(k) = s.coef(k) * std::pow(s.mobile(k), 3);
      s.dlog_eps(k) = s.drho(k) / s.rho(k) - v.log_slope_per_Pa * ph_;  // ∂ ln ε/∂P at fixed H
      s.w(k) = s.rho(k) * s.h(k);
    }
    return s;
  }

  // Row scales c = 1/|∂R/∂P| of the diagonal (Poiseuille and the deformation's wedge part), as
  // the line contact's: c R reads as a pressure in the thick inlet and the stiff Hertz zone alike.
  Eigen::VectorXd row_scales(const Nodal& s) const {
    Eigen::VectorXd c(interior());
    for (int j = first_row_; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i) {
        const auto e = [&](int ii, int jj) { return s.eps(node(ii, jj)); };
        const double xx = 0.5 * (e(i - 1, j) + 2.0 * e(i, j) + e(i + 1, j)) / (dx_ * dx_);
        const double yy = 0.5 * (e(i, j - 1) + 2.0 * e(i, j) + e(i, j + 1)) / (dy_ * dy_);
        c(unknown(i, j)) = 1.0 / (xx + yy + wedge_diagonal() * s.rho(node(i, j)) * self_ / dx_);
      }
    return c;
  }

  // The Newton matrix J = [S + D K, b; ΔXΔY 1ᵀ, 0]: S the stencil's direct dependence on the
  // pressures, D (≤ 5 coefficients a row) that on the films at the stencil's nodes, K the elastic
  // kernel, b the H0 column. Dense: assembled (D K as one sparse × dense product, which reads K
  // column by column; adding scaled rows of the column-major K strode through memory and took half
  // of a solve). Krylov: applied, with K by FFT.
  struct Jacobian {
    Eigen::MatrixXd dense;
    Eigen::SparseMatrix<double, Eigen::RowMajor> stencil, through_film;
    Eigen::VectorXd h0_column;
    std::vector<bool> yielded;  // Nodal::yielded: the columns that move the film by K_self, not P
    Eigen::VectorXd load_row;   // ∂(ΔXΔY ΣP)/∂q: the load weights, 0 where yielded
  };

  static bool any_yielded(const std::vector<bool>& yielded) { return std::any_of(yielded.begin(), yielded.end(), [](bool y) { return y; }); }
  // ∂H/∂q of the film at every node by unknown, where some unknown yields (any_yielded; else K
  // itself, not copied): K's columns where the unknown is below the cap, K_self at the unknown's node
  // (and its mirror image) where it yields — the same pattern as K (whose entries include every
  // node's own cell).
  template <class Kernel>
  Kernel yielding_kernel(const Kernel& kernel, const std::vector<bool>& yielded) const {
    Kernel out = kernel;
    if constexpr (std::is_same_v<Kernel, Eigen::MatrixXd>) {
      for (int k = 0; k < interior(); ++k)
        if (yielded[static_cast<std::size_t>(k)]) out.col(k).setZero();
    } else {
      for (int k = 0; k < out.outerSize(); ++k)
        for (typename Kernel::InnerIterator it(out, k); it; ++it)
          if (yielded[static_cast<std::size_t>(it.col())]) it.valueRef() = 0.0;
    }
    for (int j = 1; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i)
        if (const int k = unknown(i, j); yielded[static_cast<std::size_t>(k)]) out.coeffRef(node(i, j), k) += self_;
    return out;
  }

  Eigen::VectorXd residual(const Nodal& s, const Eigen::VectorXd& c, Jacobian* jacobian) const {
    const int np = interior();
    Eigen::VectorXd f(np + 1);
    std::vector<Eigen::Triplet<double>> through_film, stencil;
    if (jacobian) {
      jacobian->h0_column.setZero(np);
      through_film.reserve(static_cast<std::size_t>(5 * np));
      stencil.reserve(static_cast<std::size_t>(11 * np));
    }
    for (int j = first_row_; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i) {
        const int row = unknown(i, j), here = node(i, j);
        const int east = node(i + 1, j), west = node(i - 1, j), north = node(i, j + 1), south = node(i, j - 1);
        const auto m3 = [&](int k) { return std::pow(s.mobile(k), 3); };
        const auto face = [&](int a, int b) { return face_flow(s.coef(a), m3(a), s.coef(b), m3(b), rough()); };
        // Each face from its lower node to its upper (a → b along x or y).
        const FaceFlow fpx = face(here, east), fmx = face(west, here), fpy = face(here, north), fmy = face(south, here);
        const double epx = fpx.value, emx = fmx.value, epy = fpy.value, emy = fmy.value;
        const double gpx = s.p(east) - s.p(here), gmx = s.p(here) - s.p(west);
        const double gpy = s.p(north) - s.p(here), gmy = s.p(here) - s.p(south);
        const double poiseuille = (epx * gpx - emx * gmx) / (dx_ * dx_) + (epy * gpy - emy * gmy) / (dy_ * dy_);
        // The wedge d(ρ̄H)/dX: second-order upwind on smooth surfaces; with roughness, where films
        // close, through the limited upwind faces, cw its weights on w_{i−2} … w_{i+1}
        // (ehl_roughness.h limited_mass_face: the unlimited scheme, extrapolated from a converging
        // inlet over two nodes, would drive a contact's film through zero). First order at i = 1.
        double wedge;
        std::array<double, 4> cw{};  // ∂wedge/∂w_k, k = i − 2 … i + 1
        if (rough() && wedge_ == RoughWedge::first_order) {
          wedge = (s.w(here) - s.w(west)) / dx_;
          cw = {0.0, -1.0 / dx_, 1.0 / dx_, 0.0};
        } else if (rough()) {
          const MassFace fo = limited_mass_face(s.w(west), s.w(here), s.w(east));
          const MassFace fi = i >= 2 ? limited_mass_face(s.w(node(i - 2, j)), s.w(west), s.w(here)) : MassFace{s.w(west), 0.0, 1.0, 0.0};
          wedge = (fo.value - fi.value) / dx_;
          cw = {-fi.d_prev / dx_, (fo.d_prev - fi.d_here) / dx_, (fo.d_here - fi.d_next) / dx_, fo.d_next / dx_};
        } else if (i >= 2) {
          wedge = (3.0 * s.w(here) - 4.0 * s.w(west) + s.w(node(i - 2, j))) / (2.0 * dx_);
          const double wx = 1.0 / (2.0 * dx_);
          cw = {wx, -4.0 * wx, 3.0 * wx, 0.0};
        } else {
          wedge = (s.w(here) - s.w(west)) / dx_;
          cw = {0.0, -1.0 / dx_, 1.0 / dx_, 0.0};
        }
        const double scale = c(row);
        const double r = -scale * (poiseuille - wedge);
        // Cavitation: P ≥ 0, −c R ≥ 0, P R = 0 as φ(P, −c R) = 0 (complementarity.h).
        const Ncp phi = ncp(complementarity_, s.p(here), r);
        f(row) = phi.value;
        if (!jacobian) continue;
        const double da = phi.da, db = phi.db;
        // ∂(poiseuille − wedge)/∂u: through the faces' ε (by each node's c and m³: ∂c_k/∂P_q = δ_kq c_k
        // ∂ln ε_k/∂P_k, ∂m³_k/∂P_q = 3 m_k² K_kq with m = H − H_c, 0 where closed) and ρ̄H at the
        // stencil's nodes (∂(ρ̄H)_k/∂P_q = ρ̄_k K_kq + δ_kq ρ̄'_k H_k; K a dense row of the kernel), and
        // through the pressures of the five-point stencil.
        struct Term {
          int i, j;
          double through_c, through_m3, through_mass;  // coefficients of ∂c_k, ∂m³_k and −∂(ρ̄H)_k
        };
        const double ix2 = 1.0 / (dx_ * dx_), iy2 = 1.0 / (dy_ * dy_);
        Term terms[7] = {{i, j, (fpx.dc_a * gpx - fmx.dc_b * gmx) * ix2 + (fpy.dc_a * gpy - fmy.dc_b * gmy) * iy2,
                          (fpx.dm3_a * gpx - fmx.dm3_b * gmx) * ix2 + (fpy.dm3_a * gpy - fmy.dm3_b * gmy) * iy2,
                          cw[2]},
                         {i + 1, j, fpx.dc_b * gpx * ix2, fpx.dm3_b * gpx * ix2, cw[3]},
                         {i - 1, j, -fmx.dc_a * gmx * ix2, -fmx.dm3_a * gmx * ix2, cw[1]},
                         {i, j + 1, fpy.dc_b * gpy * iy2, fpy.dm3_b * gpy * iy2, 0.0},
                         {i, j - 1, -fmy.dc_a * gmy * iy2, -fmy.dm3_a * gmy * iy2, 0.0},
                         {i - 2, j, 0.0, 0.0, cw[0]},
                         {-1, -1, 0.0, 0.0, 0.0}};
        double d_h0 = 0.0;
        for (const Term& t : terms) {
          if (t.i < 0) continue;  // zero coefficients stay: a fixed pattern lets the Krylov preconditioner keep its analysis
          const int k = node(t.i, t.j);
          const double dh = t.through_m3 * 3.0 * s.mobile(k) * s.mobile(k) - t.through_mass * s.rho(k);  // per unit ∂H_k
          through_film.emplace_back(row, k, -scale * db * dh);
          d_h0 += dh;
          if (inside(t.i, t.j))
            stencil.emplace_back(row, unknown(t.i, t.j),
                                 -scale * db * (t.through_c * s.coef(k) * s.dlog_eps(k) - t.through_mass * s.drho(k) * s.h(k)));
        }
        // The pressures of the stencil.
        const auto pressure_term = [&](int ii, int jj, double coefficient) {
          if (inside(ii, jj)) stencil.emplace_back(row, unknown(ii, jj), -scale * db * coefficient);
        };
        pressure_term(i + 1, j, epx / (dx_ * dx_));
        pressure_term(i - 1, j, emx / (dx_ * dx_));
        pressure_term(i, j + 1, epy / (dy_ * dy_));
        pressure_term(i, j - 1, emy / (dy_ * dy_));
        pressure_term(i, j, -(epx + emx) / (dx_ * dx_) - (epy + emy) / (dy_ * dy_));
        stencil.emplace_back(row, row, da);
        jacobian->h0_column(row) = -scale * db * d_h0;
      }
    if (jacobian) {
      jacobian->stencil.resize(np, np);
      jacobian->stencil.setFromTriplets(stencil.begin(), stencil.end());
      // The stencil's entries are ∂/∂P: none for a yielded unknown (its pressure is the cap). Kept
      // as zeros: the Krylov preconditioner's analysis holds for one pattern.
      jacobian->yielded = s.yielded;
      jacobian->load_row = load_weights_;
      for (int k = 0; k < np; ++k)
        if (s.yielded[static_cast<std::size_t>(k)]) jacobian->load_row(k) = 0.0;
      for (int r = 0; r < np; ++r)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(jacobian->stencil, r); it; ++it)
          if (s.yielded[static_cast<std::size_t>(it.col())]) it.valueRef() = 0.0;
      jacobian->through_film.resize(np, nx_ * ny_);
      jacobian->through_film.setFromTriplets(through_film.begin(), through_film.end());
    }
    // Load balance: ΔX ΔY Σ P = 2π/3 (P = 0 on the boundary).
    const double cell = dx_ * dy_;
    double sum = 0.0;
    for (int j = 1; j <= ny_ - 2; ++j)
      for (int i = 1; i <= nx_ - 2; ++i) sum += s.p(node(i, j));
    f(np) = cell * sum - 2.0 * std::numbers::pi / 3.0;
    if (jacobian && dense_) {
      Eigen::MatrixXd& m = jacobian->dense;
      m.setZero(np + 1, np + 1);
      m.topLeftCorner(np, np) = jacobian->stencil;
      if (any_yielded(s.yielded))
        m.topLeftCorner(np, np).noalias() += jacobian->through_film * yielding_kernel(kernel_, s.yielded);
      else
        m.topLeftCorner(np, np).noalias() += jacobian->through_film * kernel_;
      m.col(np).head(np) = jacobian->h0_column;
      m.row(np).head(np) = jacobian->load_row.transpose();
    }
    return f;
  }

  bool solve_step(Jacobian& jac, const Eigen::VectorXd& rhs, Eigen::VectorXd& step, std::string& why) const {
    if (dense_) return ehl::dense_step(jac.dense, rhs, step, why);
    return krylov_step(jac, rhs, step, why);
  }

  // Newton–Krylov: starts the symbolic analysis (METIS ordering, UMFPACK's symbolic LU) of the
  // preconditioner on another thread, from the Jacobian at u — its pattern is the same at every
  // step — so that it runs while the caller solves the coarser grid that starts this one (0.6 s of
  // a 257² solve's 2.7, 2026-11-30: off its critical path on two cores). The Jacobian is formed
  // here: the thread touches nothing of this problem (the half-space's FFT buffers are shared).
  void start_analysis(const Eigen::VectorXd& u, double lambda) const {
    if (dense_) return;
    Jacobian jac;
    const Nodal s = nodal(u, lambda);
    residual(s, row_scales(s), &jac);
    analysis_ = std::async(std::launch::async, [local = local_matrix(jac)]() {
      Analysis a;
      a.solver = preconditioner_lu();
      a.status = a.solver->analyze(local);
      a.nonzeros = local.nonZeros();
      return a;
    });
  }

 private:
  // The preconditioner's LU: UMFPACK without iterative refinement, whose inexactness GMRES absorbs.
  static std::unique_ptr<SparseLinearSolver> preconditioner_lu() {
    return make_linear_solver(LinearSolverKind::umfpack, {}, DirectSolveOptions{0});
  }
  // A = S + D K_near of the preconditioner (krylov_step), compressed as UMFPACK reads it.
  SparseMatrix local_matrix(const Jacobian& jac) const {
    Eigen::SparseMatrix<double, Eigen::RowMajor> local =
        any_yielded(jac.yielded) ? jac.through_film * yielding_kernel(near_kernel_, jac.yielded) : jac.through_film * near_kernel_;
    local += jac.stencil;
    return SparseMatrix(local);
  }

  // GMRES on J applied (K by FFT), right-preconditioned by the sparse LU (UMFPACK) of J with K
  // cut to its near field.
  bool krylov_step(Jacobian& jac, const Eigen::VectorXd& rhs, Eigen::VectorXd& step, std::string& why) const;

  PiezoviscousLubricant lub_;
  Complementarity complementarity_;
  bool dense_;
  RoughWedge wedge_;
  EhlPointKrylovOptions krylov_;
  double tolerance_;  // Newton's, on ‖F‖∞
  int nx_, ny_;
  double dx_, dy_, a_ = 0.0, ph_ = 0.0, radius_ = 0.0, self_ = 0.0;
  bool symmetric_;  // EhlPointOptions::symmetric_in_y
  int first_row_;   // the lowest row of unknowns (interior())
  Eigen::VectorXd x_, y_, load_weights_;
  Eigen::VectorXd rigid_;  // the film at H0 = 0 without deformation: the ball's crown less the ridges
  double floor_ = 0.0;     // the boundary layers' H_c (0 for smooth surfaces)
  mutable double cap_ = std::numeric_limits<double>::infinity();  // the pressure cap / p_H (set_cap)
  Eigen::MatrixXd kernel_;  // all nodes × interior nodes (dense method)
  Eigen::SparseMatrix<double, Eigen::RowMajor> near_kernel_;  // its entries within the reach (Krylov)
  std::unique_ptr<contact::ElasticHalfSpace> halfspace_;  // K by FFT (Krylov); its buffers make products non-const
  mutable int krylov_iterations_ = 0;
  // The upwind wedge's weight on its own node: 3/2 second order, 1 first or limited (with roughness).
  double wedge_diagonal() const { return rough() ? 1.0 : 1.5; }
  // The Krylov preconditioner: its matrix (UMFPACK's solve reads it), factors and their state.
  mutable SparseMatrix factored_;
  mutable Eigen::VectorXd border_;  // A⁻¹ b: the film constant's column through the factors
  mutable double schur_ = 0.0;      // wᵀA⁻¹b: the load row's Schur complement (up to sign)
  mutable std::unique_ptr<SparseLinearSolver> lu_;
  struct Analysis {
    std::unique_ptr<SparseLinearSolver> solver;
    LinearSolveStatus status;
    Eigen::Index nonzeros = 0;
  };
  mutable std::future<Analysis> analysis_;  // start_analysis()
  mutable Eigen::Index analysed_nonzeros_ = 0;
  mutable bool stale_ = true;
  mutable int fresh_iterations_ = 0, factorisations_ = 0;
  mutable double previous_norm_ = 0.0;  // ‖F‖₂ at the last step, for the forcing term

 public:
  int krylov_iterations() const { return krylov_iterations_; }
  int factorisations() const { return factorisations_; }
};

bool PointProblem::krylov_step(Jacobian& jac, const Eigen::VectorXd& rhs, Eigen::VectorXd& step, std::string& why) const {
  const int np = interior();
  // The preconditioner: [A, b; wᵀ, 0] (w the load row's weights) with A = S + D K_near at this step, solved by the LU of
  // A alone (the load row and the H0 column are dense: in the LU they made UMFPACK's symbolic
  // analysis of 257² take 1 s) and the border by its scalar Schur complement, A⁻¹ b kept with
  // the factors. A's pattern is the same at every step (residual() keeps zero coefficients), so the
  // analysis runs once per grid.
  const auto factorise = [&]() {
    stale_ = true;  // until a factorisation succeeds
    factored_ = local_matrix(jac);
    if (analysis_.valid()) {  // the analysis started while the coarser grid was solved
      Analysis early = analysis_.get();
      if (early.status.ok && early.nonzeros == factored_.nonZeros()) lu_ = std::move(early.solver), analysed_nonzeros_ = early.nonzeros;
    }
    if (!lu_ || !lu_->analyzed() || factored_.nonZeros() != analysed_nonzeros_) {
      lu_ = preconditioner_lu();
      if (const LinearSolveStatus status = lu_->analyze(factored_); !status.ok) {
        why = "the preconditioner's analysis failed: " + status.message;
        return false;
      }
      analysed_nonzeros_ = factored_.nonZeros();
    }
    if (const LinearSolveStatus status = lu_->factorize(factored_); !status.ok) {
      why = "the preconditioner's factorisation failed: " + status.message;
      return false;
    }
    if (const LinearSolveStatus status = lu_->solve(jac.h0_column, border_); !status.ok) {
      why = "the preconditioner's solve failed: " + status.message;
      return false;
    }
    schur_ = jac.load_row.dot(border_);
    if (!std::isfinite(schur_) || schur_ == 0.0) {
      why = "the preconditioner is singular: the load does not depend on the film constant through it";
      return false;
    }
    ++factorisations_;
    return true;
  };
  std::string failure;
  const numerics::LinearMap apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    Eigen::VectorXd below = v.head(np);
    for (int k = 0; k < np; ++k)
      if (jac.yielded[static_cast<std::size_t>(k)]) below(k) = 0.0;
    Eigen::VectorXd film = deflection(below);
    add_plastic_flow([&](int k) { return jac.yielded[static_cast<std::size_t>(k)]; }, [&](int k) { return v(k); }, film);
    y.resize(np + 1);
    y.head(np) = jac.stencil * v.head(np) + jac.through_film * film + jac.h0_column * v(np);
    y(np) = jac.load_row.dot(v.head(np));
    return true;
  };
  // z = M⁻¹ r: A z_p + b z_H0 = r_p and wᵀz_p = r_H0, so z_H0 = (wᵀA⁻¹r_p − r_H0) / (wᵀA⁻¹b).
  const numerics::LinearMap precondition = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    Eigen::VectorXd y;
    const LinearSolveStatus status = lu_->solve(r.head(np), y);
    if (!status.ok) {
      failure = status.message;
      return false;
    }
    z.resize(np + 1);
    z(np) = (jac.load_row.dot(y) - r(np)) / schur_;
    z.head(np) = y - border_ * z(np);
    return true;
  };
  // Inexact Newton (Eisenstat & Walker 1996, choice 2): solve no more exactly than Newton's progress
  // can use — η = 0.9 (‖F_k‖/‖F_{k−1}‖)², at most 1e-2, at least the configured tolerance — nor
  // than the answer needs: a linear residual of a tenth of Newton's tolerance ends the solve.
  const double norm = rhs.norm();
  const double forcing = previous_norm_ > 0.0 ? 0.9 * std::pow(norm / previous_norm_, 2) : 1e-2;
  previous_norm_ = norm;
  numerics::GmresOptions g;
  g.relative_tolerance = std::clamp(std::max(forcing, 0.1 * tolerance_ / norm), std::min(krylov_.relative_tolerance, 1e-2), 1e-2);
  g.krylov_dimension = krylov_.krylov_dimension;
  g.max_restarts = krylov_.max_restarts;
  // A factorisation serves later steps while GMRES needs at most twice (+ 5) the iterations it
  // needed when fresh: the Jacobian changes little between Newton steps near the answer, and the
  // LU is most of a step. A stale one that does not converge is refreshed and the solve repeated.
  bool fresh = false;
  if (stale_) {
    if (!factorise()) return false;
    fresh = true;
  }
  numerics::GmresSummary summary = numerics::gmres(apply, precondition, rhs, step, g);
  krylov_iterations_ += summary.iterations;
  if (!summary.converged && !fresh) {
    if (!factorise()) return false;
    fresh = true;
    summary = numerics::gmres(apply, precondition, rhs, step, g);
    krylov_iterations_ += summary.iterations;
  }
  if (fresh) fresh_iterations_ = summary.iterations;
  stale_ = summary.iterations > 2 * fresh_iterations_ + 5;
  if (summary.converged) return true;
  stale_ = true;
  why = "GMRES did not solve the Newton system: " + summary.message + (failure.empty() ? "" : " (" + failure + ")");
  return false;
}

// A coarser solve's nodal field (its pressure, or its plastic flow) at (x, y) (m) by Catmull–Rom
// cubics in x and y (bilinear left a fine grid's start 25 % further from its answer: 0.084 against
// 0.068 in ‖F‖∞ on 257² at 10 N, 85 GMRES iterations against 73), not below 0; 0 outside its domain.
double interpolate(const EhlPointResult& c, const std::vector<double>& field, double x, double y) {
  const int nx = static_cast<int>(c.x_m.size()), ny = static_cast<int>(c.y_m.size());
  const double dx = c.x_m[1] - c.x_m[0], dy = c.y_m[1] - c.y_m[0];
  const double fi = (x - c.x_m[0]) / dx, fj = (y - c.y_m[0]) / dy;
  if (fi < 0.0 || fj < 0.0 || fi > nx - 1 || fj > ny - 1) return 0.0;
  const int i = std::min(static_cast<int>(fi), nx - 2), j = std::min(static_cast<int>(fj), ny - 2);
  const auto weights = [](double u) {
    return std::array<double, 4>{0.5 * u * (-1.0 + u * (2.0 - u)), 0.5 * (2.0 + u * u * (-5.0 + 3.0 * u)),
                                 0.5 * u * (1.0 + u * (4.0 - 3.0 * u)), 0.5 * u * u * (u - 1.0)};
  };
  const std::array<double, 4> wx = weights(fi - i), wy = weights(fj - j);
  double v = 0.0;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const int ii = std::clamp(i - 1 + a, 0, nx - 1), jj = std::clamp(j - 1 + b, 0, ny - 1);
      v += wx[a] * wy[b] * field[static_cast<std::size_t>(ii + nx * jj)];
    }
  return std::max(0.0, v);
}

// automatic: the dense LU up to 21 × 21 nodes, Newton–Krylov beyond (ehl_point.h).
constexpr int kLargestDenseSystem = 19 * 19;

void validate(const EhlPointContact& c, const EhlRoughness* rough, const EhlPointOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument(std::string("EHL point contact: ") + name + " must be positive and finite, got " + shortest(v));
  };
  positive(c.load_N, "load_N");
  positive(c.reduced_radius_m, "reduced_radius_m");
  positive(c.reduced_modulus_Pa, "reduced_modulus_Pa");
  positive(c.mean_speed_m_per_s, "mean_speed_m_per_s");
  if (!(o.inlet_over_radius < -1.0) || !(o.outlet_over_radius > 0.0) || !(o.side_over_radius > 1.0) ||
      !std::isfinite(o.inlet_over_radius) || !std::isfinite(o.outlet_over_radius) || !std::isfinite(o.side_over_radius))
    throw std::invalid_argument("EHL point contact: the domain [" + shortest(o.inlet_over_radius) + ", " +
                                shortest(o.outlet_over_radius) + "] × ±" + shortest(o.side_over_radius) +
                                " (in Hertz radii) must start before −1, end after 0 and reach past ±1 sideways");
  if (o.nodes_x < 11 || o.nodes_y < 11)
    throw std::invalid_argument("EHL point contact: nodes must be ≥ 11 a side, got " + std::to_string(o.nodes_x) + " × " +
                                std::to_string(o.nodes_y));
  if (!(o.tolerance > 0.0)) throw std::invalid_argument("EHL point contact: tolerance must be positive, got " + shortest(o.tolerance));
  if (o.preconditioner_reach < 0 || o.preconditioner_reach > 16)
    throw std::invalid_argument("EHL point contact: preconditioner_reach must be 0–16 nodes, got " + std::to_string(o.preconditioner_reach));
  if (!(o.krylov.relative_tolerance > 0.0 && o.krylov.relative_tolerance < 1.0) || o.krylov.krylov_dimension < 1 || o.krylov.max_restarts < 0)
    throw std::invalid_argument("EHL point contact: the Krylov tolerance must lie in (0, 1), the dimension ≥ 1, the restarts ≥ 0");
  if (rough) validate(*rough, "EHL point contact");
}

// Smooth (roughness null) or rough.
EhlPointResult solve_point(const EhlPointContact& contact, const EhlRoughness* roughness, const PiezoviscousLubricant& lubricant,
                           const EhlPointOptions& given, RoughWedge wedge = RoughWedge::limited) {
  validate(contact, roughness, given);
  EhlPointOptions options = given;
  if (roughness && roughness->map) options.symmetric_in_y = false;  // a map is not symmetric across the track
  validate(lubricant);
  const int interior = (options.nodes_x - 2) * (options.nodes_y - 2);
  const bool dense = options.linear_solver == EhlPointLinearSolver::dense_lu ||
                     (options.linear_solver == EhlPointLinearSolver::automatic && interior <= kLargestDenseSystem);
  const PointProblem problem(contact, roughness, lubricant, options, dense, wedge);
  const double radius = contact.reduced_radius_m, a = problem.radius_m(), ph = problem.hertz_pressure_Pa();
  const double lambda = 12.0 * lubricant.viscosity_Pa_s * contact.mean_speed_m_per_s * radius * radius / (a * a * a * ph);

  // Start: the Hertz semi-ellipsoid, widened over the rigid film's pressure zone √(2 R h) when that
  // is the larger (a light, hydrodynamic contact), and H0 placing the central film at Hamrock and
  // Dowson's estimate (with G at least 1000, so an isoviscous lubricant starts from a film too).
  reference::PointContactGroups g = reference::point_contact_groups(contact.load_N, radius, contact.reduced_modulus_Pa,
                                                                    contact.mean_speed_m_per_s, lubricant.viscosity_Pa_s,
                                                                    lubricant.pressure_viscosity_per_Pa);
  g.material = std::max(g.material, 1000.0);
  const double h_start_m = reference::hamrock_dowson_central_film(g) * radius;
  const double spread = std::max(1.0, std::sqrt(2.0 * radius * h_start_m) / a);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.unknowns());
  for (int j = 1; j <= problem.ny() - 2; ++j)
    for (int i = 1; i <= problem.nx() - 2; ++i) {
      const double r2 = (problem.x()(i) * problem.x()(i) + problem.y()(j) * problem.y()(j)) / (spread * spread);
      u(problem.unknown(i, j)) = std::sqrt(std::max(0.0, 1.0 - r2)) / (spread * spread);
    }
  const int np = problem.pressure_unknowns();
  // H0 for the pressures in u: the central film at `central_m`, and where the pressures' deflection
  // would close the film somewhere (to the boundary layers, with roughness), raised until its
  // lowest node is `lowest_m` above them.
  const double floor = problem.contact_floor();
  const auto place_film = [&](double central_m, double lowest_m) {
    u(np) = 0.0;
    u(np) = central_m / problem.film_scale_m() - problem.at_centre(problem.film(u));
    if (const double lowest = problem.film(u).minCoeff(); lowest <= floor)
      u(np) += floor + lowest_m / problem.film_scale_m() - lowest;
  };
  place_film(h_start_m, 0.5 * h_start_m);
  // Nested iteration (EhlPointOptions::start_from_coarser_grid).
  EhlPointOptions coarser = options;
  coarser.nodes_x = std::max(11, (options.nodes_x + 1) / 2);
  coarser.nodes_y = std::max(11, (options.nodes_y + 1) / 2);
  coarser.linear_solver = EhlPointLinearSolver::automatic;  // the dense LU once the grid is small
  coarser.tolerance = std::max(options.tolerance, 1e-4);     // a start (header): its grid's error is larger
  // A coarse grid that cannot hold the contact (high M: no film-positive solution past a fold in λ)
  // would spend the whole continuation finding that out; the Hertz start on this grid is then cheaper.
  coarser.max_continuation_steps = std::min(options.max_continuation_steps, 4);
  const bool nested = !dense && options.start_from_coarser_grid && coarser.nodes_x * coarser.nodes_y < options.nodes_x * options.nodes_y;
  if (nested) problem.start_analysis(u, lambda);
  // The coarser grid's answer (with `rough` as the surface) interpolated into u; inside its yielded
  // zone (the pressure interpolated at the cap, to rounding: the cubics' weights sum to 1) the
  // unknown carries its plastic flow on this grid, q = P_cap + flow / K_self. Where the flow alone
  // reaches past that zone (its interpolation spreads a node further) the node starts elastic:
  // started yielded, an edge node's flow row can vanish while the residual is large (the minimum
  // picks the capped pressure), and the Newton matrix with it (the crawling ball of
  // tests/lubrication/ehl_point_mixed_test.cpp on 31² and 61²: singular at the first step; without
  // the flow at all, 29 and > 30 Newton steps against 11 and 20 with it). False, u kept, where the
  // coarser solve did not converge.
  const auto start_from_coarser = [&](const EhlRoughness* rough) {
    const EhlPointResult c = solve_point(contact, rough, lubricant, coarser, RoughWedge::first_order);
    if (!c.converged) return false;
    const bool flowed = rough && c.plastic_nodes > 0;
    const double cap = rough ? rough->hardness_Pa / ph : std::numeric_limits<double>::infinity();
    const double per_flow = 1.0 / (problem.self_compliance() * problem.film_scale_m());
    problem.set_cap(cap);  // the film placed below reads the plastic flow off the unknowns
    for (int j = 1; j <= problem.ny() - 2; ++j)
      for (int i = 1; i <= problem.nx() - 2; ++i) {
        const double x = problem.x()(i) * a, y = problem.y()(j) * a;
        double& q = u(problem.unknown(i, j));
        q = interpolate(c, c.pressure_Pa, x, y) / ph;
        if (const double flow = flowed ? interpolate(c, c.plastic_flow_m, x, y) : 0.0; flow > 0.0 && q >= cap * (1.0 - 1e-12))
          q = cap + flow * per_flow;
      }
    place_film(c.central_film_m, c.minimum_film_m);
    return true;
  };
  const Eigen::VectorXd hertz_start = u;
  ehl::SolveOutcome solved;
  // With a hardness the cap is lowered onto an elastic answer (ehl::lower_cap) on the coarsest grid
  // alone: a finer grid starts from its coarser grid's capped answer and Newton takes it there with
  // the cap set, as the elastic nesting does (the rough map example at 0.7 GPa: 44 s, 297 Newton
  // and 60 cap steps on 129² → 4.8 s, 17 and none, the same answer). Where the coarser capped solve
  // or this Newton does not converge (a coarse grid that cannot hold a cap far below p_H), the
  // coarser grid's elastic answer and the cap lowered on this grid, as before 2026-12-02, the Newton
  // steps of the attempt counted too.
  const bool capped = roughness && std::isfinite(roughness->hardness_Pa);
  if (nested && capped && start_from_coarser(roughness)) {
    solved.newton = ehl::newton(problem, lambda, u, options);
    solved.iterations = solved.newton.iterations;
    if (!solved.newton.converged) problem.set_cap(std::numeric_limits<double>::infinity()), u = hertz_start;
  }
  if (!solved.newton.converged) {
    std::optional<EhlRoughness> elastic;
    if (roughness) elastic = *roughness, elastic->hardness_Pa = std::numeric_limits<double>::infinity();
    if (nested) start_from_coarser(elastic ? &*elastic : nullptr);
    const int tried = solved.iterations;
    const Eigen::VectorXd start = u;
    solved = ehl::solve_with_continuation(problem, lambda, start, u, options);
    solved.iterations += tried;
    if (solved.newton.converged && capped) ehl::lower_cap(problem, lambda, roughness->hardness_Pa / ph, u, options, solved);
  }

  EhlPointResult result;
  const Eigen::VectorXd p = problem.pressures(u), h = problem.film(u);
  for (int i = 0; i < problem.nx(); ++i) result.x_m.push_back(problem.x()(i) * a);
  for (int j = 0; j < problem.ny(); ++j) result.y_m.push_back(problem.y()(j) * a);
  result.pressure_Pa.resize(p.size());
  result.film_m.resize(h.size());
  for (Eigen::Index k = 0; k < p.size(); ++k) {
    result.pressure_Pa[static_cast<std::size_t>(k)] = p(k) * ph;
    result.film_m[static_cast<std::size_t>(k)] = h(k) * problem.film_scale_m();
  }
  result.central_film_m = problem.at_centre(h) * problem.film_scale_m();
  result.minimum_film_m = h.minCoeff() * problem.film_scale_m();
  result.max_pressure_Pa = p.maxCoeff() * ph;
  result.hertz_radius_m = a;
  result.hertz_pressure_Pa = ph;
  result.load_balance_error = (problem.dx() * problem.dy() * p.sum() - 2.0 * std::numbers::pi / 3.0) / (2.0 * std::numbers::pi / 3.0);
  result.converged = solved.newton.converged;
  result.iterations = solved.iterations;
  result.continuation_steps = solved.continuation_steps;
  result.residual = solved.newton.residual;
  result.linear_solver = dense ? "dense LU" : "GMRES, sparse LU preconditioner";
  result.krylov_iterations = problem.krylov_iterations();
  result.preconditioner_factorisations = problem.factorisations();
  if (roughness) {
    double carried = 0.0, yielded = 0.0;
    result.in_contact.assign(static_cast<std::size_t>(h.size()), false);
    result.plastic_flow_m.assign(static_cast<std::size_t>(h.size()), 0.0);
    for (int j = 1; j <= problem.ny() - 2; ++j)
      for (int i = 1; i <= problem.nx() - 2; ++i) {
        const int k = problem.node(i, j);
        if (in_contact(*roughness, result.film_m[static_cast<std::size_t>(k)]))
          result.in_contact[static_cast<std::size_t>(k)] = true, ++result.contact_nodes, carried += p(k);
        if (const double q = u(problem.unknown(i, j)); problem.yields(q)) {
          ++result.plastic_nodes, yielded += p(k);
          result.plastic_flow_m[static_cast<std::size_t>(k)] = problem.self_compliance() * (q - problem.cap()) * problem.film_scale_m();
        }
      }
    const double share = problem.dx() * problem.dy() / (2.0 * std::numbers::pi / 3.0);
    result.contact_load_share = share * carried;
    result.plastic_load_share = share * yielded;
  }
  result.message = ehl::outcome_message(solved.newton, result.iterations);
  return result;
}

}  // namespace

EhlPointOptions fit_domain_to_film(const EhlPointContact& contact, const PiezoviscousLubricant& lubricant, double contact_film_m,
                                   EhlPointOptions given) {
  validate(contact, nullptr, given);
  validate(lubricant);
  if (!(contact_film_m >= 0.0 && std::isfinite(contact_film_m)))
    throw std::invalid_argument("EHL point contact: the boundary layers' thickness must be finite and ≥ 0, got " + shortest(contact_film_m));
  const double radius = contact.reduced_radius_m;
  const double a = reference::hertz_point_radius_m(contact.load_N, radius, contact.reduced_modulus_Pa);
  reference::PointContactGroups g = reference::point_contact_groups(contact.load_N, radius, contact.reduced_modulus_Pa,
                                                                    contact.mean_speed_m_per_s, lubricant.viscosity_Pa_s,
                                                                    lubricant.pressure_viscosity_per_Pa);
  g.material = std::max(g.material, 1000.0);
  const double film_m = reference::hamrock_dowson_central_film(g) * radius + contact_film_m;
  const double inlet = std::clamp(1.5 * reference::hamrock_dowson_flooded_inlet(film_m / radius, radius / a), 1.5, 3.5);
  given.inlet_over_radius = -inlet;
  given.outlet_over_radius = 1.5;
  given.side_over_radius = std::min(inlet, 2.5);
  return given;
}

EhlPointResult solve_ehl_point(const EhlPointContact& contact, const PiezoviscousLubricant& lubricant, const EhlPointOptions& options) {
  return solve_point(contact, nullptr, lubricant, options);
}

EhlPointResult solve_ehl_point(const EhlPointContact& contact, const EhlRoughness& roughness, const PiezoviscousLubricant& lubricant,
                               const EhlPointOptions& options) {
  return solve_point(contact, &roughness, lubricant, options);
}

}  // namespace tribo::lubrication
