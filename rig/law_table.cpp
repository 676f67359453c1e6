#include "rig/law_table.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "rig/ball_film.h"
#include "rig/internal/exact_decimal.h"

namespace tribo::rig {
namespace {

using nlohmann::json;

using internal::exact_decimal;

std::string where(const std::string& source) { return "law table " + (source.empty() ? std::string("(in memory)") : source); }

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& reason) {
  throw std::invalid_argument(where(source) + ": key '" + key + "': " + reason);
}

// Reading: each accessor names the dotted key it reads.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  const json& member(const json& object, const std::string& parent, const std::string& key) const {
    const std::string dotted = parent.empty() ? key : parent + "." + key;
    if (!object.is_object()) fail(source_, parent, "is not a JSON object");
    const auto it = object.find(key);
    if (it == object.end()) fail(source_, dotted, "is missing");
    return *it;
  }
  const json& object(const json& parent_object, const std::string& parent, const std::string& key) const {
    const json& j = member(parent_object, parent, key);
    if (!j.is_object()) fail(source_, dotted(parent, key), "must be a JSON object");
    return j;
  }
  double number(const json& object, const std::string& parent, const std::string& key) const {
    return as_number(member(object, parent, key), dotted(parent, key));
  }
  double number_or(const json& object, const std::string& parent, const std::string& key, double fallback) const {
    if (object.find(key) == object.end()) return fallback;
    return number(object, parent, key);
  }
  std::string string_or(const json& object, const std::string& parent, const std::string& key, std::string fallback) const {
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_string()) fail(source_, dotted(parent, key), "must be a string");
    return it->get<std::string>();
  }
  std::vector<double> column(const json& object, const std::string& parent, const std::string& key) const {
    const json& j = member(object, parent, key);
    if (!j.is_array()) fail(source_, dotted(parent, key), "must be an array of numbers");
    std::vector<double> out;
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) out.push_back(as_number(j[i], dotted(parent, key) + "[" + std::to_string(i) + "]"));
    return out;
  }

 private:
  static std::string dotted(const std::string& parent, const std::string& key) { return parent.empty() ? key : parent + "." + key; }
  double as_number(const json& j, const std::string& key) const {
    // JSON has no NaN; a writer that emits null for NaN is caught here too.
    if (j.is_null()) fail(source_, key, "is null (NaN or missing value)");
    if (!j.is_number()) fail(source_, key, "must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(source_, key, "must be finite");
    return v;
  }
  std::string source_;
};

void require_finite(const std::string& source, const std::string& key, double v) {
  if (!std::isfinite(v)) fail(source, key, "must be finite (got " + exact_decimal(v) + ")");
}
void require_positive(const std::string& source, const std::string& key, double v) {
  require_finite(source, key, v);
  if (!(v > 0.0)) fail(source, key, "must be > 0 (got " + exact_decimal(v) + ")");
}
void require_non_negative(const std::string& source, const std::string& key, double v) {
  require_finite(source, key, v);
  if (!(v >= 0.0)) fail(source, key, "must be >= 0 (got " + exact_decimal(v) + ")");
}

enum class Sign { positive, non_negative };

void check_column(const std::string& source, const std::string& key, const std::vector<double>& c, Sign sign) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    const std::string k = key + "[" + std::to_string(i) + "]";
    if (sign == Sign::positive) require_positive(source, k, c[i]);
    else require_non_negative(source, k, c[i]);
  }
}

void check_non_increasing_to_zero(const std::string& source, const std::string& key, const std::vector<double>& c) {
  check_column(source, key, c, Sign::non_negative);
  for (std::size_t i = 1; i < c.size(); ++i) {
    if (c[i] > c[i - 1]) {
      fail(source, key + "[" + std::to_string(i) + "]", "must not increase with separation (" + exact_decimal(c[i - 1]) + " then " + exact_decimal(c[i]) + ")");
    }
  }
  if (c.back() != 0.0) fail(source, key, "last entry must be 0 (the contact vanishes at the largest separation), got " + exact_decimal(c.back()));
}

// An axis whose entries strictly increase.
void check_strictly_increasing(const std::string& source, const std::string& key, const std::vector<double>& c) {
  for (std::size_t i = 1; i < c.size(); ++i)
    if (!(c[i] > c[i - 1]))
      fail(source, key + "[" + std::to_string(i) + "]", "must be strictly increasing (" + exact_decimal(c[i - 1]) + " then " + exact_decimal(c[i]) + ")");
}

// A [separation][ηU] column: one row per separation, one entry per ηU node, each of `sign`.
void check_rows(const std::string& source, const std::string& key, const std::vector<std::vector<double>>& rows, std::size_t n,
                std::size_t eta_u_nodes, Sign sign) {
  if (rows.size() != n) fail(source, key, "has " + std::to_string(rows.size()) + " rows but table.separation_m has " + std::to_string(n));
  for (std::size_t m = 0; m < n; ++m) {
    const std::string row = key + "[" + std::to_string(m) + "]";
    if (rows[m].size() != eta_u_nodes)
      fail(source, row, "has " + std::to_string(rows[m].size()) + " entries but table.eta_u_Pa_m has " + std::to_string(eta_u_nodes));
    check_column(source, row, rows[m], sign);
  }
}

// A ball's films: shares increasing to 1, one row of films and tractions per ηU node, each entry
// NaN (a solve left out) or > 0, and every node but ηU = 0 invertible (rig/ball_film.h).
void validate_ball_film(const LawTable& t) {
  const std::string& s = t.source;
  const std::vector<double>& share = t.ball_share;
  check_column(s, "ball_film.share", share, Sign::positive);
  check_strictly_increasing(s, "ball_film.share", share);
  if (share.back() != 1.0) fail(s, "ball_film.share", "must end at 1 (the whole load), got " + exact_decimal(share.back()));
  const std::size_t nodes = t.eta_u_Pa_m.size();
  for (const auto* rows : {&t.ball_central_film_m, &t.ball_traction_N})
    if (rows->size() != nodes)
      fail(s, "ball_film.films", "has " + std::to_string(rows->size()) + " entries but table.eta_u_Pa_m has " + std::to_string(nodes));
  for (std::size_t k = 0; k < nodes; ++k) {
    const std::string key = "ball_film.films[" + std::to_string(k) + "]";
    for (const auto& [row, name] : {std::pair{&t.ball_central_film_m[k], "central_film_m"}, std::pair{&t.ball_traction_N[k], "traction_N"}}) {
      if (row->size() != share.size())
        fail(s, key + "." + name, "has " + std::to_string(row->size()) + " entries but ball_film.share has " + std::to_string(share.size()));
      for (std::size_t j = 0; j < row->size(); ++j)
        if (!std::isnan((*row)[j]) && !((*row)[j] > 0.0 && std::isfinite((*row)[j])))
          fail(s, key + "." + name + "[" + std::to_string(j) + "]", "must be > 0 or null, got " + exact_decimal((*row)[j]));
    }
    if (k == 0) {  // no film at rest
      for (const auto* row : {&t.ball_central_film_m[0], &t.ball_traction_N[0]})
        if (std::any_of(row->begin(), row->end(), [](double v) { return !std::isnan(v); }))
          fail(s, key, "must be all null: there is no film at rest (eta_u_Pa_m = 0)");
      continue;
    }
    try {
      BallFilmCurve(share, t.ball_central_film_m[k], t.ball_traction_N[k]);
    } catch (const std::invalid_argument& e) {
      fail(s, key, e.what());
    }
  }
}

}  // namespace

void validate(const LawTable& t) {
  const std::string& s = t.source;
  require_positive(s, "pin.nominal_area_m2", t.pin.nominal_area_m2);
  require_non_negative(s, "pin.radius_m", t.pin.radius_m);
  require_non_negative(s, "pin.normal_load_N", t.pin.normal_load_N);
  require_non_negative(s, "lubricant.viscosity_Pa_s", t.lubricant.viscosity_Pa_s);
  require_non_negative(s, "lubricant.temperature_viscosity_per_K", t.lubricant.temperature_viscosity_per_K);
  require_positive(s, "lubricant.reference_temperature_K", t.lubricant.reference_temperature_K);
  require_positive(s, "thermal.slider_conductivity_W_per_m_K", t.thermal.slider_conductivity_W_per_m_K);
  require_positive(s, "thermal.disc_conductivity_W_per_m_K", t.thermal.disc_conductivity_W_per_m_K);
  require_positive(s, "thermal.slider_diffusivity_m2_per_s", t.thermal.slider_diffusivity_m2_per_s);
  require_positive(s, "thermal.time_constant_s", t.thermal.time_constant_s);
  require_non_negative(s, "junction.interface_shear_strength_Pa", t.junction.interface_shear_strength_Pa);
  try {
    contact::validate(t.junction.locus);
  } catch (const std::invalid_argument& e) {
    fail(s, "junction", e.what());
  }

  const std::size_t n = t.separation_m.size();
  if (n < 3) fail(s, "table.separation_m", "needs at least 3 entries (got " + std::to_string(n) + ")");
  const std::pair<const char*, const std::vector<double>*> columns[] = {
      {"table.solid_load_N", &t.solid_load_N},         {"table.real_area_m2", &t.real_area_m2},
      {"table.lift_per_eta_u_m", &t.lift_per_eta_u_m}, {"table.squeeze_per_eta_m", &t.squeeze_per_eta_m},
      {"table.shear_per_eta_u_m", &t.shear_per_eta_u_m}};
  for (const auto& [key, column] : columns) {
    if (column->size() != n) {
      fail(s, key, "has " + std::to_string(column->size()) + " entries but table.separation_m has " + std::to_string(n) +
                       " (all columns must have the same length)");
    }
  }
  check_column(s, "table.separation_m", t.separation_m, Sign::positive);
  check_strictly_increasing(s, "table.separation_m", t.separation_m);
  check_non_increasing_to_zero(s, "table.solid_load_N", t.solid_load_N);
  check_non_increasing_to_zero(s, "table.real_area_m2", t.real_area_m2);
  if (!(t.solid_load_N.front() > 0.0)) fail(s, "table.solid_load_N[0]", "must be > 0 (the closest separation must carry load)");
  check_column(s, "table.lift_per_eta_u_m", t.lift_per_eta_u_m, Sign::non_negative);
  check_column(s, "table.squeeze_per_eta_m", t.squeeze_per_eta_m, Sign::positive);
  // A ball's fluid is its EHL film (ball_film): its Petroff shear S is 0.
  check_column(s, "table.shear_per_eta_u_m", t.shear_per_eta_u_m, t.has_ball_film() ? Sign::non_negative : Sign::positive);
  if (t.eta_u_Pa_m.empty() && t.solid_shear_Pa.empty() && t.film_share.empty() && !t.has_ball_film()) return;  // "tribo-law-1"
  const std::vector<double>& e = t.eta_u_Pa_m;
  if (e.size() < 2) fail(s, "table.eta_u_Pa_m", "needs at least 2 entries (got " + std::to_string(e.size()) + ")");
  if (e.front() != 0.0) fail(s, "table.eta_u_Pa_m[0]", "must be 0 (the law must answer at rest), got " + exact_decimal(e.front()));
  check_column(s, "table.eta_u_Pa_m", e, Sign::non_negative);
  check_strictly_increasing(s, "table.eta_u_Pa_m", e);
  check_rows(s, "table.solid_shear_Pa", t.solid_shear_Pa, n, e.size(), Sign::positive);
  if (t.has_ball_film()) validate_ball_film(t);
  if (t.film_share.empty()) return;
  check_rows(s, "table.film_share", t.film_share, n, e.size(), Sign::non_negative);
  for (std::size_t m = 0; m < n; ++m)
    for (std::size_t k = 0; k < e.size(); ++k)
      if (t.film_share[m][k] > 1.0)
        fail(s, "table.film_share[" + std::to_string(m) + "][" + std::to_string(k) + "]", "must not exceed 1 (got " + exact_decimal(t.film_share[m][k]) + ")");
}

namespace {

// A [separation][ηU] column of "table".
std::vector<std::vector<double>> rows_of(const Reader& r, const json& tab, const std::string& source, const std::string& key) {
  const json& rows = r.member(tab, "table", key);
  if (!rows.is_array()) fail(source, "table." + key, "must be an array of arrays of numbers");
  std::vector<std::vector<double>> out;
  for (std::size_t m = 0; m < rows.size(); ++m) {
    const json row{{std::to_string(m), rows[m]}};
    out.push_back(r.column(row, "table." + key, std::to_string(m)));
  }
  return out;
}

// "ball_film": the shares and, per ηU node, the films and tractions (null where left out: NaN).
void read_ball_film(const Reader& r, const json& ball, LawTable& t) {
  t.ball_share = r.column(ball, "ball_film", "share");
  if (t.ball_share.size() < 2) fail(t.source, "ball_film.share", "needs at least 2 entries (got " + std::to_string(t.ball_share.size()) + ")");
  const json& films = r.member(ball, "ball_film", "films");
  if (!films.is_array()) fail(t.source, "ball_film.films", "must be an array of objects");
  for (std::size_t k = 0; k < films.size(); ++k) {
    const std::string key = "ball_film.films[" + std::to_string(k) + "]";
    if (!films[k].is_object()) fail(t.source, key, "must be a JSON object");
    const auto column_or_null = [&](const char* name) {
      const json& a = r.member(films[k], key, name);
      if (!a.is_array()) fail(t.source, key + "." + name, "must be an array of numbers or nulls");
      std::vector<double> out;
      for (std::size_t j = 0; j < a.size(); ++j) {
        if (a[j].is_null()) {
          out.push_back(std::numeric_limits<double>::quiet_NaN());
          continue;
        }
        const json entry{{std::to_string(j), a[j]}};
        out.push_back(r.number(entry, key + "." + name, std::to_string(j)));
      }
      return out;
    };
    const double eta_u = r.number(films[k], key, "eta_u_Pa_m");
    if (k < t.eta_u_Pa_m.size() && eta_u != t.eta_u_Pa_m[k])
      fail(t.source, key + ".eta_u_Pa_m", "is " + exact_decimal(eta_u) + " but table.eta_u_Pa_m[" + std::to_string(k) + "] is " + exact_decimal(t.eta_u_Pa_m[k]));
    t.ball_central_film_m.push_back(column_or_null("central_film_m"));
    t.ball_traction_N.push_back(column_or_null("traction_N"));
  }
}

}  // namespace

LawTable read_law_table(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(where(source) + ": cannot open the file");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::invalid_argument(where(source) + ": malformed JSON at byte " + std::to_string(e.byte) + ": " + e.what());
  } catch (const json::exception& e) {
    // Not a syntax error but a value JSON can write and a double cannot hold (a number beyond
    // ±1.8e308: out_of_range.406, found by the law_table fuzzer).
    throw std::invalid_argument(where(source) + ": malformed JSON: " + e.what());
  }
  return law_table_from_json(doc, source);
}

LawTable law_table_from_json(const json& doc, const std::string& source) {
  if (!doc.is_object()) throw std::invalid_argument(where(source) + ": the document must be a JSON object");

  const Reader r(source);
  LawTable t;
  t.source = source;
  const json& format = r.member(doc, "", "format");
  if (!format.is_string() || (format.get<std::string>() != "tribo-law-1" && format.get<std::string>() != "tribo-law-2")) {
    fail(source, "format", "must be \"tribo-law-1\" or \"tribo-law-2\" (got " + format.dump() + ")");
  }
  const bool films = format.get<std::string>() == "tribo-law-2";

  const json& pin = r.object(doc, "", "pin");
  t.pin.shape = r.string_or(pin, "pin", "shape", "");
  t.pin.radius_m = r.number_or(pin, "pin", "radius_m", 0.0);
  t.pin.nominal_area_m2 = r.number(pin, "pin", "nominal_area_m2");
  t.pin.normal_load_N = r.number_or(pin, "pin", "normal_load_N", 0.0);

  const json& lub = r.object(doc, "", "lubricant");
  t.lubricant.viscosity_Pa_s = r.number(lub, "lubricant", "viscosity_Pa_s");
  t.lubricant.temperature_viscosity_per_K = r.number(lub, "lubricant", "temperature_viscosity_per_K");
  t.lubricant.reference_temperature_K = r.number(lub, "lubricant", "reference_temperature_K");

  const json& th = r.object(doc, "", "thermal");
  t.thermal.slider_conductivity_W_per_m_K = r.number(th, "thermal", "slider_conductivity_W_per_m_K");
  t.thermal.disc_conductivity_W_per_m_K = r.number(th, "thermal", "disc_conductivity_W_per_m_K");
  t.thermal.slider_diffusivity_m2_per_s = r.number(th, "thermal", "slider_diffusivity_m2_per_s");
  t.thermal.time_constant_s = r.number(th, "thermal", "time_constant_s");

  const json& jn = r.object(doc, "", "junction");
  contact::JunctionLocus& l = t.junction.locus;
  l.alpha = r.number(jn, "junction", "alpha");
  l.n = r.number(jn, "junction", "n");
  l.sigma0_over_tau_i = r.number(jn, "junction", "sigma0_over_tau_i");
  l.location_per_s = r.number(jn, "junction", "location_per_s");
  l.strain_rate_index_m = r.number_or(jn, "junction", "strain_rate_index_m", 0.0);
  l.reference_load_rate_per_s = r.number_or(jn, "junction", "reference_load_rate_per_s", 1.0);
  t.junction.interface_shear_strength_Pa = r.number(jn, "junction", "interface_shear_strength_Pa");

  const json& tab = r.object(doc, "", "table");
  t.separation_m = r.column(tab, "table", "separation_m");
  t.solid_load_N = r.column(tab, "table", "solid_load_N");
  t.real_area_m2 = r.column(tab, "table", "real_area_m2");
  t.lift_per_eta_u_m = r.column(tab, "table", "lift_per_eta_u_m");
  t.squeeze_per_eta_m = r.column(tab, "table", "squeeze_per_eta_m");
  t.shear_per_eta_u_m = r.column(tab, "table", "shear_per_eta_u_m");
  if (films) {
    t.eta_u_Pa_m = r.column(tab, "table", "eta_u_Pa_m");
    t.solid_shear_Pa = rows_of(r, tab, source, "solid_shear_Pa");
    if (tab.find("film_share") != tab.end()) t.film_share = rows_of(r, tab, source, "film_share");
    if (doc.find("ball_film") != doc.end()) read_ball_film(r, r.object(doc, "", "ball_film"), t);
  }

  validate(t);
  return t;
}

// ---- MonotoneTable: Fritsch & Carlson (1980) ------------------------------------------------
//
// On [x_k, x_{k+1}] with h_k = x_{k+1} − x_k, Δ_k = (y_{k+1} − y_k)/h_k and t = (x − x_k)/h_k the
// cubic Hermite form is y = H00 y_k + H10 h_k d_k + H01 y_{k+1} + H11 h_k d_{k+1}. Slopes:
//   1. interior d_k = (Δ_{k−1} + Δ_k)/2, or 0 where Δ changes sign or vanishes (local extremum);
//      end slopes from the one-sided three-point formula, set to 0 if of the wrong sign;
//   2. per interval: Δ_k = 0 ⇒ d_k = d_{k+1} = 0; else with a = d_k/Δ_k, b = d_{k+1}/Δ_k, if
//      a² + b² > 9 scale both by 3/√(a² + b²) — Fritsch & Carlson's sufficient condition for a
//      monotone cubic on the interval. Scaling only shrinks slopes, so an earlier interval stays
//      within its region when a later one shrinks the slope they share.
// Linear data give Δ_k constant, d_k = Δ_k, a = b = 1: the interpolant is the line itself.

MonotoneTable::MonotoneTable(std::vector<double> x, std::vector<double> y, std::string axis)
    : x_(std::move(x)), y_(std::move(y)), axis_(std::move(axis)) {
  const std::size_t n = x_.size();
  if (n < 2 || y_.size() != n) {
    throw std::invalid_argument("monotone table over " + axis_ + ": needs x and y of the same length >= 2 (got " +
                                std::to_string(n) + " and " + std::to_string(y_.size()) + ")");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i])) {
      throw std::invalid_argument("monotone table over " + axis_ + ": entry " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(x_[i] > x_[i - 1])) {
      throw std::invalid_argument("monotone table over " + axis_ + ": x must be strictly increasing at entry " + std::to_string(i));
    }
  }
  std::vector<double> h(n - 1), delta(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x_[k + 1] - x_[k];
    delta[k] = (y_[k + 1] - y_[k]) / h[k];
  }
  d_.assign(n, 0.0);
  if (n == 2) {
    d_[0] = d_[1] = delta[0];
    return;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    d_[k] = delta[k - 1] * delta[k] > 0.0 ? 0.5 * (delta[k - 1] + delta[k]) : 0.0;
  }
  auto end_slope = [](double h0, double h1, double d0, double d1) {
    const double d = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    return d * d0 > 0.0 ? d : 0.0;
  };
  d_[0] = end_slope(h[0], h[1], delta[0], delta[1]);
  d_[n - 1] = end_slope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (delta[k] == 0.0) {
      d_[k] = d_[k + 1] = 0.0;
      continue;
    }
    const double a = d_[k] / delta[k], b = d_[k + 1] / delta[k];
    const double r2 = a * a + b * b;
    if (r2 > 9.0) {
      const double tau = 3.0 / std::sqrt(r2);
      d_[k] = tau * a * delta[k];
      d_[k + 1] = tau * b * delta[k];
    }
  }
}

std::size_t MonotoneTable::interval(double x) const {
  if (!(x >= x_.front() && x <= x_.back())) {
    throw std::out_of_range("monotone table: " + axis_ + " = " + exact_decimal(x) + " lies outside the table's range [" + exact_decimal(x_.front()) +
                            ", " + exact_decimal(x_.back()) + "] (no extrapolation)");
  }
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  const std::size_t k = static_cast<std::size_t>(it - x_.begin());
  return std::min(k == 0 ? 0 : k - 1, x_.size() - 2);
}

double MonotoneTable::value(double x) const {
  const std::size_t k = interval(x);
  if (x == x_[k]) return y_[k];
  if (x == x_[k + 1]) return y_[k + 1];
  // Hermite form with H00 = 1 − H01 written out, so constant data come back exactly.
  const double h = x_[k + 1] - x_[k], t = (x - x_[k]) / h, t2 = t * t, t3 = t2 * t;
  const double h10 = t3 - 2.0 * t2 + t, h01 = -2.0 * t3 + 3.0 * t2, h11 = t3 - t2;
  const double y = y_[k] + h01 * (y_[k + 1] - y_[k]) + h * (h10 * d_[k] + h11 * d_[k + 1]);
  // Every interval's cubic is monotone (step 2 above), so it lies between its end values; the
  // clamp removes only rounding, e.g. a −1e-30 where a column reaches 0.
  return std::clamp(y, std::min(y_[k], y_[k + 1]), std::max(y_[k], y_[k + 1]));
}

double MonotoneTable::slope(double x) const {
  const std::size_t k = interval(x);
  const double h = x_[k + 1] - x_[k], t = (x - x_[k]) / h, t2 = t * t;
  const double g10 = 3.0 * t2 - 4.0 * t + 1.0, g01 = 6.0 * (t - t2), g11 = 3.0 * t2 - 2.0 * t;
  return g01 * (y_[k + 1] - y_[k]) / h + g10 * d_[k] + g11 * d_[k + 1];
}

// ---- EtaUTable --------------------------------------------------------------------------------

EtaUTable::EtaUTable(const std::vector<double>& separation_m, std::vector<double> eta_u_Pa_m,
                     const std::vector<std::vector<double>>& rows)
    : eta_u_(std::move(eta_u_Pa_m)) {
  if (eta_u_.size() < 2 || rows.size() != separation_m.size())
    throw std::invalid_argument("EtaUTable: needs two ηU nodes and one row per separation");
  for (std::size_t k = 0; k < eta_u_.size(); ++k) {
    std::vector<double> column;
    for (const std::vector<double>& row : rows) {
      if (row.size() != eta_u_.size()) throw std::invalid_argument("EtaUTable: a row's length differs from the ηU axis");
      column.push_back(row[k]);
    }
    at_eta_u_.emplace_back(separation_m, column, "separation_m");
  }
}

std::pair<std::size_t, double> EtaUTable::locate(double eta_u) const {
  if (!(eta_u >= eta_u_.front() && eta_u <= eta_u_.back()))
    throw std::out_of_range("law table: eta_u_Pa_m = " + exact_decimal(eta_u) + " lies outside the table's [" + exact_decimal(eta_u_.front()) +
                            ", " + exact_decimal(eta_u_.back()) + "]; homogenise with a larger [micro_ehl] max_speed_m_per_s");
  const auto upper = std::upper_bound(eta_u_.begin(), eta_u_.end(), eta_u);
  const std::size_t k = upper == eta_u_.end() ? eta_u_.size() - 2 : static_cast<std::size_t>(upper - eta_u_.begin()) - 1;
  const double a = eta_u_[k], b = eta_u_[k + 1];
  return {k, a > 0.0 ? std::log(eta_u / a) / std::log(b / a) : (eta_u - a) / (b - a)};
}

double EtaUTable::value(double h_m, double eta_u) const {
  const auto [k, w] = locate(eta_u);
  return (1.0 - w) * at_eta_u_[k].value(h_m) + w * at_eta_u_[k + 1].value(h_m);
}

double EtaUTable::slope_h(double h_m, double eta_u) const {
  const auto [k, w] = locate(eta_u);
  return (1.0 - w) * at_eta_u_[k].slope(h_m) + w * at_eta_u_[k + 1].slope(h_m);
}

}  // namespace tribo::rig
