#include "apps/surface_config.h"

namespace tribo::cli {

void read_spectrum(ConfigTable& t, contact::GaussianSurfaceParams& p) {
  const std::string spectrum = t.choice("spectrum", "gaussian_acf", {"gaussian_acf", "self_affine"});
  p.kind = spectrum == "gaussian_acf" ? contact::SpectrumKind::gaussian_acf : contact::SpectrumKind::self_affine;
  p.seed = static_cast<std::uint64_t>(t.integer("seed", 1, 0));
  if (p.kind == contact::SpectrumKind::gaussian_acf) {
    p.correlation_length_m = t.required_number("correlation_length_m", Range::positive);
    p.correlation_length_across_m = t.number("correlation_length_across_m", 0.0, Range::non_negative);
  } else {
    p.hurst = t.number("hurst", p.hurst, Range::positive);
    p.rolloff_wavelength_m = t.number("rolloff_wavelength_m", 0.0, Range::non_negative);
    p.cutoff_wavelength_m = t.number("cutoff_wavelength_m", 0.0, Range::non_negative);
    p.peklenik_gamma = t.number("peklenik_gamma", 1.0, Range::positive);
  }
}

contact::GaussianSurfaceParams read_gaussian_surface(ConfigTable& surface, ConfigTable* domain) {
  contact::GaussianSurfaceParams p;
  p.size_m = domain ? domain->number("size_m", 1e-3, Range::positive) : 1e-3;
  p.grid = domain ? domain->integer("grid", 128, 8, 16384) : 128;  // 16384² = the largest surface contact/ reads
  p.rms_height_m = surface.number("rms_height_m", 0.0, Range::non_negative);
  p.rms_slope = surface.number("rms_slope", 0.0, Range::non_negative);
  read_spectrum(surface, p);
  input_guard(surface, "spectrum", [&] { contact::validate(p); return 0; });
  return p;
}

}  // namespace tribo::cli
