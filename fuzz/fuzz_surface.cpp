// libFuzzer harness for every surface reader (contact/surface_io.h): the first byte picks the
// format (0 .npy, 1 ASCII matrix, 2 x-y-z, 3 ASCII with an instrument header — Gwyddion's or an
// interferometer's, 4 Dektak profile CSV), the rest is the file. The readers' documented error is
// std::invalid_argument; anything else escaping (std::out_of_range, std::bad_alloc, …), a
// sanitizer report, or a result that breaks the documented contract is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "contact/surface_io.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int format = data[0] % 5;
  // A topography's stated size: finite and positive both ways — or, where the format may leave it
  // out (an ASCII matrix without an instrument header), 0 both ways (contact/surface_io.h).
  auto check_extent = [](const tribo::contact::Topography& t, bool may_be_absent = false) {
    if (may_be_absent && t.lx_m == 0.0 && t.ly_m == 0.0) return;
    TRIBO_FUZZ_CHECK(std::isfinite(t.lx_m) && t.lx_m > 0.0 && std::isfinite(t.ly_m) && t.ly_m > 0.0);
  };
  std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  try {
    if (format == 0) {
      const Eigen::ArrayXXd h = tribo::contact::read_npy(in, "fuzz.npy");
      TRIBO_FUZZ_CHECK(h.size() > 0 && h.allFinite());
    } else if (format == 1) {
      const Eigen::ArrayXXd h = tribo::contact::read_ascii_matrix(in, "fuzz.txt");
      TRIBO_FUZZ_CHECK(h.size() > 0 && h.allFinite());
    } else if (format == 2) {
      const tribo::contact::Topography t = tribo::contact::read_xyz(in, "fuzz.xyz");
      TRIBO_FUZZ_CHECK(t.heights_m.rows() >= 2 && t.heights_m.cols() >= 2 && t.heights_m.allFinite());
      check_extent(t);
    } else if (format == 3) {
      const tribo::contact::Topography t = tribo::contact::read_ascii_topography(in, "fuzz.txt");
      TRIBO_FUZZ_CHECK(t.heights_m.size() > 0 && t.heights_m.allFinite());
      check_extent(t, /*may_be_absent=*/true);
    } else {
      const tribo::contact::Topography t = tribo::contact::read_dektak_csv(in, "fuzz.csv");
      TRIBO_FUZZ_CHECK(t.heights_m.rows() >= 1 && t.heights_m.cols() == 1 && t.heights_m.allFinite());
      check_extent(t);
    }
  } catch (const std::invalid_argument& e) {
    // Every message names the file it is about.
    TRIBO_FUZZ_CHECK(std::string(e.what()).find("fuzz.") != std::string::npos);
  }
  return 0;
}
