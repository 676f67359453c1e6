#include "lubrication/reynolds.h"

#include "lubrication/cavitation_krylov.h"
#include "lubrication/struct_multigrid.h"
#include "numerics/format.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <deque>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tribo::lubrication {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The options' stopping rule for the iterative (hypre) backends.
IterativeSolveOptions iterative_options(const ReynoldsOptions& options) {
  return {options.multigrid_tolerance, options.multigrid_max_iterations};
}
// A hypre backend with that rule (made on first use: it starts MPI).
std::unique_ptr<SparseLinearSolver> make_multigrid_solver(LinearSolverKind kind, const ReynoldsOptions& options) {
  return make_linear_solver(kind, iterative_options(options));
}

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("reynolds: " + what); }

// A link is one face of the cell around an unknown node P, towards neighbour node N.
enum class LinkKind { unknown, dirichlet, rim };
struct Link {
  LinkKind kind;
  Eigen::Index node;   // neighbour node N (outside the film for rim links)
  int unknown;         // unknown index of N, or −1
  double theta;        // fraction of the spacing to the boundary value (1 except rim links)
  double value_Pa;     // boundary pressure for dirichlet and rim links
  bool along_x;
  int sign;            // +1 towards +x / +y, −1 towards −x / −y
};

// Grid topology: which nodes are unknowns, and the four links of each.
struct Topology {
  std::vector<int> unknown_of;             // per node, −1 where p is prescribed
  std::vector<Eigen::Index> node_of;       // per unknown
  std::vector<std::array<Link, 4>> links;  // per unknown
  Eigen::ArrayXX<bool> wetted;             // per node
  Eigen::ArrayXXd boundary_Pa;             // per node, prescribed p (0 inside)
  Eigen::ArrayXXd weight_m2;               // per node, load-integration weight
};

// Smallest fraction of a link kept between a node and the rim; nodes closer to the rim than
// this along a grid line are put on the rim (p = 0), which keeps k/θ bounded. The pressure
// error this causes is O(θ_min · dx · |∇p|), far below the O(dx²) discretisation error.
constexpr double kMinRimFraction = 1e-3;

// Iterates remembered by the non-monotone line search.
constexpr std::size_t kNonMonotoneMemory = 8;

// Distance fraction t ∈ (0, 1] along the link from (x, y) in direction (ex, ey) of length d
// at which the circle is crossed, for a point inside the circle.
double rim_fraction(const DiscDomain& disc, double x, double y, double ex, double ey, double d) {
  const double px = x - disc.centre_x_m, py = y - disc.centre_y_m;
  const double b = px * ex + py * ey;
  const double c = px * px + py * py - disc.radius_m * disc.radius_m;
  return (-b + std::sqrt(b * b - c)) / d;
}

Topology build_topology(const ReynoldsProblem& pr) {
  const contact::Grid& g = pr.grid;
  const bool periodic = pr.boundary_y == BoundaryY::periodic && !pr.disc;
  Topology t;
  t.unknown_of.assign(g.size(), -1);
  t.wetted = Eigen::ArrayXX<bool>::Constant(g.nx, g.ny, false);
  t.boundary_Pa = g.field();
  t.weight_m2 = g.field();
  auto inside_disc = [&](int i, int j) {
    const double x = i * g.dx_m - pr.disc->centre_x_m, y = j * g.dy_m - pr.disc->centre_y_m;
    return x * x + y * y < pr.disc->radius_m * pr.disc->radius_m;
  };
  const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Eigen::Index n = g.index(i, j);
      bool unknown;
      if (pr.disc) {
        unknown = inside_disc(i, j);
        for (const auto& d : dirs) {
          if (!unknown) break;
          if (inside_disc(i + d[0], j + d[1])) continue;
          const double len = d[0] ? g.dx_m : g.dy_m;
          if (rim_fraction(*pr.disc, i * g.dx_m, j * g.dy_m, d[0], d[1], len) < kMinRimFraction) unknown = false;
        }
        t.wetted(n) = unknown;
      } else {
        const bool x_end = i == 0 || i == g.nx - 1;
        const bool y_end = !periodic && (j == 0 || j == g.ny - 1);
        unknown = !x_end && !y_end;
        t.wetted(n) = true;
        if (x_end && !y_end) t.boundary_Pa(n) = i == 0 ? pr.inlet_pressure_Pa : pr.outlet_pressure_Pa;
        const double wx = x_end ? 0.5 * g.dx_m : g.dx_m;
        const double wy = periodic ? g.dy_m : ((j == 0 || j == g.ny - 1) ? 0.5 * g.dy_m : g.dy_m);
        t.weight_m2(n) = wx * wy;
      }
      if (unknown) {
        t.unknown_of[n] = static_cast<int>(t.node_of.size());
        t.node_of.push_back(n);
      }
    }
  if (t.node_of.empty()) bad("the film domain holds no interior grid node; refine the grid");
  t.links.resize(t.node_of.size());
  for (std::size_t u = 0; u < t.node_of.size(); ++u) {
    const Eigen::Index n = t.node_of[u];
    const int i = static_cast<int>(n % g.nx), j = static_cast<int>(n / g.nx);
    double len_x = 0;  // row length of the cell for the disc's load weights
    for (int k = 0; k < 4; ++k) {
      const int ni = i + dirs[k][0];
      int nj = j + dirs[k][1];
      if (periodic) nj = (nj + g.ny) % g.ny;
      const Eigen::Index m = g.index(ni, nj);
      const bool along_x = dirs[k][0] != 0;
      const double len = along_x ? g.dx_m : g.dy_m;
      Link link{LinkKind::unknown, m, t.unknown_of[m], 1.0, 0.0, along_x, along_x ? dirs[k][0] : dirs[k][1]};
      if (link.unknown < 0) {
        if (pr.disc) {
          link.kind = LinkKind::rim;
          link.theta = rim_fraction(*pr.disc, i * g.dx_m, j * g.dy_m, dirs[k][0], dirs[k][1], len);
          // The neighbour may be inside the circle but on the rim (θ_min rule): the rim is there.
          if (inside_disc(ni, nj)) link.theta = 1.0;
        } else {
          link.kind = LinkKind::dirichlet;
          link.value_Pa = t.boundary_Pa(m);
        }
      }
      if (along_x) len_x += 0.5 * link.theta * g.dx_m;
      t.links[u][k] = link;
    }
    if (pr.disc) t.weight_m2(n) = len_x * g.dy_m;
  }
  return t;
}


// Face quantities of a link (see the header): conductance from the trapezoid rule on ∫dx/k with
// k = φh³/(12η), the Couette film t̃ = ∫(t/k)dx / ∫dx/k (plain: h̃ = ∫dx/h² / ∫dx/h³), and the
// face length times 1/(θ d).
struct Face {
  double conductance_per_Pa;  // k A / (θ d): mass flow per unit pressure difference (m³/(Pa s))
  double couette_m3_per_s;    // s (U/2) t̃ A, the Couette flow out of the cell at ϑ = 1
};

// φ of a node along the link's direction (1 when the field is empty).
double flow_factor(const ReynoldsProblem& pr, Eigen::Index node, bool along_x) {
  const Eigen::ArrayXXd& phi = along_x ? pr.pressure_flow_factor_x : pr.pressure_flow_factor_y;
  return phi.size() == 0 ? 1.0 : phi(node);
}

bool average_flow_model(const ReynoldsProblem& pr) {
  return pr.pressure_flow_factor_x.size() != 0 || pr.pressure_flow_factor_y.size() != 0 ||
         pr.couette_film_m.size() != 0;
}

Face face_of(const ReynoldsProblem& pr, Eigen::Index p_node, const Link& link) {
  const contact::Grid& g = pr.grid;
  const double hp = pr.gap_m(p_node), hn = pr.gap_m(link.node);
  const double d = link.along_x ? g.dx_m : g.dy_m, area = link.along_x ? g.dy_m : g.dx_m;
  // The diffusive face runs from P to the rim point (gap interpolated there) for rim links.
  const bool rim = link.kind == LinkKind::rim;
  const double hb = rim ? hp + link.theta * (hn - hp) : hn;
  if (!average_flow_model(pr)) {  // the plain equation, kept bit for bit
    const double inv3 = 1.0 / (hp * hp * hp) + 1.0 / (hb * hb * hb);
    const double k = 2.0 / inv3 / (12.0 * pr.viscosity_Pa_s);
    Face f{k * area / (link.theta * d), 0.0};
    if (link.along_x && pr.sliding_speed_m_per_s != 0.0) {
      // The Couette divergence uses the regular face P–N (the Gibou cell is a full dx × dy cell).
      const double i3 = 1.0 / (hp * hp * hp) + 1.0 / (hn * hn * hn);
      const double i2 = 1.0 / (hp * hp) + 1.0 / (hn * hn);
      f.couette_m3_per_s = link.sign * 0.5 * pr.sliding_speed_m_per_s * (i2 / i3) * area;
    }
    return f;
  }
  // Average flow model: 1/(φh³) at P, N and the rim point (φ interpolated there like h).
  const double phi_p = flow_factor(pr, p_node, link.along_x), phi_n = flow_factor(pr, link.node, link.along_x);
  const double phi_b = rim ? phi_p + link.theta * (phi_n - phi_p) : phi_n;
  const double ap = 1.0 / (phi_p * hp * hp * hp), ab = 1.0 / (phi_b * hb * hb * hb);
  const double k = 2.0 / (ap + ab) / (12.0 * pr.viscosity_Pa_s);
  Face f{k * area / (link.theta * d), 0.0};
  if (link.along_x && pr.sliding_speed_m_per_s != 0.0) {
    const double an = 1.0 / (phi_n * hn * hn * hn);
    const double tp = pr.couette_film_m.size() == 0 ? hp : pr.couette_film_m(p_node);
    const double tn = pr.couette_film_m.size() == 0 ? hn : pr.couette_film_m(link.node);
    f.couette_m3_per_s = link.sign * 0.5 * pr.sliding_speed_m_per_s * ((tp * ap + tn * an) / (ap + an)) * area;
  }
  return f;
}

// Barus reduced pressure q = (1 − e^{−ψp})/ψ (q = p for ψ = 0).
double reduced_pressure(double p_Pa, double psi_per_Pa) {
  return psi_per_Pa > 0.0 ? -std::expm1(-psi_per_Pa * p_Pa) / psi_per_Pa : p_Pa;
}

// Whether the Couette flux through this link takes ϑ from P (else from the neighbour).
bool upwind_is_p(const ReynoldsProblem& pr, const Link& link) { return link.sign * pr.sliding_speed_m_per_s >= 0.0; }

double gap_rate(const ReynoldsProblem& pr, Eigen::Index node) {
  return pr.gap_rate_m_per_s.size() == 0 ? 0.0 : pr.gap_rate_m_per_s(node);
}

std::string shape(const Eigen::ArrayXXd& f) { return std::to_string(f.rows()) + " x " + std::to_string(f.cols()); }

}  // namespace

void validate(const ReynoldsProblem& pr) {
  const contact::Grid& g = pr.grid;
  if (g.nx < 3 || g.ny < 3)
    bad("grid must have at least 3 nodes in x and y (got " + std::to_string(g.nx) + " x " + std::to_string(g.ny) + ")");
  if (!(std::isfinite(g.dx_m) && g.dx_m > 0 && std::isfinite(g.dy_m) && g.dy_m > 0))
    bad("grid spacing dx_m, dy_m must be finite and > 0");
  const std::string grid_shape = std::to_string(g.nx) + " x " + std::to_string(g.ny);
  if (!g.holds(pr.gap_m)) bad("gap_m is " + shape(pr.gap_m) + ", the grid " + grid_shape);
  for (Eigen::Index n = 0; n < pr.gap_m.size(); ++n)
    if (!std::isfinite(pr.gap_m(n)) || pr.gap_m(n) <= 0.0) {
      std::ostringstream m;
      m << "gap_m must be finite and > 0 everywhere; node (i=" << n % g.nx << ", j=" << n / g.nx << ") has h = "
        << pr.gap_m(n) << " m";
      bad(m.str());
    }
  if (pr.gap_rate_m_per_s.size() != 0) {
    if (!g.holds(pr.gap_rate_m_per_s)) bad("gap_rate_m_per_s must be empty or have one value per node");
    if (!pr.gap_rate_m_per_s.allFinite()) bad("gap_rate_m_per_s holds a non-finite value");
  }
  // Average flow fields: empty, or one finite value per node, φ > 0 and t ≥ 0.
  auto check_field = [&](const Eigen::ArrayXXd& v, const char* name, bool zero_allowed) {
    if (v.size() == 0) return;
    if (!g.holds(v))
      bad(std::string(name) + " must be empty or have one value per node (got " + shape(v) + ", the grid " +
          grid_shape + ")");
    for (Eigen::Index n = 0; n < v.size(); ++n)
      if (!std::isfinite(v(n)) || v(n) < 0.0 || (!zero_allowed && v(n) == 0.0)) {
        std::ostringstream m;
        m << name << " must be finite and " << (zero_allowed ? ">= 0" : "> 0") << " everywhere; node (i=" << n % g.nx
          << ", j=" << n / g.nx << ") has " << v(n);
        bad(m.str());
      }
  };
  check_field(pr.pressure_flow_factor_x, "pressure_flow_factor_x", false);
  check_field(pr.pressure_flow_factor_y, "pressure_flow_factor_y", false);
  check_field(pr.couette_film_m, "couette_film_m", true);
  if (!std::isfinite(pr.viscosity_Pa_s) || pr.viscosity_Pa_s <= 0.0)
    bad("viscosity_Pa_s must be finite and > 0 (got " + numerics::shortest(pr.viscosity_Pa_s) + " Pa s)");
  if (!std::isfinite(pr.pressure_viscosity_per_Pa) || pr.pressure_viscosity_per_Pa < 0.0)
    bad("pressure_viscosity_per_Pa must be finite and >= 0");
  if (!std::isfinite(pr.sliding_speed_m_per_s)) bad("sliding_speed_m_per_s must be finite");
  if (!std::isfinite(pr.inlet_pressure_Pa) || !std::isfinite(pr.outlet_pressure_Pa))
    bad("inlet_pressure_Pa and outlet_pressure_Pa must be finite");
  if (pr.cavitation == Cavitation::mass_conserving && (pr.inlet_pressure_Pa < 0 || pr.outlet_pressure_Pa < 0))
    bad("with cavitation the boundary pressures must be >= 0 (gauge, cavitation at p = 0)");
  if (pr.disc) {
    const DiscDomain& d = *pr.disc;
    if (!(std::isfinite(d.radius_m) && d.radius_m > 0)) bad("disc radius_m must be finite and > 0");
    if (!(std::isfinite(d.centre_x_m) && std::isfinite(d.centre_y_m))) bad("disc centre must be finite");
    if (d.centre_x_m - d.radius_m <= 0 || d.centre_x_m + d.radius_m >= g.span_x_m() ||
        d.centre_y_m - d.radius_m <= 0 || d.centre_y_m + d.radius_m >= g.span_y_m())
      bad("the disc must lie strictly inside the grid");
  }
}

struct ReynoldsSolver::Impl {
  // Pattern signature: a new symbolic analysis is needed only when it changes. A type of Impl's
  // own, not the anonymous namespace's: a member of such a type warns (-Wsubobject-linkage) where
  // this file is compiled inside another (unity builds).
  struct Signature {
    Eigen::Index nx = 0, ny = 0;
    BoundaryY by = BoundaryY::ambient;
    bool disc = false;
    double cx = 0, cy = 0, r = 0, dx = 0, dy = 0;
    Cavitation cav = Cavitation::none;
    int upwind = 0;
    bool operator==(const Signature&) const = default;
  };
  static Signature signature_of(const ReynoldsProblem& pr) {
    Signature s{pr.grid.nx, pr.grid.ny, pr.boundary_y, pr.disc.has_value(), 0, 0, 0, pr.grid.dx_m, pr.grid.dy_m,
                pr.cavitation, pr.sliding_speed_m_per_s > 0 ? 1 : (pr.sliding_speed_m_per_s < 0 ? -1 : 0)};
    if (pr.disc) {
      s.cx = pr.disc->centre_x_m;
      s.cy = pr.disc->centre_y_m;
      s.r = pr.disc->radius_m;
    }
    return s;
  }
  ReynoldsOptions options;
  std::unique_ptr<SparseLinearSolver> cholmod = make_linear_solver(LinearSolverKind::cholmod);
  std::unique_ptr<SparseLinearSolver> umfpack = make_linear_solver(LinearSolverKind::umfpack);
  std::unique_ptr<SparseLinearSolver> multigrid;        // created on first use (starts MPI and hypre)
  std::unique_ptr<SparseLinearSolver> pfmg;             // structured multigrid of the box pfmg_box
  BoxGrid pfmg_box;
  std::unique_ptr<SparseLinearSolver> multigrid_newton;  // GMRES + AMG for the reduced Newton system
  std::unique_ptr<CavitationKrylovSolver> block_newton;  // GMRES + block-triangular preconditioner
  std::optional<Signature> cholmod_signature, umfpack_signature;
  int analyses = 0;
  double linear_s = 0;
  double pressure_scale_Pa = 0;  // the last solve's max |p| of the full film (its NCP scale)

  bool use_multigrid(std::size_t unknowns) const {
    if (options.pressure_solver == PressureSolver::automatic)
      return unknowns >= static_cast<std::size_t>(options.multigrid_min_unknowns);
    return options.pressure_solver == PressureSolver::multigrid;
  }

  // The unknowns of a rectangular domain as a box (build_topology numbers them row by row), when
  // the options ask for structured multigrid and PFMG takes the box.
  std::optional<BoxGrid> pfmg_box_of(const ReynoldsProblem& pr) const {
    if (!options.structured_multigrid || pr.disc) return std::nullopt;
    const bool periodic = pr.boundary_y == BoundaryY::periodic;
    const BoxGrid box{static_cast<int>(pr.grid.nx - 2), static_cast<int>(periodic ? pr.grid.ny : pr.grid.ny - 2), periodic};
    if (!pfmg_supports(box)) return std::nullopt;
    return box;
  }

  // The backend solve_linear() takes for this problem with `unknowns` unknowns.
  LinearSolverKind pressure_backend(const ReynoldsProblem& pr, std::size_t unknowns) const {
    if (!use_multigrid(unknowns)) return LinearSolverKind::cholmod;
    return pfmg_box_of(pr) ? LinearSolverKind::pfmg_pcg : LinearSolverKind::amg_pcg;
  }

  // The structured multigrid of `box` (made again when the box changes) and the BoomerAMG-PCG
  // backend, both made on first use.
  SparseLinearSolver& pfmg_for(const BoxGrid& box) {
    if (!pfmg || box.ni != pfmg_box.ni || box.nj != pfmg_box.nj || box.periodic_j != pfmg_box.periodic_j) {
      pfmg = make_pfmg_solver(box, iterative_options(options));
      pfmg_box = box;
    }
    return *pfmg;
  }
  SparseLinearSolver& amg_pcg() {
    if (!multigrid) multigrid = make_multigrid_solver(LinearSolverKind::amg_pcg, options);
    return *multigrid;
  }

  // The linear (ϑ ≡ 1) problem A p = b, A SPD; returns max |b|, the scale of the mass rows.
  static double assemble_linear(const ReynoldsProblem& pr, const Topology& t, SparseMatrix& a, Eigen::VectorXd& b) {
    const std::size_t n = t.node_of.size();
    std::vector<Eigen::Triplet<double, int>> triplets;
    triplets.reserve(5 * n);
    b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    const double cell = pr.grid.cell_area_m2();
    for (std::size_t u = 0; u < n; ++u) {
      const Eigen::Index node = t.node_of[u];
      double diag = 0;
      for (const Link& link : t.links[u]) {
        const Face f = face_of(pr, node, link);
        diag += f.conductance_per_Pa;
        if (link.kind == LinkKind::unknown)
          triplets.emplace_back(static_cast<int>(u), link.unknown, -f.conductance_per_Pa);
        else
          b[u] += f.conductance_per_Pa * link.value_Pa;
        b[u] -= f.couette_m3_per_s;
      }
      b[u] -= gap_rate(pr, node) * cell;
      triplets.emplace_back(static_cast<int>(u), static_cast<int>(u), diag);
    }
    a.resize(static_cast<int>(n), static_cast<int>(n));
    a.setFromTriplets(triplets.begin(), triplets.end());
    return b.cwiseAbs().maxCoeff();
  }

  // Solves the linear (ϑ ≡ 1) problem into p (per unknown); returns the SPD system's rhs scale.
  // With multigrid, a solve that misses its tolerance returns ok = false with its iterate in p.
  LinearSolveStatus solve_linear(const ReynoldsProblem& pr, const Topology& t, Eigen::VectorXd& p, double& rhs_scale) {
    const std::size_t n = t.node_of.size();
    SparseMatrix a;
    Eigen::VectorXd b;
    rhs_scale = assemble_linear(pr, t, a, b);
    const auto t0 = Clock::now();
    // The pressure matrix does not depend on the sliding direction or the cavitation model.
    Signature sig = signature_of(pr);
    sig.cav = Cavitation::none;
    sig.upwind = 0;
    LinearSolveStatus s;
    if (const LinearSolverKind kind = pressure_backend(pr, n); kind != LinearSolverKind::cholmod) {
      // Multigrid has no reusable symbolic phase: every solve sets up the hierarchy of its matrix
      // (cheap for PFMG, the bulk of the solve for BoomerAMG).
      SparseLinearSolver& mg = kind == LinearSolverKind::pfmg_pcg ? pfmg_for(*pfmg_box_of(pr)) : amg_pcg();
      s = mg.analyze(a);
      if (s.ok) s = mg.factorize(a);
      if (s.ok) s = mg.solve(b, p);
      linear_s += seconds_since(t0);
      return s;
    }
    if (!cholmod_signature || !(*cholmod_signature == sig) || !cholmod->analyzed()) {
      cholmod_signature.reset();
      s = cholmod->analyze(a);
      ++analyses;
      if (s.ok) cholmod_signature = sig;
    }
    if (s.ok) s = cholmod->factorize(a);
    if (s.ok) s = cholmod->solve(b, p);
    linear_s += seconds_since(t0);
    return s;
  }

  // Jacobian of one unknown's mass row: ∂/∂p and ∂/∂ϑ of the columns self + unknown neighbours.
  struct MassRow {
    std::array<int, 5> column{};
    std::array<double, 5> d_p{}, d_theta{};
    int count = 0;
  };
  // Linearised NCP row: φ + α Δp + β Δϑ = 0.
  struct NcpRow {
    double phi, alpha, beta;
  };

  // Residual F (size 2n: mass rows divided by mass_scale, NCP rows) and, if wanted, the rows of
  // its Jacobian.
  void residual(const ReynoldsProblem& pr, const Topology& t, const Eigen::VectorXd& z, double mass_scale,
                double p_scale, Eigen::VectorXd& f, std::vector<MassRow>* mass_rows,
                std::vector<NcpRow>* ncp_rows) const {
    const std::size_t n = t.node_of.size();
    const double cell = pr.grid.cell_area_m2();
    f.resize(static_cast<Eigen::Index>(2 * n));
    for (std::size_t u = 0; u < n; ++u) {
      const Eigen::Index node = t.node_of[u];
      const int row = static_cast<int>(2 * u);
      const double p = z[row], th = z[row + 1];
      double mass = gap_rate(pr, node) * cell * th;
      MassRow jr;
      jr.column[0] = static_cast<int>(u);
      jr.d_theta[0] = gap_rate(pr, node) * cell / mass_scale;
      jr.count = 1;
      for (const Link& link : t.links[u]) {
        const Face fc = face_of(pr, node, link);
        const bool known = link.kind != LinkKind::unknown;
        const double pn = known ? link.value_Pa : z[2 * link.unknown];
        const double thn = known ? 1.0 : z[2 * link.unknown + 1];
        const bool from_p = upwind_is_p(pr, link);
        mass += fc.conductance_per_Pa * (p - pn) + fc.couette_m3_per_s * (from_p ? th : thn);
        jr.d_p[0] += fc.conductance_per_Pa / mass_scale;
        if (from_p) jr.d_theta[0] += fc.couette_m3_per_s / mass_scale;
        if (!known) {
          // Every unknown neighbour gets a column, even with zero entries, so the pattern of the
          // Newton matrix never changes and its symbolic analysis stays valid.
          jr.column[jr.count] = link.unknown;
          jr.d_p[jr.count] = -fc.conductance_per_Pa / mass_scale;
          jr.d_theta[jr.count] = from_p ? 0.0 : fc.couette_m3_per_s / mass_scale;
          ++jr.count;
        }
      }
      f[row] = mass / mass_scale;
      const Ncp c = ncp(options.complementarity, p / p_scale, 1.0 - th);
      f[row + 1] = c.value;
      if (mass_rows) (*mass_rows)[u] = jr;
      if (ncp_rows) (*ncp_rows)[u] = NcpRow{c.value, c.da / p_scale, -c.db};
    }
  }

  // Projected nonlinear Gauss–Seidel on the JFO conditions (Cryer, SIAM J. Control 9, 1971, for
  // the obstacle problem; the mass-conserving p–ϑ form of Giacopini et al., J. Tribol. 132, 2010):
  // each node in turn takes the (p, ϑ) that zeroes its own mass row with its neighbours held —
  // full film (ϑ = 1) if that gives p ≥ 0, else p = 0 and ϑ from the row (a node without outflow,
  // whose row has no ϑ term, then keeps its start). The mass rows are affine
  // in z (the upwind side is fixed by the sliding direction), so F_u(z) = c_u + J_u z with c_u
  // taken once from F and J at the start. `rows` and `f` are those of z.
  static void relax_fronts(const std::vector<MassRow>& rows, const Eigen::VectorXd& f, Eigen::VectorXd& z, int sweeps) {
    const std::size_t n = rows.size();
    auto neighbours = [&](std::size_t u, int from) {
      const MassRow& r = rows[u];
      double v = 0.0;
      for (int k = from; k < r.count; ++k) v += r.d_p[k] * z[2 * r.column[k]] + r.d_theta[k] * z[2 * r.column[k] + 1];
      return v;
    };
    std::vector<double> c(n);
    for (std::size_t u = 0; u < n; ++u) c[u] = f[static_cast<Eigen::Index>(2 * u)] - neighbours(u, 0);
    auto visit = [&](std::size_t u) {
      const MassRow& r = rows[u];
      const double s = c[u] + neighbours(u, 1);  // the row without the node's own terms
      const double p_full = -(s + r.d_theta[0]) / r.d_p[0];
      if (p_full >= 0.0) {
        z[2 * u] = p_full;
        z[2 * u + 1] = 1.0;
      } else if (r.d_theta[0] > 0.0) {
        z[2 * u] = 0.0;
        z[2 * u + 1] = std::clamp(-s / r.d_theta[0], 0.0, 1.0);
      }
    };
    for (int k = 0; k < sweeps; ++k) {
      for (std::size_t u = 0; u < n; ++u) visit(u);
      for (std::size_t u = n; u-- > 0;) visit(u);
    }
  }

  // The Newton system J Δz = −F reduced to one unknown per node by eliminating, from each
  // node's NCP row φ + αΔp + βΔϑ = 0, the increment with the larger coefficient: Δϑ where
  // |β| ≥ |α|·p_s (full film; the unknown is Δp), else Δp (cavitated; the unknown is Δϑ). With
  // the minimum function this is exact block elimination of a 0/1 row, and the reduced matrix has
  // the 5-point pattern of the pressure matrix — half the size of J for UMFPACK.
  void reduced_system(const std::vector<MassRow>& rows, const std::vector<NcpRow>& ncp, const Eigen::VectorXd& f,
                      double p_scale, std::vector<char>& keeps_p, std::vector<Eigen::Triplet<double, int>>& triplets,
                      Eigen::VectorXd& rhs) const {
    const std::size_t n = rows.size();
    keeps_p.resize(n);
    for (std::size_t u = 0; u < n; ++u) keeps_p[u] = std::abs(ncp[u].beta) >= std::abs(ncp[u].alpha) * p_scale;
    triplets.clear();
    rhs.resize(static_cast<Eigen::Index>(n));
    for (std::size_t u = 0; u < n; ++u) {
      const MassRow& r = rows[u];
      double b = -f[static_cast<Eigen::Index>(2 * u)];
      for (int k = 0; k < r.count; ++k) {
        const NcpRow& c = ncp[r.column[k]];
        double coefficient;
        if (keeps_p[r.column[k]]) {  // Δϑ = (−φ − αΔp)/β
          coefficient = r.d_p[k] - r.d_theta[k] * c.alpha / c.beta;
          b += r.d_theta[k] * c.phi / c.beta;
        } else {  // Δp = (−φ − βΔϑ)/α
          coefficient = r.d_theta[k] - r.d_p[k] * c.beta / c.alpha;
          b += r.d_p[k] * c.phi / c.alpha;
        }
        triplets.emplace_back(static_cast<int>(u), r.column[k], coefficient);
      }
      rhs[static_cast<Eigen::Index>(u)] = b;
    }
  }

  // Grid sequencing (nested iteration; Kelley, Solving Nonlinear Equations with Newton's Method,
  // SIAM 2003, §1.9; for free boundaries Hoppe, SIAM J. Numer. Anal. 24, 1987): the semismooth
  // Newton iteration moves the cavitation fronts a few cells per step, so started from the full
  // film it needs more steps the finer the grid (10, 16, 26, 48 from 128² to 1024²). The same
  // problem on every other node, solved first (recursively, to the same tolerance), puts the
  // fronts within a coarse cell, and its bilinear interpolation starts the fine Newton iteration.
  // The coarse answer is only a starting point: the fine solve meets its own tolerance, and if it
  // fails from there it is repeated from the usual full-film start.
  // Returns the coarse solution on the coarse grid with the pressure scale its Newton iteration
  // used, or nothing when the grid does not coarsen (disc domain, nodes not aligned, too small) or
  // the coarse solve did not converge.
  struct CoarseStart {
    ReynoldsSolution solution;
    double pressure_scale_Pa;
  };
  std::optional<CoarseStart> coarse_start(const ReynoldsProblem& pr, std::size_t unknowns) {
    const contact::Grid& g = pr.grid;
    const bool periodic = pr.boundary_y == BoundaryY::periodic;
    if (!options.grid_sequencing || pr.disc || !use_multigrid(unknowns)) return std::nullopt;
    if ((g.nx - 1) % 2 != 0 || (periodic ? g.ny % 2 : (g.ny - 1) % 2) != 0) return std::nullopt;
    contact::Grid c{(g.nx - 1) / 2 + 1, periodic ? g.ny / 2 : (g.ny - 1) / 2 + 1, 2 * g.dx_m, 2 * g.dy_m};
    if (c.nx < options.grid_sequencing_min_nodes || c.ny < options.grid_sequencing_min_nodes) return std::nullopt;
    ReynoldsProblem coarse = pr;
    coarse.grid = c;
    auto inject = [&](const Eigen::ArrayXXd& f) {
      if (f.size() == 0) return Eigen::ArrayXXd();
      Eigen::ArrayXXd out(c.nx, c.ny);
      for (Eigen::Index j = 0; j < c.ny; ++j)
        for (Eigen::Index i = 0; i < c.nx; ++i) out(i, j) = f(2 * i, 2 * j);
      return out;
    };
    coarse.gap_m = inject(pr.gap_m);
    coarse.gap_rate_m_per_s = inject(pr.gap_rate_m_per_s);
    coarse.pressure_flow_factor_x = inject(pr.pressure_flow_factor_x);
    coarse.pressure_flow_factor_y = inject(pr.pressure_flow_factor_y);
    coarse.couette_film_m = inject(pr.couette_film_m);
    // The coarse grid uses the backend its own size calls for (UMFPACK below the multigrid
    // threshold under `automatic`, which ends the recursion there), and coarsens again while it can.
    // The coarse answer is a start whose own discretisation error (O(dx²), ≈ 1e-4 of the
    // pressure here) dwarfs a residual of 1e-6: a tighter coarse solve only costs its last steps.
    ReynoldsOptions coarse_options = options;
    coarse_options.newton_tolerance = std::max(options.newton_tolerance, options.grid_sequencing_tolerance);
    ReynoldsSolver solver(coarse_options);
    ReynoldsSolution s = solver.solve(coarse);
    if (!s.summary.converged) return std::nullopt;
    return CoarseStart{std::move(s), solver.impl_->pressure_scale_Pa};
  }

  // Bilinear value of a coarse-grid field at fine node (i, j) (coarse node spacing = 2 fine).
  static double interpolate(const Eigen::ArrayXXd& f, Eigen::Index i, Eigen::Index j, bool periodic) {
    const Eigen::Index nx = f.rows(), ny = f.cols();
    const Eigen::Index i0 = i / 2, j0 = j / 2;
    const Eigen::Index i1 = std::min(i0 + 1, nx - 1);
    const Eigen::Index j1 = periodic ? (j0 + 1) % ny : std::min(j0 + 1, ny - 1);
    const double tx = (i % 2) ? 0.5 : 0.0, ty = (j % 2) ? 0.5 : 0.0;
    return (1 - tx) * (1 - ty) * f(i0, j0) + tx * (1 - ty) * f(i1, j0) + (1 - tx) * ty * f(i0, j1) +
           tx * ty * f(i1, j1);
  }

  ReynoldsSolution solve(const ReynoldsProblem& pr) {
    validate(pr);
    if (pr.pressure_viscosity_per_Pa > 0.0) return solve_piezoviscous(pr);
    return solve_isoviscous(pr);
  }

  // Barus' law through the reduced pressure q (see the header): the isoviscous solve in q, then
  // p = −ln(1 − ψq)/ψ and the load and peak from p.
  ReynoldsSolution solve_piezoviscous(const ReynoldsProblem& pr) {
    const auto start = Clock::now();
    const double psi = pr.pressure_viscosity_per_Pa;
    ReynoldsProblem reduced = pr;
    reduced.pressure_viscosity_per_Pa = 0.0;
    reduced.inlet_pressure_Pa = reduced_pressure(pr.inlet_pressure_Pa, psi);
    reduced.outlet_pressure_Pa = reduced_pressure(pr.outlet_pressure_Pa, psi);
    ReynoldsSolution sol = solve_isoviscous(reduced);
    const Topology t = build_topology(pr);
    sol.load_N = 0;
    sol.max_pressure_Pa = -std::numeric_limits<double>::infinity();
    bool blow_up = false;
    for (Eigen::Index node = 0; node < pr.grid.size(); ++node) {
      const double x = psi * sol.pressure_Pa(node);
      if (x >= 1.0) blow_up = true;
      sol.pressure_Pa(node) = x >= 1.0 ? std::numeric_limits<double>::infinity() : -std::log1p(-x) / psi;
      if (!t.wetted(node)) continue;
      sol.load_N += t.weight_m2(node) * sol.pressure_Pa(node);
      sol.max_pressure_Pa = std::max(sol.max_pressure_Pa, sol.pressure_Pa(node));
    }
    if (blow_up) {
      sol.summary.converged = false;
      sol.summary.message = "piezoviscous blow-up: the reduced pressure reaches 1/psi, no finite Barus pressure";
    }
    sol.summary.wall_s = seconds_since(start);
    return sol;
  }

  ReynoldsSolution solve_isoviscous(const ReynoldsProblem& pr, bool sequencing = true) {
    const auto start = Clock::now();
    linear_s = 0;
    const Topology t = build_topology(pr);
    const std::size_t n = t.node_of.size();
    ReynoldsSolution sol;
    sol.wetted = t.wetted;
    sol.pressure_Pa = t.boundary_Pa;
    sol.fill_fraction = pr.grid.field(1.0);
    ReynoldsSummary& sum = sol.summary;
    const bool multigrid_path = use_multigrid(n);
    sum.linear_solver = to_string(pressure_backend(pr, n));

    // A problem that may cavitate is solved on the coarse grid first (grid sequencing, below). An
    // answer there that cavitates starts the fine Newton iteration and gives the pressure scale,
    // the two uses of the fine full-film solve, which is then skipped (0.6 s of 15 at 1024²). A
    // problem that turns out not to cavitate pays for the coarse solve, about a third of its own.
    std::optional<CoarseStart> coarse;
    if (sequencing && pr.cavitation == Cavitation::mass_conserving) coarse = coarse_start(pr, n);
    const bool coarse_cavitates = coarse && coarse->solution.cavitated_fraction > 0.0;
    Eigen::VectorXd p;
    double rhs_scale = 0;
    LinearSolveStatus s;
    if (coarse_cavitates) {
      SparseMatrix a;
      Eigen::VectorXd b;
      rhs_scale = assemble_linear(pr, t, a, b);
      p = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));  // the start comes from the coarse grid
      pressure_scale_Pa = coarse->pressure_scale_Pa;
    } else {
      s = solve_linear(pr, t, p, rhs_scale);
      pressure_scale_Pa = s.ok ? p.cwiseAbs().maxCoeff() : 0.0;
    }
    sum.linear_iterations = s.iterations;
    sum.linear_residual = s.relative_residual;
    if (!s.ok) {
      sum.message = s.message;
      // A multigrid solve that missed its tolerance still returns its iterate: reported as not
      // converged, with its residual, never as an answer.
      if (multigrid_path && s.iterations > 0 && p.size() == static_cast<Eigen::Index>(n)) {
        sum.residual = s.relative_residual;
        sum.iterations = 1;
        for (std::size_t u = 0; u < n; ++u) sol.pressure_Pa(t.node_of[u]) = p[u];
      }
      sum.wall_s = seconds_since(start);
      sum.linear_solver_s = linear_s;
      return sol;
    }
    sum.converged = true;
    sum.iterations = 1;
    sum.residual = s.relative_residual;
    sum.message = multigrid_path ? "linear solve (no cavitation), multigrid PCG: " + std::to_string(s.iterations) +
                                       " iterations, relative residual " + numerics::fmt(s.relative_residual, "%.3e")
                                 : "linear solve (no cavitation)";
    // The linear solution satisfies the complementarity conditions wherever it is ≥ 0; only a
    // sub-ambient pressure calls for the Newton solve.
    const bool cavitates = coarse_cavitates || (pr.cavitation == Cavitation::mass_conserving && p.minCoeff() < 0.0);
    if (cavitates) {
      sum.linear_solver = multigrid_path ? to_string(LinearSolverKind::amg_gmres) : to_string(LinearSolverKind::umfpack);
      int direct_fallbacks = 0;
      std::string fallback_reason;  // the last GMRES failure that sent a step to UMFPACK
      double previous_f_norm = 0.0, previous_forcing = 0.0;  // inexact Newton's memory
      std::vector<char> previous_split;
      sum.converged = false;
      const double p_scale = std::max(pressure_scale_Pa, 1e-300);
      const double mass_scale = std::max(rhs_scale, 1e-300);
      Eigen::VectorXd z(static_cast<Eigen::Index>(2 * n));
      for (std::size_t u = 0; u < n; ++u) {
        z[2 * u] = std::max(p[u], 0.0);
        z[2 * u + 1] = p[u] >= 0.0 ? 1.0 : 0.9;  // off the NCP kink where the film may rupture
      }
      if (coarse) {
        const ReynoldsSolution& c = coarse->solution;
        const bool periodic = pr.boundary_y == BoundaryY::periodic;
        for (std::size_t u = 0; u < n; ++u) {
          const Eigen::Index node = t.node_of[u], i = node % pr.grid.nx, j = node / pr.grid.nx;
          z[2 * u] = std::max(interpolate(c.pressure_Pa, i, j, periodic), 0.0);
          z[2 * u + 1] = std::clamp(interpolate(c.fill_fraction, i, j, periodic), 0.0, 1.0);
        }
        linear_s += c.summary.linear_solver_s;
        sum.linear_iterations += c.summary.linear_iterations;
      }
      Eigen::VectorXd f, f_trial, dz(static_cast<Eigen::Index>(2 * n)), rhs, x;
      std::vector<MassRow> mass_rows(n);
      std::vector<NcpRow> ncp_rows(n);
      std::vector<char> keeps_p;
      std::vector<Eigen::Triplet<double, int>> triplets;
      SparseMatrix jac(static_cast<int>(n), static_cast<int>(n));
      const Signature sig = signature_of(pr);
      if (coarse && options.coarse_start_sweeps > 0) {
        residual(pr, t, z, mass_scale, p_scale, f, &mass_rows, nullptr);
        relax_fronts(mass_rows, f, z, options.coarse_start_sweeps);
      }
      residual(pr, t, z, mass_scale, p_scale, f, nullptr, nullptr);
      double merit = 0.5 * f.squaredNorm();
      std::deque<double> merits{merit};
      sum.iterations = 0;
      sum.message = "Newton iteration limit reached";
      for (int it = 0; it < options.max_newton_iterations; ++it) {
        sum.residual = f.cwiseAbs().maxCoeff();
        if (sum.residual <= options.newton_tolerance) {
          sum.converged = true;
          sum.message = "converged: scaled residual " + numerics::shortest(sum.residual);
          break;
        }
        residual(pr, t, z, mass_scale, p_scale, f, &mass_rows, &ncp_rows);
        reduced_system(mass_rows, ncp_rows, f, p_scale, keeps_p, triplets, rhs);
        const auto t0 = Clock::now();
        LinearSolveStatus ls;
        bool solved = false;
        if (multigrid_path && options.cavitation_preconditioner == CavitationPreconditioner::block_triangular) {
          // GMRES with upwind sweeps of the cavitated block and AMG on the pressure Schur
          // complement (cavitation_krylov.h); the split is the one the reduction used. A step it
          // cannot set up or solve falls back to UMFPACK.
          jac.setFromTriplets(triplets.begin(), triplets.end());
          if (!block_newton) {
            CavitationKrylovOptions ko;
            ko.max_iterations = options.multigrid_max_iterations;
            block_newton = std::make_unique<CavitationKrylovSolver>(ko);
          }
          block_newton->set_amg_reuse_changed_fraction(coarse ? options.amg_reuse_changed_fraction : 0.0);
          ls = block_newton->setup(jac, keeps_p);
          // Inexact Newton (Eisenstat & Walker, SIAM J. Sci. Comput. 17, 1996, choice 2 with
          // their safeguard): the step needs ‖J s + F‖ ≤ η_k ‖F‖ only as tight as the residual
          // is falling, η_k = γ (‖F_k‖/‖F_{k−1}‖)², never below the multigrid tolerance; the
          // convergence test on F itself is unchanged, so the answer meets the same tolerance.
          double forcing = options.multigrid_tolerance;
          const double f_norm = f.norm();
          if (options.inexact_newton) {
            const double gamma = 0.9, eta_max = coarse ? options.max_forcing : options.max_forcing_full_film_start;
            double eta = eta_max;
            if (previous_f_norm > 0.0) {
              const double ratio = f_norm / previous_f_norm;
              eta = gamma * ratio * ratio;
              const double safeguard = gamma * previous_forcing * previous_forcing;
              if (safeguard > 0.1) eta = std::max(eta, safeguard);
            }
            // With the minimum function F is affine while the split holds, and a split equal to
            // the last step's is the primal–dual active-set method's stopping signal (Hintermüller,
            // Ito & Kunisch 2002): this step is likely the last, so it is solved to the tolerance
            // at once rather than tightened over two more steps.
            if (options.complementarity == Complementarity::minimum && keeps_p == previous_split) eta = 0.0;
            // Near the solution the step need not be more accurate than the Newton tolerance
            // itself (Kelley, Iterative Methods for Linear and Nonlinear Equations, SIAM 1995,
            // §6.3): ‖r‖ ≤ ½ tolerance suffices — in the max norm of the Newton test, which
            // GMRES checks on its true residual (solve()'s max_norm_tolerance).
            eta = std::max(eta, 0.5 * options.newton_tolerance / std::max(f_norm, 1e-300));
            forcing = std::max(std::min(eta, eta_max), options.multigrid_tolerance);
          }
          previous_f_norm = f_norm;
          previous_split = keeps_p;
          previous_forcing = forcing;
          const double max_norm = options.inexact_newton ? 0.5 * options.newton_tolerance : 0.0;
          if (ls.ok) ls = block_newton->solve(rhs, x, forcing, max_norm);
          sum.linear_iterations += ls.iterations;
          if (ls.ok) {
            if (forcing <= options.multigrid_tolerance)
              sum.linear_residual = std::max(sum.linear_residual, ls.relative_residual);
            solved = true;
          } else {
            ++direct_fallbacks;
            fallback_reason = ls.message;
            ls = {};
          }
        } else if (multigrid_path) {
          // GMRES + AMG on the reduced system with the cavitated unknowns scaled to pressures,
          // y = p_s·Δϑ, so that every column has the units of Δp (AMG's strength of connection
          // compares entries of a row). A step GMRES cannot solve falls back to UMFPACK.
          std::vector<Eigen::Triplet<double, int>> scaled;
          scaled.reserve(triplets.size());
          for (const auto& tr : triplets)
            scaled.emplace_back(tr.row(), tr.col(), keeps_p[tr.col()] ? tr.value() : tr.value() / p_scale);
          jac.setFromTriplets(scaled.begin(), scaled.end());
          if (!multigrid_newton) multigrid_newton = make_multigrid_solver(LinearSolverKind::amg_gmres, options);
          ls = multigrid_newton->analyze(jac);
          if (ls.ok) ls = multigrid_newton->factorize(jac);
          if (ls.ok) ls = multigrid_newton->solve(rhs, x);
          sum.linear_iterations += ls.iterations;
          if (ls.ok) {
            sum.linear_residual = std::max(sum.linear_residual, ls.relative_residual);
            for (std::size_t u = 0; u < n; ++u)
              if (!keeps_p[u]) x[static_cast<Eigen::Index>(u)] /= p_scale;
            solved = true;
          } else {
            ++direct_fallbacks;
            fallback_reason = ls.message;
            ls = {};
          }
        }
        if (!solved) jac.setFromTriplets(triplets.begin(), triplets.end());
        if (!solved && (!umfpack_signature || !(*umfpack_signature == sig) || !umfpack->analyzed())) {
          umfpack_signature.reset();
          ls = umfpack->analyze(jac);
          ++analyses;
          if (ls.ok) umfpack_signature = sig;
        }
        if (!solved && ls.ok) ls = umfpack->factorize(jac);
        if (!solved && ls.ok) ls = umfpack->solve(rhs, x);
        linear_s += seconds_since(t0);
        if (!ls.ok) {
          sum.message = ls.message;
          break;
        }
        for (std::size_t u = 0; u < n; ++u) {
          const NcpRow& c = ncp_rows[u];
          const double xu = x[static_cast<Eigen::Index>(u)];
          dz[2 * u] = keeps_p[u] ? xu : (-c.phi - c.beta * xu) / c.alpha;
          dz[2 * u + 1] = keeps_p[u] ? (-c.phi - c.alpha * xu) / c.beta : xu;
        }
        ++sum.iterations;
        // Non-monotone Armijo back-tracking (Grippo, Lampariello & Lucidi 1986) on the merit
        // ½‖F‖²: the step must decrease the largest merit of the last few iterates. The FB
        // kinks and the upwind switch make a monotone search stall where full steps converge.
        const double reference = *std::max_element(merits.begin(), merits.end());
        double step = 1.0;
        bool accepted = false;
        while (step >= options.min_step) {
          residual(pr, t, z + step * dz, mass_scale, p_scale, f_trial, nullptr, nullptr);
          const double trial = 0.5 * f_trial.squaredNorm();
          if (trial <= reference - 2.0 * options.armijo_constant * step * merit) {
            accepted = true;
            break;
          }
          step *= 0.5;
        }
        if (!accepted) {
          sum.message = "line search failed: no sufficient decrease of the residual";
          break;
        }
        z += step * dz;
        f = f_trial;
        merit = 0.5 * f.squaredNorm();
        merits.push_back(merit);
        if (merits.size() > kNonMonotoneMemory) merits.pop_front();
      }
      if (!sum.converged && sum.iterations == options.max_newton_iterations) {
        sum.residual = f.cwiseAbs().maxCoeff();
        if (sum.residual <= options.newton_tolerance) {
          sum.converged = true;
          sum.message = "converged: scaled residual " + numerics::shortest(sum.residual);
        }
      }
      if (!sum.converged && coarse) {
        // The interpolated start did not lead to convergence: repeat from the full-film start.
        ReynoldsSolution retry = solve_isoviscous(pr, false);
        retry.summary.message += " (after a failed start from the coarse grid: " + sum.message + ")";
        retry.summary.wall_s = seconds_since(start);
        return retry;
      }
      if (coarse)
        sum.message += " (started from the " + std::to_string(coarse->solution.pressure_Pa.rows()) + " x " +
                       std::to_string(coarse->solution.pressure_Pa.cols()) + " grid's solution, " +
                       std::to_string(coarse->solution.summary.iterations) + " Newton steps there)";
      if (direct_fallbacks > 0)
        sum.message += " (" + std::to_string(direct_fallbacks) + " Newton steps fell back from GMRES to UMFPACK; last: " +
                       fallback_reason + ")";
      for (std::size_t u = 0; u < n; ++u) {
        p[u] = z[2 * u];
        sol.fill_fraction(t.node_of[u]) = z[2 * u + 1];
      }
    }
    for (std::size_t u = 0; u < n; ++u) sol.pressure_Pa(t.node_of[u]) = p[u];
    double wetted_area = 0, cavitated_area = 0;
    sol.max_pressure_Pa = -std::numeric_limits<double>::infinity();
    for (Eigen::Index node = 0; node < pr.grid.size(); ++node) {
      if (!t.wetted(node)) continue;
      sol.load_N += t.weight_m2(node) * sol.pressure_Pa(node);
      sol.max_pressure_Pa = std::max(sol.max_pressure_Pa, sol.pressure_Pa(node));
      wetted_area += t.weight_m2(node);
      if (sol.fill_fraction(node) < 1.0 - 1e-9) cavitated_area += t.weight_m2(node);
    }
    sol.cavitated_fraction = wetted_area > 0 ? cavitated_area / wetted_area : 0.0;
    sum.linear_solver_s = linear_s;
    sum.wall_s = seconds_since(start);
    return sol;
  }
};

ReynoldsSolver::ReynoldsSolver(ReynoldsOptions options) : impl_(std::make_unique<Impl>()) {
  if (!(options.newton_tolerance > 0) || options.max_newton_iterations < 1 || !(options.armijo_constant > 0) ||
      !(options.armijo_constant < 0.5) || !(options.min_step > 0) || !(options.min_step <= 1) ||
      !(options.multigrid_tolerance > 0) || !(options.multigrid_tolerance < 1) ||
      options.multigrid_max_iterations < 1 || options.multigrid_min_unknowns < 0 ||
      !(options.amg_reuse_changed_fraction >= 0) || !(options.amg_reuse_changed_fraction <= 1) ||
      !(options.max_forcing > 0) || !(options.max_forcing < 1) || !(options.max_forcing_full_film_start > 0) ||
      !(options.max_forcing_full_film_start < 1) || options.grid_sequencing_min_nodes < 3 ||
      !(options.grid_sequencing_tolerance > 0) || options.coarse_start_sweeps < 0)
    throw std::invalid_argument(
        "reynolds options: need newton_tolerance > 0, max_newton_iterations >= 1, 0 < armijo_constant < 0.5, "
        "0 < min_step <= 1, 0 < multigrid_tolerance < 1, multigrid_max_iterations >= 1, "
        "multigrid_min_unknowns >= 0, 0 <= amg_reuse_changed_fraction <= 1, 0 < max_forcing < 1, "
        "0 < max_forcing_full_film_start < 1, "
        "grid_sequencing_min_nodes >= 3, grid_sequencing_tolerance > 0, coarse_start_sweeps >= 0");
  impl_->options = options;
}
ReynoldsSolver::~ReynoldsSolver() = default;
ReynoldsSolver::ReynoldsSolver(ReynoldsSolver&&) noexcept = default;
ReynoldsSolver& ReynoldsSolver::operator=(ReynoldsSolver&&) noexcept = default;

ReynoldsSolution ReynoldsSolver::solve(const ReynoldsProblem& problem) { return impl_->solve(problem); }
int ReynoldsSolver::symbolic_analyses() const { return impl_->analyses; }

ReynoldsSolution solve_reynolds(const ReynoldsProblem& problem, const ReynoldsOptions& options) {
  return ReynoldsSolver(options).solve(problem);
}

FilmFlow film_flow(const ReynoldsProblem& pr, const ReynoldsSolution& sol) {
  validate(pr);
  const Topology t = build_topology(pr);
  FilmFlow flow;
  const double cell = pr.grid.cell_area_m2();
  for (std::size_t u = 0; u < t.node_of.size(); ++u) {
    const Eigen::Index node = t.node_of[u];
    const double psi = pr.pressure_viscosity_per_Pa;
    const double p = reduced_pressure(sol.pressure_Pa(node), psi), th = sol.fill_fraction(node);
    const double storage = gap_rate(pr, node) * cell * th;
    flow.squeeze_storage_m3_per_s += storage;
    double balance = storage;
    for (const Link& link : t.links[u]) {
      const bool known = link.kind != LinkKind::unknown;
      const double pn = reduced_pressure(known ? link.value_Pa : sol.pressure_Pa(link.node), psi);
      const double thn = known ? 1.0 : sol.fill_fraction(link.node);
      const Face f = face_of(pr, node, link);
      const double out = f.conductance_per_Pa * (p - pn) + f.couette_m3_per_s * (upwind_is_p(pr, link) ? th : thn);
      balance += out;
      if (!known) continue;
      flow.net_outflow_m3_per_s += out;
      if (!pr.disc && link.along_x && link.sign < 0 && link.node % pr.grid.nx == 0) flow.inflow_x0_m3_per_s -= out;
      if (!pr.disc && link.along_x && link.sign > 0 && link.node % pr.grid.nx == pr.grid.nx - 1)
        flow.outflow_xL_m3_per_s += out;
    }
    flow.max_cell_imbalance_m3_per_s = std::max(flow.max_cell_imbalance_m3_per_s, std::abs(balance));
  }
  return flow;
}

Eigen::ArrayXXd x_face_flow_m2_per_s(const ReynoldsProblem& pr, const ReynoldsSolution& sol) {
  validate(pr);
  if (pr.disc) bad("x_face_flow_m2_per_s needs a rectangular domain (the problem has a disc domain)");
  const contact::Grid& g = pr.grid;
  if (!g.holds(sol.pressure_Pa) || !g.holds(sol.fill_fraction))
    bad("x_face_flow_m2_per_s: the solution does not belong to this problem's grid");
  const double psi = pr.pressure_viscosity_per_Pa;
  Eigen::ArrayXXd q(g.nx - 1, g.ny);
  for (Eigen::Index j = 0; j < g.ny; ++j)
    for (Eigen::Index i = 0; i + 1 < g.nx; ++i) {
      const Eigen::Index p = g.index(i, j), n = g.index(i + 1, j);
      const Link link{LinkKind::unknown, n, -1, 1.0, 0.0, true, +1};
      const Face f = face_of(pr, p, link);
      const double th = upwind_is_p(pr, link) ? sol.fill_fraction(p) : sol.fill_fraction(n);
      const double dp = reduced_pressure(sol.pressure_Pa(n), psi) - reduced_pressure(sol.pressure_Pa(p), psi);
      q(i, j) = (-f.conductance_per_Pa * dp + f.couette_m3_per_s * th) / g.dy_m;
    }
  return q;
}

}  // namespace tribo::lubrication
