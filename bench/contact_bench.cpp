// FFT boundary-element contact speed (DESIGN §9): the floor is one FFTW r2c + c2r pair per CG
// iteration. For periodic self-affine Gaussian surfaces (H = 0.8, no roll-off, cut-off at 4
// cells, Rq = 1, E* = 1 — the family of issue 3's ContactMechanics reference point), loaded to
// about 10 % real contact, each benchmark reports
//   iterations           CG iterations to the relative residual 1e-8 (normal_contact.h)
//   per_iter_over_fft    wall time per iteration / wall time of one r2c + c2r pair, same grid
//   per_iter_over_fft_cpu the same ratio in process CPU time (robust on a shared machine)
//   fft_pair_ms          that FFT pair, measured in the same process with the same thread count
//   fft_pairs            half-space evaluations of the solve (1 per iteration + 1 for the start
//                        + 1 where it leaves single precision)
//   single_pairs         how many of them in single precision (normal_contact.h, mixed precision)
//   pairs_per_iter       fft_pairs / iterations (the floor is 1)
//   solve_cpu_s, solve_s the whole solve, process CPU and wall time
//   peak_rss_MiB         the process' peak resident memory so far (VmHWM)
// A solve benchmark runs kSolveRounds rounds, each a solve between two FFT pairs (the mean of the
// two: this machine's speed drifts by up to 2× within minutes, so the pairs bracket each solve);
// the counters are the rounds' medians, with the least and largest ratio in CPU time
// (per_iter_over_fft_cpu_min, _max) for the spread;
// and, to locate the floor, BM_Product (one half-space product with its energy, as the solve
// does it, over an FFT pair) and BM_GridPass (one fused update pass — 4 grids read, 2 written,
// the solve's heaviest — over an FFT pair), both in CPU time and measured in the same process.
// Arguments: grid side n, threads. The elastic-plastic case caps the pressure so that the mean
// pressure is 0.6 × hardness (where public FFT codes are reported to stall).
// Run: build/bench/contact_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "contact/fft.h"
#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"
#include "numerics/median.h"

namespace {

using namespace tribo::contact;
using tribo::numerics::median;

double peak_rss_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0.0;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 10, '\n');
  }
  return 0.0;
}

// Process CPU time: on a shared machine it measures the work, where wall time also measures
// the other jobs; for one thread it is the wall time of an idle machine.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct PairTime {
  double wall_s, cpu_s;
};

PairTime fft_pair_time(Eigen::Index n, int threads) {
  RealFft2d fft(n, n, threads);
  fft.real().setRandom();
  const int reps = n >= 1024 ? 5 : 20;
  fft.forward();
  fft.inverse();
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < reps; ++k) {
    fft.forward();
    fft.inverse();
  }
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps,
          (cpu_seconds() - c0) / reps};
}

Eigen::ArrayXXd bench_surface(Eigen::Index n) {
  GaussianSurfaceParams p;
  p.grid = n;
  p.size_m = 1.0;
  p.hurst = 0.8;
  p.rms_height_m = 1.0;
  p.cutoff_wavelength_m = 4.0 / static_cast<double>(n);
  p.seed = 1;
  return gaussian_surface(p);
}

constexpr int kSolveRounds = 5;

void solve_bench(benchmark::State& state, bool plastic) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const Eigen::ArrayXXd z = bench_surface(n);
  const double slope = surface_statistics(z, 1.0, 1.0).rms_slope;
  const Grid grid = Grid::patch(n, n, 1.0, 1.0);
  ElasticHalfSpace hs(grid, 1.0, true, threads);
  const Eigen::ArrayXXd h = gap_from_heights(z);
  // A ≈ κ W/(E* h'), κ ≈ 2.2: a mean pressure 0.045 E* h' gives ≈ 10 % contact.
  const double load = 0.045 * slope * grid.area_m2();
  NormalContactOptions opt;
  opt.tolerance = 1e-8;
  if (plastic) opt.pressure_cap_Pa = load / grid.area_m2() / 0.6;
  NormalContactResult r;
  PairTime before = fft_pair_time(n, threads);
  std::vector<double> solve_s, solve_cpu_s, pair_s, pair_cpu_s, ratio, ratio_cpu;
  for (auto _ : state) {
    const double c0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    r = solve_normal_load(hs, h, load, opt);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_seconds() - c0;
    benchmark::DoNotOptimize(r.real_area_m2);
    const PairTime after = fft_pair_time(n, threads);
    const PairTime pair{0.5 * (before.wall_s + after.wall_s), 0.5 * (before.cpu_s + after.cpu_s)};
    const double iterations = r.summary.iterations;
    solve_s.push_back(wall), solve_cpu_s.push_back(cpu), pair_s.push_back(pair.wall_s), pair_cpu_s.push_back(pair.cpu_s);
    ratio.push_back(wall / iterations / pair.wall_s), ratio_cpu.push_back(cpu / iterations / pair.cpu_s);
    before = after;
  }
  if (!r.summary.converged) state.SkipWithError(r.summary.message.c_str());
  state.counters["iterations"] = r.summary.iterations;
  state.counters["fft_pairs"] = r.summary.fft_pairs;
  state.counters["single_pairs"] = r.summary.single_pairs;
  state.counters["pairs_per_iter"] = static_cast<double>(r.summary.fft_pairs) / r.summary.iterations;
  state.counters["solve_cpu_s"] = median(solve_cpu_s);
  state.counters["solve_s"] = median(solve_s);
  state.counters["fft_pair_cpu_ms"] = 1e3 * median(pair_cpu_s);
  state.counters["area_fraction"] = r.area_fraction;
  state.counters["fft_pair_ms"] = 1e3 * median(pair_s);
  state.counters["per_iter_over_fft"] = median(ratio);
  state.counters["per_iter_over_fft_cpu"] = median(ratio_cpu);
  state.counters["per_iter_over_fft_cpu_min"] = *std::min_element(ratio_cpu.begin(), ratio_cpu.end());
  state.counters["per_iter_over_fft_cpu_max"] = *std::max_element(ratio_cpu.begin(), ratio_cpu.end());
  state.counters["peak_rss_MiB"] = peak_rss_mib();
}

void BM_FftPair(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  RealFft2d fft(n, n, threads);
  fft.real().setRandom();
  for (auto _ : state) {
    fft.forward();
    fft.inverse();
  }
}

// One half-space product as the solve does it (r2c, kernel multiply with the energy sum, c2r,
// on the caller's arrays), against the bare FFT pair.
void BM_Product(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  ElasticHalfSpace hs(Grid::patch(n, n, 1.0, 1.0), 1.0, true, threads);
  const Eigen::ArrayXXd t = Eigen::ArrayXXd::Random(n, n);
  Eigen::ArrayXXd r(n, n);
  double energy = hs.displacement_and_energy(t, r);  // first touch of r outside the timing
  double cpu = 0.0;
  for (auto _ : state) {
    const double c0 = cpu_seconds();
    energy += hs.displacement_and_energy(t, r);
    cpu += cpu_seconds() - c0;
  }
  benchmark::DoNotOptimize(energy);
  const PairTime fft = fft_pair_time(n, threads);
  state.counters["over_fft_cpu"] = cpu / static_cast<double>(state.iterations()) / fft.cpu_s;
}

// The same product taken line by line (ElasticHalfSpace::displacement_by_rows) with nothing fused
// into its stages, against the bare FFT pair: what the transforms cost when taken apart.
void BM_LineProduct(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  ElasticHalfSpace hs(Grid::patch(n, n, 1.0, 1.0), 1.0, true, threads);
  Eigen::ArrayXXd t = Eigen::ArrayXXd::Random(n, n);
  Eigen::ArrayXXd r(n, n);
  const ElasticHalfSpace::RowPass nothing = [](int, Eigen::Index) {};
  const ElasticHalfSpace::UseRow keep = [](int, Eigen::Index, const double*) {};
  const std::function<bool(double)> want = [](double) { return true; };
  double energy = hs.displacement_by_rows(t.data(), r.data(), nothing, want, keep);
  double cpu = 0.0;
  for (auto _ : state) {
    const double c0 = cpu_seconds();
    energy += hs.displacement_by_rows(t.data(), r.data(), nothing, want, keep);
    cpu += cpu_seconds() - c0;
  }
  benchmark::DoNotOptimize(energy);
  const PairTime fft = fft_pair_time(n, threads);
  state.counters["over_fft_cpu"] = cpu / static_cast<double>(state.iterations()) / fft.cpu_s;
}

// A pass shaped like the solve's update pass: 4 grids read, 2 written, a few flops per cell and
// two reductions — the memory traffic of one of the two fused passes per iteration.
void BM_GridPass(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const Eigen::Index cells = n * n;
  Eigen::ArrayXd a = Eigen::ArrayXd::Random(cells), b = Eigen::ArrayXd::Random(cells),
                 c = Eigen::ArrayXd::Random(cells), d = Eigen::ArrayXd::Random(cells);
  double* ap = a.data();
  double* bp = b.data();
  const double* cp = c.data();
  const double* dp = d.data();
  double cpu = 0.0, sink = 0.0;
  for (auto _ : state) {
    const double c0 = cpu_seconds();
    double s1 = 0.0, s2 = 0.0;
#pragma omp parallel for if (cells >= Eigen::Index{1} << 15) reduction(+ : s1, s2) schedule(static)
    for (Eigen::Index i = 0; i < cells; ++i) {
      const double y = std::clamp(ap[i] - 1e-3 * cp[i], 0.0, 10.0);
      const double v = bp[i] - 1e-3 * dp[i];
      s1 += y;
      s2 += v * v;
      ap[i] = y;
      bp[i] = v;
    }
    sink += s1 + s2;
    cpu += cpu_seconds() - c0;
  }
  benchmark::DoNotOptimize(sink);
  const PairTime fft = fft_pair_time(n, threads);
  state.counters["over_fft_cpu"] = cpu / static_cast<double>(state.iterations()) / fft.cpu_s;
  state.counters["GB_per_s"] = 6.0 * 8.0 * static_cast<double>(cells) * static_cast<double>(state.iterations()) /
                               std::max(cpu, 1e-12) * 1e-9 * threads;
}

void BM_ElasticSolve(benchmark::State& state) { solve_bench(state, false); }
void BM_ElasticPlasticSolve(benchmark::State& state) { solve_bench(state, true); }

void grids(benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->Iterations(kSolveRounds)->UseRealTime();
}

BENCHMARK(BM_FftPair)->Apply([](benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
});
BENCHMARK(BM_Product)->Apply([](benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
});
BENCHMARK(BM_LineProduct)->Apply([](benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
});
BENCHMARK(BM_GridPass)->Apply([](benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
});
BENCHMARK(BM_ElasticSolve)->Apply(grids);
BENCHMARK(BM_ElasticPlasticSolve)->Apply(grids);

}  // namespace

BENCHMARK_MAIN();
