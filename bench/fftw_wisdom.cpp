// Makes contact/fftw_wisdom.txt, the FFTW wisdom tribo ships (contact/fft.h,
// shipped_fftw_wisdom_loaded): the plans FFTW_MEASURE chooses on this machine for the r2c and c2r
// transforms of RealFft2d on square grids 64² … 4096², on 1 and on 2 threads, and for the line
// transforms of RowColumnFft on the same grids. Run on an idle machine (the planner times its
// candidates):
//   OMP_WAIT_POLICY=passive build/bench/fftw_wisdom > contact/fftw_wisdom.txt
// and rebuild; the wisdom is compiled into tribo_contact. With --lines-only the shipped 2-D plans
// are kept as they are and only the line transforms are measured (so the 2-D transforms, and
// every result through them, keep their bits). With --single, contact/fftwf_wisdom.txt: the
// single-precision line transforms (RowColumnFftSingle) on the same grids:
//   OMP_WAIT_POLICY=passive build/bench/fftw_wisdom --single > contact/fftwf_wisdom.txt
// Progress and planning times on stderr.
#include <fftw3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "contact/fft.h"

namespace {

// Measured plans for the line transforms of Lines on the square grids 64² … 4096².
template <class Lines>
void plan_lines(const char* what) {
  for (int n = 64; n <= 4096; n *= 2) {
    const auto start = std::chrono::steady_clock::now();
    const Lines planned(n, n, true);
    std::fprintf(stderr, "%d x %d %s: planned in %.1f s\n", n, n, what,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

// FFTW's exported wisdom to stdout (and freed); 1 when FFTW could not export it.
int print_wisdom(char* wisdom) {
  if (wisdom == nullptr) {
    std::fputs("fftw_wisdom: FFTW could not export its wisdom\n", stderr);
    return 1;
  }
  std::fputs(wisdom, stdout);
  std::free(wisdom);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using tribo::contact::RealFft2d;
  using tribo::contact::RowColumnFft;
  using tribo::contact::RowColumnFftSingle;
  const bool lines_only = argc == 2 && std::strcmp(argv[1], "--lines-only") == 0;
  const bool single = argc == 2 && std::strcmp(argv[1], "--single") == 0;
  if (argc > 2 || (argc == 2 && !lines_only && !single)) {
    std::fputs("usage: fftw_wisdom [--lines-only] > contact/fftw_wisdom.txt\n"
               "       fftw_wisdom --single > contact/fftwf_wisdom.txt\n",
               stderr);
    return 2;
  }
  { RealFft2d first(8, 8, 1); }  // FFTW's threads initialised and the shipped wisdom imported ...
  if (single) {
    fftwf_forget_wisdom();  // ... and forgotten, so every plan below is measured afresh
    plan_lines<RowColumnFftSingle>("single-precision lines");
    return print_wisdom(fftwf_export_wisdom_to_string());
  }
  if (!lines_only) fftw_forget_wisdom();
  plan_lines<RowColumnFft>("lines");
  for (const int threads : {1, 2}) {
    if (lines_only) break;
    for (int n = 64; n <= 4096; n *= 2) {
      const auto start = std::chrono::steady_clock::now();
      const RealFft2d planned(n, n, threads, true);
      std::fprintf(stderr, "%d x %d, %d thread(s): planned in %.1f s\n", n, n, threads,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  }
  return print_wisdom(fftw_export_wisdom_to_string());
}
