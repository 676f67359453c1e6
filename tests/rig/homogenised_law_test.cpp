// The homogenised law (rig/homogenised_law.h) and its table (rig/law_table.h): the Fritsch–Carlson
// interpolant, the law.json reader, the dry limit against the Coulomb + junction-locus rig, the
// squeeze film's linear drain, Petroff's full-film shear, lift over slip distance, Jaeger's flash
// temperature (thesis (5.2.1)) and the composition with catalogue effects. Tables are built here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact/junction_locus.h"
#include "rig/composite_law.h"
#include "rig/friction_model.h"
#include "rig/homogenised_law.h"
#include "rig/law_table.h"
#include "rig/steady_sliding.h"
#include "rig/parameters.h"
#include "rig/simulator.h"

namespace tribo::rig {
namespace {

// ---- helpers ------------------------------------------------------------------------------------

// The thesis junction locus of the catalogue's rate_dependent_static defaults (μs,max = 0.55,
// α = 25, n = 1.25, μs = 0.26 at φ̇ = 0.0785 1/s; thesis §5.1).
contact::JunctionLocus thesis_locus() {
  FrictionModel m;
  m.add("rate_dependent_static");
  return *junction_locus(m);
}

// A table whose solid load is linear in h̄, N_s = k_s (h_b − h̄), over [h_f, h_b]; the real area
// falls linearly to 0 at the 7th of 10 nodes and stays 0; lift L and squeeze K constant; the
// shear column is Petroff's A0/h̄.
struct LinearSpec {
  double h_front_m = 1e-7, h_back_m = 1e-6;
  double stiffness_N_per_m = 2.5e8;          // k_s = −dN_s/dh̄
  double area_front_m2 = 1e-7;
  double lift_m = 1e5;                       // L
  double squeeze_m = 1e8;                    // K
  double nominal_area_m2 = 7.126e-5;         // A0: π (4.7625 mm)²
  double viscosity_Pa_s = 0.021;
  double gamma_per_K = 0.03;
};

LawTable linear_table(const LinearSpec& s, int nodes = 10) {
  LawTable t;
  t.pin.shape = "flat";
  t.pin.radius_m = 4.7625e-3;
  t.pin.nominal_area_m2 = s.nominal_area_m2;
  t.pin.normal_load_N = 93.857;
  t.lubricant = {s.viscosity_Pa_s, s.gamma_per_K, 300.15};
  t.thermal = {46.0, 52.0, 1.2e-5, 1.9};
  t.junction.locus = thesis_locus();
  t.junction.interface_shear_strength_Pa = 2.2e8;
  const int zero_from = 6;  // A_r = 0 from this node on
  for (int i = 0; i < nodes; ++i) {
    const double h = i + 1 == nodes ? s.h_back_m : s.h_front_m + (s.h_back_m - s.h_front_m) * i / (nodes - 1);
    t.separation_m.push_back(h);
    t.solid_load_N.push_back(s.stiffness_N_per_m * (s.h_back_m - h));
    t.real_area_m2.push_back(i >= zero_from ? 0.0 : s.area_front_m2 * (zero_from - i) / zero_from);
    t.lift_per_eta_u_m.push_back(s.lift_m);
    t.squeeze_per_eta_m.push_back(s.squeeze_m);
    t.shear_per_eta_u_m.push_back(s.nominal_area_m2 / h);
  }
  return t;
}

// A thesis-like table: N_s = N0 (1 − x)³ over x = (h̄ − h_f)/(h_b − h_f), A_r = N_s / H with
// H = τ_i / 0.12 (so μk ≈ 0.12 at the nodes), Appendix III's squeeze coefficient for a flat disc of
// the slider radius, K = 3π R⁴ / (2 h̄³), a lift falling as 1/h̄ and Petroff's shear A0/h̄.
LawTable thesis_like_table(double viscosity_Pa_s) {
  LawTable t = linear_table(LinearSpec{}, 3);
  t.lubricant.viscosity_Pa_s = viscosity_Pa_s;
  t.separation_m.clear();
  t.solid_load_N.clear();
  t.real_area_m2.clear();
  t.lift_per_eta_u_m.clear();
  t.squeeze_per_eta_m.clear();
  t.shear_per_eta_u_m.clear();
  const double hf = 5e-8, hb = 1.5e-6, n0 = 400.0, hardness = 2.2e8 / 0.12, r = 4.7625e-3;
  const int nodes = 30;
  for (int i = 0; i < nodes; ++i) {
    const double x = static_cast<double>(i) / (nodes - 1), h = hf + (hb - hf) * x;
    const double ns = i + 1 == nodes ? 0.0 : n0 * std::pow(1.0 - x, 3);
    t.separation_m.push_back(h);
    t.solid_load_N.push_back(ns);
    t.real_area_m2.push_back(ns / hardness);
    t.lift_per_eta_u_m.push_back(0.02 / h);  // 2e4 m at 1 µm
    t.squeeze_per_eta_m.push_back(3.0 * std::numbers::pi * std::pow(r, 4) / (2.0 * h * h * h));
    t.shear_per_eta_u_m.push_back(t.pin.nominal_area_m2 / h);
  }
  return t;
}

nlohmann::json to_json(const LawTable& t) {
  const auto& l = t.junction.locus;
  return {
      {"format", "tribo-law-1"},
      {"provenance", {{"tool", "homogenised_law_test"}, {"anything", {1, 2, 3}}}},
      {"pin", {{"shape", t.pin.shape}, {"radius_m", t.pin.radius_m}, {"nominal_area_m2", t.pin.nominal_area_m2},
               {"normal_load_N", t.pin.normal_load_N}}},
      {"lubricant", {{"viscosity_Pa_s", t.lubricant.viscosity_Pa_s},
                     {"temperature_viscosity_per_K", t.lubricant.temperature_viscosity_per_K},
                     {"reference_temperature_K", t.lubricant.reference_temperature_K}}},
      {"thermal", {{"slider_conductivity_W_per_m_K", t.thermal.slider_conductivity_W_per_m_K},
                   {"disc_conductivity_W_per_m_K", t.thermal.disc_conductivity_W_per_m_K},
                   {"slider_diffusivity_m2_per_s", t.thermal.slider_diffusivity_m2_per_s},
                   {"time_constant_s", t.thermal.time_constant_s}}},
      {"junction", {{"alpha", l.alpha}, {"n", l.n}, {"sigma0_over_tau_i", l.sigma0_over_tau_i}, {"location_per_s", l.location_per_s},
                    {"strain_rate_index_m", l.strain_rate_index_m}, {"reference_load_rate_per_s", l.reference_load_rate_per_s},
                    {"interface_shear_strength_Pa", t.junction.interface_shear_strength_Pa}}},
      {"table", {{"separation_m", t.separation_m}, {"solid_load_N", t.solid_load_N}, {"real_area_m2", t.real_area_m2},
                 {"lift_per_eta_u_m", t.lift_per_eta_u_m}, {"squeeze_per_eta_m", t.squeeze_per_eta_m},
                 {"shear_per_eta_u_m", t.shear_per_eta_u_m},
                 {"solid_load_standard_error_N", std::vector<double>(t.separation_m.size(), 0.1)}}},
      {"stribeck", nlohmann::json::array({{{"U_m_per_s", 0.01}, {"mu", 0.1}, {"fluid_share", 0.2}, {"separation_m", 3e-7}}})},
  };
}

std::filesystem::path write_json(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "tribo_rig_law_tests";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

// Expects read_law_table to throw std::invalid_argument whose message holds the file and fragments,
// for a file of the bytes `text` (malformed JSON, or numbers a JSON document cannot hold).
void expect_text_rejected(const std::string& name, const std::string& text, std::initializer_list<std::string> fragments) {
  const auto path = write_json(name, text);
  try {
    read_law_table(path);
    ADD_FAILURE() << "accepted " << name;
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path.string()), std::string::npos) << msg;
    for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
  }
}

// The same for a document.
void expect_rejected(const std::string& name, const nlohmann::json& doc, std::initializer_list<std::string> fragments) {
  expect_text_rejected(name, doc.dump(), fragments);
}

FrictionContext context_at(std::span<const double> state, double speed_m_per_s, double load_N) {
  FrictionContext c;
  c.phase = speed_m_per_s > 0.0 ? Phase::slip : Phase::stick;
  c.slip_direction = speed_m_per_s > 0.0 ? 1 : 0;
  c.relative_speed_m_per_s = speed_m_per_s;
  c.normal_load_N = load_N;
  c.tangential_load_rate_per_s = 0.0785;
  c.state = state;
  return c;
}

// ---- MonotoneTable (Fritsch & Carlson 1980) -----------------------------------------------------

TEST(MonotoneTable, ReproducesTheNodesExactly) {
  const std::vector<double> x = {0.0, 0.3, 0.35, 1.0, 2.5, 2.6}, y = {1.0, -2.0, 4.0, 4.0, 0.5, 7.0};
  const MonotoneTable t(x, y);
  // A Hermite cubic interpolates its node values by construction: exact equality.
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(t.value(x[i]), y[i]) << "node " << i;
}

TEST(MonotoneTable, MonotoneDataGiveAMonotoneNonNegativeInterpolant) {
  // A steep drop to zero between flat stretches: where a C² spline overshoots below 0, Fritsch &
  // Carlson's interpolant stays non-increasing and ≥ 0 (their Theorem: α² + β² ≤ 9 suffices).
  const std::vector<double> x = {0.0, 1.0, 2.0, 2.1, 2.2, 4.0, 7.0, 7.5}, y = {5.0, 5.0, 4.9, 1.0, 0.02, 0.01, 0.0, 0.0};
  const MonotoneTable t(x, y, "separation_m");
  double previous = t.value(0.0);
  for (int i = 1; i <= 20000; ++i) {
    const double xi = 7.5 * i / 20000.0, v = t.value(xi);
    ASSERT_LE(v, previous) << "x = " << xi;  // exact: monotone per interval, clamped to its end values
    ASSERT_GE(v, 0.0) << "x = " << xi;
    ASSERT_LE(t.slope(xi), 1e-12 * 5.0 / 0.1) << "x = " << xi;  // slope ≤ 0 up to rounding of the derivative formula
    previous = v;
  }
}

TEST(MonotoneTable, IsExactOnLinearData) {
  const std::vector<double> x = {1e-7, 1.3e-7, 2e-7, 5e-7, 5.5e-7, 1e-6};
  std::vector<double> y;
  for (double xi : x) y.push_back(3.0 - 2e6 * xi);
  const MonotoneTable t(x, y);
  for (int i = 0; i <= 1000; ++i) {
    const double xi = 1e-7 + 9e-7 * i / 1000.0;
    // All slopes equal Δ, a = b = 1: the cubic is the line; rounding only (1e-14 of the range 1.8).
    EXPECT_NEAR(t.value(xi), 3.0 - 2e6 * xi, 1e-14 * 2.0);
    EXPECT_NEAR(t.slope(xi), -2e6, 1e-12 * 2e6);
  }
}

TEST(MonotoneTable, QueryOutsideTheRangeThrowsNamingTheAxisAndNeverExtrapolates) {
  const MonotoneTable t({1.0, 2.0, 3.0}, {3.0, 2.0, 1.0}, "separation_m");
  for (double bad : {0.999, 3.001, std::nan("")}) {
    try {
      t.value(bad);
      ADD_FAILURE() << "extrapolated at " << bad;
    } catch (const std::out_of_range& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("separation_m"), std::string::npos) << msg;
      EXPECT_NE(msg.find("[1, 3]"), std::string::npos) << msg;
    }
    EXPECT_THROW(t.slope(bad), std::out_of_range);
  }
  EXPECT_EQ(t.value(3.0), 1.0);  // the ends themselves are inside
  EXPECT_THROW(MonotoneTable({1.0, 1.0, 2.0}, {0.0, 1.0, 2.0}), std::invalid_argument);
}

// ---- law.json reader ------------------------------------------------------------------------------

TEST(LawTableReader, ReadsEveryFieldAndIgnoresUnknownKeys) {
  const LawTable t = linear_table(LinearSpec{});
  const auto path = write_json("good.json", to_json(t).dump(2));
  const LawTable r = read_law_table(path);
  EXPECT_EQ(r.source, path.string());
  EXPECT_EQ(r.pin.shape, "flat");
  EXPECT_EQ(r.pin.nominal_area_m2, t.pin.nominal_area_m2);
  EXPECT_EQ(r.lubricant.viscosity_Pa_s, 0.021);
  EXPECT_EQ(r.thermal.time_constant_s, 1.9);
  EXPECT_EQ(r.junction.locus.location_per_s, t.junction.locus.location_per_s);  // JSON round trip of a double is exact
  EXPECT_EQ(r.junction.interface_shear_strength_Pa, 2.2e8);
  EXPECT_EQ(r.separation_m, t.separation_m);
  EXPECT_EQ(r.solid_load_N, t.solid_load_N);
  EXPECT_EQ(r.shear_per_eta_u_m, t.shear_per_eta_u_m);
}

TEST(LawTableReader, MalformedFilesNameTheKeyAndTheReason) {
  const nlohmann::json good = to_json(linear_table(LinearSpec{}));
  {
    nlohmann::json d = good;
    d["table"].erase("shear_per_eta_u_m");
    expect_rejected("missing_column.json", d, {"table.shear_per_eta_u_m", "missing"});
  }
  {
    nlohmann::json d = good;
    d["table"]["real_area_m2"].erase(d["table"]["real_area_m2"].size() - 1);
    expect_rejected("unequal.json", d, {"table.real_area_m2", "same length"});
  }
  {
    nlohmann::json d = good;
    d["table"]["separation_m"][2] = d["table"]["separation_m"][1];
    expect_rejected("not_increasing.json", d, {"table.separation_m[2]", "strictly increasing"});
  }
  {
    nlohmann::json d = good;
    d["table"]["lift_per_eta_u_m"][3] = -1.0;
    expect_rejected("negative.json", d, {"table.lift_per_eta_u_m[3]", ">= 0"});
  }
  {
    nlohmann::json d = good;
    d["table"]["squeeze_per_eta_m"][4] = nullptr;  // how JSON writers spell NaN
    expect_rejected("nan.json", d, {"table.squeeze_per_eta_m[4]", "NaN"});
  }
  {
    nlohmann::json d = good;
    d["lubricant"]["viscosity_Pa_s"] = "thick";
    expect_rejected("type.json", d, {"lubricant.viscosity_Pa_s", "must be a number"});
  }
  {
    nlohmann::json d = good;
    d["table"]["solid_load_N"][5] = 1e4;
    expect_rejected("increasing_load.json", d, {"table.solid_load_N[5]", "must not increase"});
  }
  {
    nlohmann::json d = good;
    d["format"] = "tribo-law-9";
    expect_rejected("format.json", d, {"format", "tribo-law-1"});
  }
  expect_rejected("short.json", [&] {
    nlohmann::json d = good;
    for (auto& [key, column] : d["table"].items()) column = std::vector<double>(column.begin(), column.begin() + 2);
    return d;
  }(), {"table.separation_m", "at least 3"});
  expect_text_rejected("broken.json", "{\"format\": ", {"malformed JSON"});
  // A number no double holds is valid JSON syntax that nlohmann reports as out_of_range, not as a
  // parse error: it must end as the same named error (the law_table fuzzer, 2026-11-28).
  expect_text_rejected("overflow.json", "{\"format\": \"tribo-law-1\", \"pin\": {\"radius_m\": 3.7e1111}}",
                       {"overflow.json: malformed JSON", "number overflow"});
  EXPECT_THROW(read_law_table(std::filesystem::temp_directory_path() / "tribo_rig_law_tests" / "does_not_exist.json"),
               std::invalid_argument);
}

TEST(HomogenisedBase, LoadOutsideTheSolidLoadRangeIsRejectedNamingNormalLoad) {
  const LawTable t = linear_table(LinearSpec{});  // N_s(front) = 2.5e8 × 0.9e-6 = 225 N
  for (double w : {0.0, -1.0, 226.0}) {
    try {
      HomogenisedBase base(t, w);
      ADD_FAILURE() << "accepted W = " << w;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("normal_load_N"), std::string::npos) << e.what();
    }
  }
  // The initial film carries W: N_s(h̄0) = W to rounding (bisection to the last bit of h̄).
  const HomogenisedBase base(t, 93.857);
  EXPECT_NEAR(base.solid_load_N(base.initial_separation_m()), 93.857, 1e-12 * 93.857);
  EXPECT_NEAR(base.initial_separation_m(), 1e-6 - 93.857 / 2.5e8, 1e-12 * 1e-6);
}

// ---- dry limit: the homogenised rig is the Coulomb + junction-locus rig --------------------------

TEST(HomogenisedLaw, DryLimitReproducesCoulombWithTheJunctionLocus) {
  // η0 = 0: h̄ stays at h̄0 with N_s(h̄0) = W, so F_static = μs(φ̇) W and F_k = τ_i A_r(h̄0) = μk W —
  // the Coulomb law with rate_dependent_static on the same locus (effect.h channel 1).
  const RigParameters rig;
  const auto base = std::make_shared<const HomogenisedBase>(thesis_like_table(0.0), rig.normal_load_N);
  FrictionModel homogenised;
  homogenised.baseline.homogenised = base;
  const double h0 = base->initial_separation_m();
  const double mu_k = base->table().junction.interface_shear_strength_Pa * base->real_area_m2(h0) / rig.normal_load_N;
  ASSERT_GT(mu_k, 0.05);
  ASSERT_LT(mu_k, 0.2);
  FrictionModel classic = coulomb(0.55, mu_k);
  classic.add("rate_dependent_static");  // defaults = thesis_locus() used in the table

  // v = 2.8e-2 in/s (thesis Fig 5.2.1). The first breakaway needs μs W/(k v) ≈ 3.3 s of loading, so
  // 2 s would show none: run 12 s for three or more stick-slip cycles.
  SimulationOptions opt;
  opt.duration_s = 12.0;
  const Drive drive = Drive::constant(7.112e-4);
  const auto law_h = make_friction_law(homogenised);
  const auto law_c = make_friction_law(classic);
  EXPECT_EQ(law_h->name(), "homogenised");
  const SimulationResult rh = simulate(rig, drive, *law_h, opt), rc = simulate(rig, drive, *law_c, opt);
  ASSERT_TRUE(rh.summary.completed) << rh.summary.message;
  ASSERT_TRUE(rc.summary.completed) << rc.summary.message;
  std::vector<Event> bh, bc;
  for (const Event& e : rh.events) if (e.kind == EventKind::breakaway) bh.push_back(e);
  for (const Event& e : rc.events) if (e.kind == EventKind::breakaway) bc.push_back(e);
  ASSERT_GE(bc.size(), 3u);
  ASSERT_EQ(bh.size(), bc.size());
  for (std::size_t i = 0; i < bc.size(); ++i) {
    // The two runs differ only by the extra (inert) state in CVODE's error control: 1e-6 relative.
    EXPECT_NEAR(bh[i].t_s, bc[i].t_s, 1e-6 * bc[i].t_s) << "breakaway " << i;
    EXPECT_NEAR(bh[i].mu, bc[i].mu, 1e-6 * bc[i].mu) << "breakaway " << i;
  }
  // The film cannot move: the dry rate is exactly 0 at any speed (algebraic limit, no stiffness).
  std::vector<double> state(law_h->state_size()), rates(law_h->state_size());
  law_h->initial_state(state);
  EXPECT_EQ(state[0], h0);
  law_h->state_rates(context_at(state, 0.3, rig.normal_load_N), rates);
  EXPECT_EQ(rates[0], 0.0);
  EXPECT_GT(rates[1], 0.0);  // the contact still heats (Jaeger), but η = 0 has nothing to thin
}

// ---- squeeze film and full film -------------------------------------------------------------------

TEST(HomogenisedLaw, StuckFilmDrainsAtTheLinearisedSqueezeRate) {
  // U = 0, N_s = k_s (h_b − h̄), K constant: η K dh̄/dt = N_s(h̄) − W = −k_s (h̄ − h̄0), so a deviation δ
  // decays as exp(−t k_s/(η K)) (Reynolds squeeze film, thesis Appendix III, at the pin's scale).
  const LinearSpec s;
  const double W = 93.857;
  const HomogenisedLaw law(std::make_shared<const HomogenisedBase>(linear_table(s), W));
  const double h0 = law.base().initial_separation_m();
  for (double delta : {-2e-9, 1e-9, 5e-8}) {
    const std::vector<double> state = {h0 + delta, 0.0};
    std::vector<double> rates(2);
    law.state_rates(context_at(state, 0.0, W), rates);
    const double expected = -s.stiffness_N_per_m * delta / (s.viscosity_Pa_s * s.squeeze_m);
    // PCHIP is exact on the linear N_s; rounding of N_s(h̄0) − W (≈1e-14 W) against k_s δ ≥ 0.5 N.
    EXPECT_NEAR(rates[0], expected, 1e-9 * std::abs(expected)) << "delta = " << delta;
    EXPECT_EQ(rates[1], 0.0);  // no power while stuck, ΔT = 0 stays
  }
  EXPECT_NEAR(law.base().film_relaxation_time_s(h0, 0.0), s.viscosity_Pa_s * s.squeeze_m / s.stiffness_N_per_m,
              1e-12 * s.viscosity_Pa_s * s.squeeze_m / s.stiffness_N_per_m);
}

TEST(HomogenisedLaw, SlidingFilmSettlesOverASlipDistanceThatTendsToKOverTheLiftSlope) {
  // Linearising η K dh̄/dt = N_s + η U L − W with N_s = k_s (h_b − h̄), L = L0 − L1 h̄ about the balance
  // gives t_h = η K / (k_s + η U L1): time-like (t_h → η K / k_s) while the solids dominate, and a
  // settling distance U t_h → K / L1 independent of U once the lift does — the thesis' decay with
  // slip distance (§5.2a). PCHIP is exact on these linear columns (rounding only).
  const LinearSpec s;
  LawTable t = linear_table(s);
  const double l1 = 4e12;  // 1/m²: the lift falls by 3.6e6 m⁻¹ over the table, stays > 0
  for (std::size_t i = 0; i < t.separation_m.size(); ++i) t.lift_per_eta_u_m[i] = 4e6 - l1 * t.separation_m[i];
  const HomogenisedBase base(t, 93.857);
  const double h = 0.5 * (s.h_front_m + s.h_back_m), eta_k = s.viscosity_Pa_s * s.squeeze_m;
  for (double u : {0.0, 1e-3, 1.0, 1e3}) {
    const double expected = eta_k / (s.stiffness_N_per_m + s.viscosity_Pa_s * u * l1);
    EXPECT_NEAR(base.film_relaxation_time_s(h, 0.0, u), expected, 1e-12 * expected) << "U = " << u;
  }
  const double far = 1e6;  // η U L1 = 8.4e16 ≫ k_s: within k_s/(η U L1) = 3e-9 of K/L1
  EXPECT_NEAR(far * base.film_relaxation_time_s(h, 0.0, far), s.squeeze_m / l1, 1e-8 * s.squeeze_m / l1);
}

TEST(HomogenisedLaw, FullFilmShearIsPetroff) {
  // Where the solid contact has vanished (A_r = 0 at the last four nodes) the friction is the
  // viscous shear of a film of thickness h̄ over the pin face: Petroff, F = η U A0 / h̄.
  const LinearSpec s;
  const LawTable t = linear_table(s);
  const HomogenisedLaw law(std::make_shared<const HomogenisedBase>(t, 93.857));
  for (std::size_t i = 6; i < t.separation_m.size(); ++i) {
    const double h = t.separation_m[i];
    for (double u : {1e-3, 0.1, 2.0}) {
      const std::vector<double> state = {h, 0.0};
      const double petroff = s.viscosity_Pa_s * u * s.nominal_area_m2 / h;
      EXPECT_NEAR(law.kinetic_force_N(context_at(state, u, 93.857)), petroff, 1e-12 * petroff) << "h = " << h;
    }
  }
}

// ---- lift over slip distance ----------------------------------------------------------------------

TEST(HomogenisedLaw, FilmSlopeAlongSlipDistanceDependsOnSpeedOnlyThroughWOverU) {
  // dh̄/ds = (dh̄/dt)/|U| = L/K − (W − N_s(h̄)) / (η K |U|): the lift term is the same at every speed
  // (the slip-distance-governed build-up of thesis §5.2a); only the drain term carries 1/|U|.
  const LinearSpec s;
  const double W = 93.857;
  const HomogenisedLaw law(std::make_shared<const HomogenisedBase>(linear_table(s), W));
  const double h = law.base().initial_separation_m() + 3e-8;
  const double drain = (W - s.stiffness_N_per_m * (s.h_back_m - h)) / (s.viscosity_Pa_s * s.squeeze_m);  // m/s
  for (double u : {0.005, 0.02, 0.3}) {
    const std::vector<double> state = {h, 0.0};
    std::vector<double> rates(2);
    law.state_rates(context_at(state, u, W), rates);
    const double expected = s.lift_m / s.squeeze_m - drain / u;
    EXPECT_NEAR(rates[0] / u, expected, 1e-9 * std::abs(expected)) << "U = " << u;
  }
}

TEST(HomogenisedLaw, LiftRaisesTheFilmAlongTheClosedFormInSlipDistance) {
  // Constant L, K, linear N_s, γ = 0 (η constant): dh̄/dt = [η U L − k_s (h̄ − h̄0)] / (η K), so
  //   h̄(s) = h̄0 + (η U L / k_s) (1 − exp(−k_s s / (η K U))),   s = U t,
  // whose initial slope L/K is the same at every speed. RK4 on the law's state_rates at two speeds.
  LinearSpec s;
  s.gamma_per_K = 0.0;
  const double W = 93.857;
  const HomogenisedLaw law(std::make_shared<const HomogenisedBase>(linear_table(s), W));
  const double h0 = law.base().initial_separation_m();
  const double eta = s.viscosity_Pa_s, tau = eta * s.squeeze_m / s.stiffness_N_per_m;
  for (double u : {0.01, 0.02}) {
    std::vector<double> y = {h0, 0.0};
    auto f = [&](const std::vector<double>& state) {
      std::vector<double> r(2);
      law.state_rates(context_at(state, u, W), r);
      return r;
    };
    const int steps = 2000;
    const double dt = 5.0 * tau / steps;
    for (int i = 0; i < steps; ++i) {
      const auto k1 = f(y);
      std::vector<double> y2 = {y[0] + 0.5 * dt * k1[0], y[1] + 0.5 * dt * k1[1]};
      const auto k2 = f(y2);
      std::vector<double> y3 = {y[0] + 0.5 * dt * k2[0], y[1] + 0.5 * dt * k2[1]};
      const auto k3 = f(y3);
      std::vector<double> y4 = {y[0] + dt * k3[0], y[1] + dt * k3[1]};
      const auto k4 = f(y4);
      for (int j = 0; j < 2; ++j) y[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
      const double t = (i + 1) * dt, slip = u * t;
      const double rise = eta * u * s.lift_m / s.stiffness_N_per_m;
      const double exact = h0 + rise * (1.0 - std::exp(-s.stiffness_N_per_m * slip / (eta * s.squeeze_m * u)));
      // RK4 global error ~ (dt/τ)⁴ ≈ 4e-11 of the rise.
      ASSERT_NEAR(y[0], exact, 1e-9 * rise) << "U = " << u << ", s = " << slip;
    }
    std::vector<double> r(2);
    const std::vector<double> start = {h0, 0.0};
    law.state_rates(context_at(start, u, W), r);
    EXPECT_NEAR(r[0] / u, s.lift_m / s.squeeze_m, 1e-9 * s.lift_m / s.squeeze_m);  // same initial dh̄/ds
  }
}

// ---- Jaeger's flash temperature -------------------------------------------------------------------

TEST(HomogenisedLaw, JaegerTemperatureIsTheThesisFormulaInSIAndRisesWithSpeed) {
  const LawTable t = thesis_like_table(0.021);
  const HomogenisedLaw law(std::make_shared<const HomogenisedBase>(t, 93.857));
  const double h = law.base().initial_separation_m() * 1.05, dT = 3.0;
  const double a = law.base().real_area_m2(h);
  ASSERT_GT(a, HomogenisedBase::kJaegerAreaFloorFraction * t.pin.nominal_area_m2);
  double previous = 0.0;
  for (double u : {1e-3, 1e-2, 0.1, 1.0}) {
    const std::vector<double> state = {h, dT};
    const FrictionContext c = context_at(state, u, 93.857);
    const double fk = law.kinetic_force_N(c), p = fk * u;
    // Thesis (5.2.1) with μk v N_s g/J → friction power P (W), b = √κ, ξ1 slider, ξ2 disc.
    const double b = std::sqrt(t.thermal.slider_diffusivity_m2_per_s);
    const double jaeger = p * b /
                          (1.9 * std::sqrt(a) * (1.1 * t.thermal.disc_conductivity_W_per_m_K * b +
                                                 0.7 * t.thermal.slider_conductivity_W_per_m_K * std::pow(a, 0.25) * std::sqrt(u)));
    EXPECT_NEAR(law.base().jaeger_temperature_rise_K(p, h, u), jaeger, 1e-12 * jaeger) << "U = " << u;
    std::vector<double> rates(2);
    law.state_rates(c, rates);
    EXPECT_NEAR(rates[1], (jaeger - dT) / t.thermal.time_constant_s, 1e-12 * std::abs(jaeger - dT) / t.thermal.time_constant_s);
    EXPECT_GT(jaeger, previous) << "U = " << u;
    previous = jaeger;
  }
  // The film thins as it heats: η(ΔT) = η0 exp(−γ ΔT) (lubrication/viscosity.h).
  EXPECT_NEAR(law.base().viscosity_Pa_s(dT), 0.021 * std::exp(-0.03 * dT), 1e-15);
}

// ---- composition with the effect catalogue --------------------------------------------------------

TEST(HomogenisedLaw, CompositeWithoutEffectsEqualsTheBareLawAndEffectsStackOnTop) {
  const double W = 93.857;
  const auto base = std::make_shared<const HomogenisedBase>(thesis_like_table(0.021), W);
  const HomogenisedLaw bare(base);
  FrictionModel m;
  m.baseline.homogenised = base;
  const auto composite = make_friction_law(m);
  ASSERT_EQ(composite->state_size(), 2u);
  const std::vector<double> state = {base->initial_separation_m() * 1.1, 4.0};
  for (double u : {0.0, 0.01, 0.5}) {
    const FrictionContext c = context_at(state, u, W);
    EXPECT_EQ(composite->kinetic_force_N(c), bare.kinetic_force_N(c));
    EXPECT_EQ(composite->static_limit_N(c), bare.static_limit_N(c));
    std::vector<double> r1(2), r2(2);
    composite->state_rates(c, r1);
    bare.state_rates(c, r2);
    EXPECT_EQ(r1, r2);
  }
  // viscous_friction adds c U (channel 4) and slip_transient its state after the base's two.
  m.set("viscous_friction", "coefficient_N_s_per_m", 40.0);
  m.add("slip_transient");
  const auto stacked = make_friction_law(m);
  ASSERT_EQ(stacked->state_size(), 3u);
  std::vector<double> s3(3);
  stacked->initial_state(s3);
  EXPECT_EQ(s3[0], base->initial_separation_m());
  EXPECT_EQ(s3[1], 0.0);
  const std::vector<double> with_effect_state = {state[0], state[1], 0.0};
  const FrictionContext c = context_at(with_effect_state, 0.01, W);
  EXPECT_NEAR(stacked->kinetic_force_N(c), bare.kinetic_force_N(context_at(state, 0.01, W)) + 40.0 * 0.01, 1e-12 * W);
  // The table carries the static locus: listing rate_dependent_static as well is a config error.
  m.add("rate_dependent_static");
  EXPECT_THROW(make_friction_law(m), std::invalid_argument);
}

TEST(HomogenisedLaw, RateAndStateHealingRaisesTheStaticLimitOnTheSolidLoad) {
  // Channel 5 on the homogenised base: F_static = χ (μs(φ̇) + Δμs) N_s(h̄), with rate_and_state's
  // Δμs = a ln(V_r(v)/V0) + b ln(V0 θ/D_c) (rig/effects/rate_and_state.h) after the base's state.
  const double W = 93.857;
  const auto base = std::make_shared<const HomogenisedBase>(thesis_like_table(0.021), W);
  FrictionModel m;
  m.baseline.homogenised = base;
  m.add("rate_and_state");
  const auto law = make_friction_law(m);
  ASSERT_EQ(law->state_size(), 3u);
  const double a = m.get("rate_and_state", "a"), b = m.get("rate_and_state", "b");
  const double dc = m.get("rate_and_state", "decay_distance_m"), v0 = m.get("rate_and_state", "reference_speed_m_per_s");
  std::vector<double> initial(3);
  law->initial_state(initial);
  EXPECT_EQ(initial[2], dc / v0);  // steady sliding at V0
  const double h = base->initial_separation_m() * 1.1;
  const std::vector<double> aged = {h, 4.0, 10.0 * dc / v0};
  FrictionContext c = context_at(aged, 0.0, W);
  c.drive_speed_m_per_s = v0;
  const double v_eps = 1e-3 * v0;
  const double increment = a * std::log(std::sqrt(v0 * v0 + v_eps * v_eps) / v0) + b * std::log(10.0);
  const double expected = (base->static_coefficient(c) + increment) * base->solid_load_N(h);
  EXPECT_NEAR(law->static_limit_N(c), expected, 1e-12 * expected);
}

TEST(HomogenisedLaw, LubricatedThesisLikeRigBreaksAwayOnTheLocusWithTheFilmAtRest) {
  // With η = 0.021 Pa s the stuck film sits at its equilibrium (no lift while U = 0), so the first
  // breakaway is again μs(φ̇) N_s(h̄0)/W = μs(φ̇) (thesis (3.1.24)); after it, lift opens the film.
  const RigParameters rig;
  const auto base = std::make_shared<const HomogenisedBase>(thesis_like_table(0.021), rig.normal_load_N);
  const double h0 = base->initial_separation_m();
  // Film time constant t_h = η K/(−dN_s/dh̄) at h̄0, against the rig period 2π/ω_n ≈ 0.062 s.
  // Not stiff for the Adams integrator: t_h = 0.73 s here, an order above the period.
  EXPECT_GT(base->film_relaxation_time_s(h0, 0.0), 2.0 * std::numbers::pi / rig.natural_frequency_rad_per_s());
  const HomogenisedLaw law(base);
  SimulationOptions opt;
  opt.duration_s = 4.0;
  const double v = 7.112e-4;
  const SimulationResult r = simulate(rig, Drive::constant(v), law, opt);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  ASSERT_FALSE(r.events.empty());
  const double phi_dot = rig.stiffness_N_per_m * v / rig.normal_load_N;
  const double mu_s = contact::static_friction_from_load_rate(thesis_locus(), phi_dot);
  EXPECT_NEAR(r.events.front().mu, mu_s, 1e-8);  // CVODE root location, as in effects_test
}


// Steady sliding's temperature is a fixed point of Jaeger's ΔT_J(ΔT). A viscous film that heats
// itself has ΔT_J ∝ η(ΔT) ∝ e^{−γΔT}, slope −γ ΔT at the fixed point: beyond γΔT = 3 the damped
// iteration ΔT ← (ΔT + ΔT_J)/2 cycles, and steady_sliding bisects instead. Every speed of a sweep
// through that range must settle on a true fixed point.
TEST(SteadySliding, EveryStateIsATemperatureFixedPointWhereTheDampedIterationWouldCycle) {
  LinearSpec spec;
  spec.viscosity_Pa_s = 2.0;
  spec.lift_m = 10.0;
  const HomogenisedBase base(linear_table(spec), 50.0);
  int hot = 0;
  for (int k = 0; k <= 30; ++k) {
    const double u = 1e-3 * std::pow(1e4, k / 30.0);
    SteadySliding s;
    try {
      s = steady_sliding(base, u);
    } catch (const std::out_of_range&) {
      break;  // the film has left the table
    }
    ASSERT_TRUE(s.converged) << "U = " << u << ": " << s.message;
    const double target = base.jaeger_temperature_rise_K((s.solid_friction_N + s.fluid_shear_N) * u, s.separation_m, u);
    EXPECT_NEAR(s.temperature_rise_K, target, 1e-8 * (1.0 + target)) << "U = " << u;
    hot += spec.gamma_per_K * s.temperature_rise_K > 3.0 ? 1 : 0;
  }
  std::printf("%d speeds where the damped iteration alone would cycle (γΔT > 3)\n", hot);
  EXPECT_GT(hot, 0);
}

// ---- "tribo-law-2": the real area's shear over ηU (asperity-top EHL films) --------------------------

// The linear table with a shear table over ηU = 0, 1e-4, 1e-2 Pa m: τ_i, 0.9 τ_i, 0.6 τ_i at every
// separation, so that interpolation over h̄ is exact and over ηU its own rule shows.
LawTable filmed_table() {
  LawTable t = linear_table(LinearSpec{});
  t.eta_u_Pa_m = {0.0, 1e-4, 1e-2};
  const double tau = t.junction.interface_shear_strength_Pa;
  t.solid_shear_Pa.assign(t.separation_m.size(), {tau, 0.9 * tau, 0.6 * tau});
  t.film_share.assign(t.separation_m.size(), {0.0, 0.1, 0.4});
  return t;
}

nlohmann::json filmed_json(const LawTable& t) {
  nlohmann::json j = to_json(t);
  j["format"] = "tribo-law-2";
  j["table"]["eta_u_Pa_m"] = t.eta_u_Pa_m;
  j["table"]["solid_shear_Pa"] = t.solid_shear_Pa;
  j["table"]["film_share"] = t.film_share;
  return j;
}

TEST(LawTableReader, ReadsBothFormatsAndTheShearTableOfTheSecond) {
  const LawTable t = filmed_table();
  const LawTable r = read_law_table(write_json("filmed.json", filmed_json(t).dump()));
  EXPECT_EQ(r.eta_u_Pa_m, t.eta_u_Pa_m);
  EXPECT_EQ(r.solid_shear_Pa, t.solid_shear_Pa);
  EXPECT_EQ(r.film_share, t.film_share);
  EXPECT_TRUE(read_law_table(write_json("plain.json", to_json(t).dump())).eta_u_Pa_m.empty());  // "tribo-law-1"
}

TEST(LawTableReader, AMalformedShearTableNamesTheKeyAndTheReason) {
  const nlohmann::json good = filmed_json(filmed_table());
  {
    nlohmann::json d = good;
    d["table"]["eta_u_Pa_m"][0] = 1e-6;
    expect_rejected("axis_start.json", d, {"table.eta_u_Pa_m[0]", "must be 0"});
  }
  {
    nlohmann::json d = good;
    d["table"]["solid_shear_Pa"][3].erase(2);
    expect_rejected("short_row.json", d, {"table.solid_shear_Pa[3]", "entries"});
  }
  {
    nlohmann::json d = good;
    d["table"].erase("solid_shear_Pa");
    expect_rejected("no_shear.json", d, {"table.solid_shear_Pa", "missing"});
  }
  {
    LawTable no_axis = filmed_table();  // a film share built in code without its ηU axis
    no_axis.eta_u_Pa_m.clear();
    no_axis.solid_shear_Pa.clear();
    EXPECT_THROW(validate(no_axis), std::invalid_argument);
  }
  {
    nlohmann::json d = good;
    d["table"]["film_share"][2][1] = 1.5;
    expect_rejected("film_share.json", d, {"table.film_share[2][1]", "must not exceed 1"});
  }
  {
    nlohmann::json d = good;
    d["format"] = "tribo-law-3";
    expect_rejected("format3.json", d, {"format", "tribo-law-2"});
  }
}

// A ball's EHL film (homogenise/ball_film.h, rig/ball_film.h): "ball_film" holds the shares (up to
// 1) and per ηU node the films and tractions, null where a solve was left out; each node but
// ηU = 0 needs two shares to invert.
TEST(LawTableReader, ABallsFilmsComeOnePerSpeedNodeWithNullWhereASolveWasLeftOut) {
  nlohmann::json good = filmed_json(filmed_table());
  const std::size_t nodes = good["table"]["eta_u_Pa_m"].size();
  nlohmann::json films = nlohmann::json::array();
  for (std::size_t k = 0; k < nodes; ++k) {
    const double e = good["table"]["eta_u_Pa_m"][k].get<double>();
    nlohmann::json h = nlohmann::json::array(), f = nlohmann::json::array();
    for (double s : {0.01, 0.1, 1.0}) {
      h.push_back(k == 0 ? nlohmann::json(nullptr) : nlohmann::json(1e-7 * std::pow(s, -0.1) * (1.0 + k)));
      f.push_back(k == 0 ? nlohmann::json(nullptr) : nlohmann::json(0.1 * s));
    }
    films.push_back({{"eta_u_Pa_m", e}, {"central_film_m", h}, {"traction_N", f}});
  }
  films[1]["central_film_m"][2] = nullptr;  // left out: the node still has two
  good["ball_film"] = {{"share", {0.01, 0.1, 1.0}}, {"films", films}};
  const LawTable r = read_law_table(write_json("ball.json", good.dump()));
  ASSERT_TRUE(r.has_ball_film());
  EXPECT_EQ(r.ball_share, (std::vector<double>{0.01, 0.1, 1.0}));
  ASSERT_EQ(r.ball_central_film_m.size(), nodes);
  EXPECT_TRUE(std::isnan(r.ball_central_film_m[1][2]));
  EXPECT_EQ(r.ball_traction_N[2][1], 0.1 * 0.1);
  {
    nlohmann::json d = good;
    d["ball_film"]["share"][2] = 0.9;
    expect_rejected("ball_share.json", d, {"ball_film.share", "must end at 1"});
  }
  {
    nlohmann::json d = good;
    d["ball_film"]["films"][2]["eta_u_Pa_m"] = 7.0;
    expect_rejected("ball_node.json", d, {"ball_film.films[2].eta_u_Pa_m", "table.eta_u_Pa_m[2]"});
  }
  {
    nlohmann::json d = good;
    d["ball_film"]["films"][1]["traction_N"][0] = -1.0;
    expect_rejected("ball_negative.json", d, {"ball_film.films[1].traction_N[0]", "must be > 0 or null"});
  }
  {
    nlohmann::json d = good;
    d["ball_film"]["films"][1]["central_film_m"][1] = nullptr;
    expect_rejected("ball_one_share.json", d, {"ball_film.films[1]", "fewer than two shares"});
  }
  {
    nlohmann::json d = good;
    d["ball_film"]["films"][0]["traction_N"][1] = 0.5;
    expect_rejected("ball_at_rest.json", d, {"ball_film.films[0]", "no film at rest"});
  }
  {
    nlohmann::json d = good;
    d["ball_film"]["films"].erase(nodes - 1);
    expect_rejected("ball_short.json", d, {"ball_film.films", "entries"});
  }
}

// The kinetic force's solid part is τ̄(h̄, ηU) A_r(h̄): τ_i A_r at rest; at ηU = 1e-3 Pa m, halfway
// between 1e-4 and 1e-2 in ln ηU, 0.75 τ_i A_r (linear in ln ηU); at 5e-5, halfway between 0 and
// 1e-4 in ηU, 0.95 τ_i A_r; beyond 1e-2 the query is refused, naming the axis (never extrapolated).
TEST(HomogenisedLaw, FilmedShearScalesTheSolidKineticForceAndIsNeverExtrapolated) {
  const LawTable t = filmed_table();
  const HomogenisedBase base(t, 93.857);
  const HomogenisedLaw law(std::make_shared<const HomogenisedBase>(t, 93.857));
  const double h = t.separation_m[2], tau = t.junction.interface_shear_strength_Pa, eta = t.lubricant.viscosity_Pa_s;
  const std::vector<double> state = {h, 0.0};
  for (const auto& [eta_u, factor] : {std::pair{1e-3, 0.75}, std::pair{5e-5, 0.95}}) {
    const double u = eta_u / eta;
    const double viscous = eta * u * base.shear_per_eta_u_m(h);
    EXPECT_NEAR(law.kinetic_force_N(context_at(state, u, 93.857)), factor * tau * base.real_area_m2(h) + viscous, 1e-9 * tau * base.real_area_m2(h))
        << eta_u;
  }
  EXPECT_DOUBLE_EQ(base.solid_shear_Pa(h, 0.0), tau);
  EXPECT_NEAR(base.film_share(h, 1e-3), 0.25, 1e-12);  // the same rule: halfway in ln ηU
  EXPECT_NEAR(base.solid_kinetic_coefficient(state, 1e-3 / eta), 0.75 * tau * base.real_area_m2(h) / base.solid_load_N(h), 1e-12);
  try {
    law.kinetic_force_N(context_at(state, 2e-2 / eta, 93.857));
    ADD_FAILURE() << "a query beyond the ηU axis was answered";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("eta_u_Pa_m"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo::rig
