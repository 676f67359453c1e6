// `tribo sweep` costs (issue 17): what the sweep adds per point beyond the point's own process, and
// the throughput of many cheap rig points on 1 and 2 cores. Everything runs the real
// `tribo` executable (TRIBO_EXE), as a user would: what a point costs beyond its work is the
// sweep's machinery (worker processes, messages, rows), which an in-process stand-in would not measure.
//   build/bench/sweep_bench --benchmark_counters_tabular=true --benchmark_repetitions=6
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

// Points per sweep. The overhead pair runs kPoints direct `tribo rig` processes too (≈ 15–20 ms
// each); the throughput sweeps run kThroughputPoints, "many cheap points" (issue 17): at ≈ 0.5 ms of
// CPU a point in memory on a worker, the sweep's own start-up and final sort (≈ 20–30 ms whatever
// the jobs) are then ≈ 2–3 % of a one-job sweep instead of ≈ 20 % at 200 points.
constexpr int kPoints = 200;
constexpr int kThroughputPoints = 2000;

// A cheap rig point: Coulomb stick-slip for 0.5 s of rig time (≈ the cheapest useful point). Its
// direct runs write summary.json only (`--summary-only`), the least a process run can; the sweep's
// points run on their config in memory and write nothing.
fs::path workdir() {
  const fs::path dir = fs::temp_directory_path() / "tribo_sweep_bench";
  fs::create_directories(dir);
  std::ofstream(dir / "rig.toml") << "[rig]\ndrive_speed_m_per_s = 1e-2\n[friction]\nlaw = \"coulomb\"\nmu_s = 0.3\n"
                                     "mu_k = 0.2\n[run]\nduration_s = 0.5\n";
  for (int jobs : {0, 1})  // 0: as many as the cores the sweep may use
    for (int points : {kPoints, kThroughputPoints}) {
      std::ofstream(dir / ("spec" + std::to_string(jobs) + "_" + std::to_string(points) + ".toml"))
          << "[base]\ncommand = \"rig\"\nconfig = \"rig.toml\"\n[[axis]]\nkey = \"rig.mass_kg\"\nfrom = 0.9\nto = 1.1\n"
          << "count = " << points << "\n[sweep]\njobs = " << jobs << "\n"
          << "[outputs]\ncolumns = [\"summary.json:regime\", \"summary.json:peak_to_peak_m\"]\n";
    }
  return dir;
}

// `tribo sweep` of `points` points, `jobs` at a time, into dir/sweepJ_P (emptied first).
std::vector<std::string> sweep_args(const fs::path& dir, int jobs, int points) {
  const std::string name = std::to_string(jobs) + "_" + std::to_string(points);
  fs::remove_all(dir / ("sweep" + name));
  return {"sweep", (dir / ("spec" + name + ".toml")).string(), "--out", (dir / ("sweep" + name)).string()};
}

std::vector<std::string> rig_args(const fs::path& dir) {
  return {"rig", (dir / "rig.toml").string(), "--out", (dir / "rig").string(), "--summary-only"};
}

// Runs TRIBO_EXE with `args` (stdout to `out`, stderr discarded, OMP_NUM_THREADS=1 as the sweep
// gives its points) and waits; throws when it fails.
void run_tribo(const std::vector<std::string>& args, const std::string& out = "/dev/null") {
  std::vector<std::string> all{TRIBO_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env{"OMP_NUM_THREADS=1"};
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("OMP_NUM_THREADS=", 0) != 0) env.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, TRIBO_EXE, &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("posix_spawn failed");
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("tribo " + args.front() + " failed");
}

// CPU time (user + system) of every waited-for descendant so far.
double children_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double seconds_of(const std::vector<std::string>& args, const std::string& out = "/dev/null") {
  const auto t0 = std::chrono::steady_clock::now();
  run_tribo(args, out);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The point's own work: one `tribo rig` process, started and waited for.
void BM_RigProcess(benchmark::State& state) {
  const fs::path dir = workdir();
  for (auto _ : state) state.SetIterationTime(seconds_of(rig_args(dir)));
}
BENCHMARK(BM_RigProcess)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The sweep's own cost per point: a kPoints sweep one point at a time against kPoints direct `tribo rig`
// runs of the same config, interleaved so both see the same machine load.
void BM_SweepOverheadPerPoint(benchmark::State& state) {
  const fs::path dir = workdir();
  double direct = 0.0, swept = 0.0, cpu = 0.0;
  for (auto _ : state) {
    double d = 0.0;
    for (int k = 0; k < kPoints; ++k) d += seconds_of(rig_args(dir));
    const double s = seconds_of(sweep_args(dir, 1, kPoints), (dir / "sweep1.txt").string());
    direct += d;
    swept += s;
    state.SetIterationTime(s);
    // The sweep's own CPU time per point, as it reports it ("… own CPU time X ms per point run"):
    // unlike the wall-time difference it does not depend on how loaded the machine is.
    std::ifstream in(dir / "sweep1.txt");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("own CPU time ");
    if (at != std::string::npos) cpu += std::stod(text.substr(at + 13));
  }
  state.counters["sweep_cpu_ms_per_point"] = cpu / static_cast<double>(state.iterations());
  const double n = static_cast<double>(state.iterations()) * kPoints;
  state.counters["rig_process_ms"] = 1e3 * direct / n;
  state.counters["sweep_ms_per_point"] = 1e3 * swept / n;
  state.counters["overhead_ms_per_point"] = 1e3 * (swept - direct) / n;
}
BENCHMARK(BM_SweepOverheadPerPoint)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

// Throughput of a kThroughputPoints sweep on 1 or 2 cores (items/s = points/s): the sweep, with
// `jobs` left to its default (the cores it may use), runs under a CPU mask of range(0) cores, set
// on this process around the start and inherited — what `taskset -c 0 tribo sweep …` does.
void BM_SweepThroughput(benchmark::State& state) {
  const fs::path dir = workdir();
  cpu_set_t all, mask;
  if (sched_getaffinity(0, sizeof all, &all) != 0) throw std::runtime_error("sched_getaffinity failed");
  CPU_ZERO(&mask);
  for (int cpu = 0, taken = 0; cpu < CPU_SETSIZE && taken < state.range(0); ++cpu)
    if (CPU_ISSET(cpu, &all)) {
      CPU_SET(cpu, &mask);
      ++taken;
    }
  if (CPU_COUNT(&mask) < state.range(0)) {
    state.SkipWithError("fewer cores than asked for");
    return;
  }
  const double cpu0 = children_cpu_s();
  for (auto _ : state) {
    const std::vector<std::string> args = sweep_args(dir, 0, kThroughputPoints);
    if (sched_setaffinity(0, sizeof mask, &mask) != 0) throw std::runtime_error("sched_setaffinity failed");
    const double s = seconds_of(args);
    sched_setaffinity(0, sizeof all, &all);
    state.SetIterationTime(s);
  }
  state.SetItemsProcessed(state.iterations() * kThroughputPoints);
  // CPU time of the sweep and its workers per point: equal for 1 and 2 cores means running points
  // side by side costs nothing extra. On a host that shares CPU per session (Linux autogroup) the
  // wall time cannot show the second core; this figure can.
  state.counters["cpu_ms_per_point"] =
      1e3 * (children_cpu_s() - cpu0) / (static_cast<double>(state.iterations()) * kThroughputPoints);
}
BENCHMARK(BM_SweepThroughput)->ArgName("cores")->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
