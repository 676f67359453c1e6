#include "gap/recorder.h"

#include <liquid/liquid.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace tribo::gap {
namespace {

// One second-order section, b0 + b1 z⁻¹ + b2 z⁻² over 1 + a1 z⁻¹ + a2 z⁻².
struct Section {
  double b0, b1, b2, a1, a2;
};

// liquid-dsp's Butterworth sections (single precision), widened to double and scaled so that the
// cascade's DC gain is 1 exactly: a float coefficient's rounding would otherwise leave a level
// error of ~1e-7 that no friction law has.
std::vector<Section> design(const AntiAliasFilter& f, double step_s) {
  const double fc = f.cutoff_Hz * step_s;  // cycles per sample
  if (!(f.order > 0 && fc > 0.0 && fc < 0.5))
    throw std::invalid_argument("anti-alias filter: order " + std::to_string(f.order) + " at " + std::to_string(f.cutoff_Hz) +
                                " Hz must lie below the Nyquist frequency of the " + std::to_string(step_s) + "-s step");
  const unsigned n = static_cast<unsigned>(f.order);
  const unsigned sections = (n + 1) / 2;
  std::vector<float> b(3 * sections), a(3 * sections);
  // Pass-band and stop-band ripple are not used by a Butterworth design; liquid requires them positive.
  if (liquid_iirdes(LIQUID_IIRDES_BUTTER, LIQUID_IIRDES_LOWPASS, LIQUID_IIRDES_SOS, n, static_cast<float>(fc), 0.0f, 1.0f, 60.0f,
                    b.data(), a.data()) != LIQUID_OK)
    throw std::runtime_error("anti-alias filter: liquid_iirdes failed for order " + std::to_string(n));
  std::vector<Section> out;
  for (unsigned s = 0; s < sections; ++s) {
    const double a0 = a[3 * s];
    Section q{b[3 * s] / a0, b[3 * s + 1] / a0, b[3 * s + 2] / a0, a[3 * s + 1] / a0, a[3 * s + 2] / a0};
    const double dc = (q.b0 + q.b1 + q.b2) / (1.0 + q.a1 + q.a2);
    q.b0 /= dc, q.b1 /= dc, q.b2 /= dc;
    out.push_back(q);
  }
  return out;
}

}  // namespace

std::vector<double> low_pass(const AntiAliasFilter& filter, const std::vector<double>& u, double step_s) {
  if (u.empty()) return {};
  const std::vector<Section> sections = design(filter, step_s);
  // Linear and of DC gain 1: filtering u − u₀ from rest and adding u₀ back is the filter started
  // from the steady state of u₀.
  const double u0 = u.front();
  std::vector<double> y(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) y[i] = u[i] - u0;
  for (const Section& q : sections) {
    double s1 = 0.0, s2 = 0.0;  // transposed direct form II
    for (double& v : y) {
      const double x = v;
      v = q.b0 * x + s1;
      s1 = q.b1 * x - q.a1 * v + s2;
      s2 = q.b2 * x - q.a2 * v;
    }
  }
  for (double& v : y) v += u0;
  return y;
}

double gain_at(const AntiAliasFilter& filter, double frequency_Hz, double step_s) {
  const std::complex<double> z_inv = std::polar(1.0, -2.0 * M_PI * frequency_Hz * step_s);
  std::complex<double> h = 1.0;
  for (const Section& q : design(filter, step_s))
    h *= (q.b0 + z_inv * (q.b1 + z_inv * q.b2)) / (1.0 + z_inv * (q.a1 + z_inv * q.a2));
  return std::abs(h);
}

}  // namespace tribo::gap
