// `tribo sweep SPEC.toml --out DIR`: a parameter study (apps/sweep_spec.h). Each point is its own
// `tribo COMMAND` process (DIR/points/NNNNN/: config.toml, the command's outputs, log.txt), run
// `jobs` at a time with one OpenMP thread each; its row is appended to DIR/results.csv and flushed
// as soon as it finishes. Started again with the same command after a kill, the sweep skips the
// points already in results.csv (a torn last line is dropped); a changed spec or base config is
// refused. At the end results.csv is rewritten sorted by point id.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/sweep_spec.h"

extern char** environ;

namespace tribo::cli {
namespace {

struct Args {
  std::string spec;
  std::string out = "out/sweep";
};

std::string csv_quoted(std::string s) {
  std::replace(s.begin(), s.end(), '"', '\'');
  std::replace(s.begin(), s.end(), '\n', ' ');
  return '"' + s + '"';
}

// DIR/points/NNNNN: the folder of point `id`.
std::filesystem::path point_dir(const std::filesystem::path& dir, int id) {
  char name[16];
  std::snprintf(name, sizeof name, "%05d", id);
  return dir / "points" / name;
}

std::string header(const SweepSpec& spec) {
  std::string h = "point_id";
  for (const SweepAxis& a : spec.axes) h += "," + a.key;
  h += ",status,error,wall_s";
  for (const SweepOutput& o : spec.outputs) h += "," + o.column;
  return h;
}

// The rows already in results.csv by point id (complete lines only: a kill mid-write leaves a torn
// last line, which is dropped). A header that differs from `expected` is refused.
std::map<int, std::string> finished_rows(const std::filesystem::path& file, const std::string& expected) {
  std::map<int, std::string> rows;
  std::ifstream in(file, std::ios::binary);
  if (!in) return rows;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t start = 0;
  bool first = true;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    const std::string line = text.substr(start, nl - start);
    if (first) {
      if (line != expected) throw InputError(file.string() + ": its columns differ from this spec's; use another --out");
      first = false;
      continue;
    }
    rows[std::stoi(line.substr(0, line.find(',')))] = line;
  }
  return rows;
}

void write_rows(const std::filesystem::path& file, const std::string& head, const std::map<int, std::string>& rows) {
  std::string text = head + "\n";
  for (const auto& [id, row] : rows) text += row + "\n";
  write_file_atomically(file, text);
}

// The folder holds the sweep of exactly this spec and base config, or nothing yet.
void claim_output(const std::filesystem::path& dir, const SweepSpec& spec, std::size_t points) {
  const std::string spec_hash = config_hash(spec.spec_file), base_hash = config_hash(spec.base_config);
  const auto file = dir / "sweep.json";
  if (std::ifstream in(file); in) {
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || j.value("spec_hash", "") != spec_hash || j.value("base_config_hash", "") != base_hash)
      throw InputError(dir.string() + ": holds a sweep of a different spec or base config (sweep.json); "
                       "resume only with the same files, or use another --out");
    return;
  }
  nlohmann::json j = provenance_json(spec.spec_file, spec_hash);
  j["spec_hash"] = spec_hash;
  j["base_config"] = spec.base_config.string();
  j["base_config_hash"] = base_hash;
  j["command"] = spec.command;
  j["points"] = points;
  for (const SweepAxis& a : spec.axes) j["axes"].push_back({{"key", a.key}, {"values", a.values}});
  write_file_atomically(file, j.dump(2) + "\n");
}

std::string last_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no message" : last;
}

struct Running {
  int id = 0;
  std::chrono::steady_clock::time_point start;
};

// Starts `tribo COMMAND config --out dir` with stdout and stderr in dir/log.txt.
pid_t spawn_point(const SweepSpec& spec, const std::filesystem::path& dir, bool one_thread) {
  std::vector<std::string> args{"/proc/self/exe", spec.command, (dir / "config.toml").string(), "--out", dir.string()};
  if (spec.command == "homogenise") args.push_back("--no-plots");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_strings;
  for (char** e = environ; *e; ++e)
    if (!one_thread || std::string(*e).rfind("OMP_NUM_THREADS=", 0) != 0) env_strings.emplace_back(*e);
  if (one_thread) env_strings.emplace_back("OMP_NUM_THREADS=1");
  std::vector<char*> envp;
  for (std::string& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string log = (dir / "log.txt").string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("sweep: cannot start a point process (posix_spawn error " + std::to_string(rc) + ")");
  return pid;
}

void run_sweep(const Args& args) {
  const SweepSpec spec = load_sweep_spec(args.spec);
  const auto points = sweep_points(spec);
  const std::filesystem::path dir(args.out), results = dir / "results.csv";
  make_output_dir(dir);
  claim_output(dir, spec, points.size());
  const std::string head = header(spec);
  std::map<int, std::string> rows = finished_rows(results, head);
  write_rows(results, head, rows);  // drops a torn line before appending

  std::vector<int> pending;
  for (int k = 0; k < static_cast<int>(points.size()); ++k)
    if (!rows.count(k)) pending.push_back(k);
  const int jobs = spec.jobs > 0 ? spec.jobs : std::max(1u, std::thread::hardware_concurrency());
  Progress progress("sweep: " + std::to_string(points.size()) + " points", static_cast<int>(points.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) progress.step("done before");

  std::ofstream append(results, std::ios::app);
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  int failed = 0;
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && static_cast<int>(running.size()) < jobs) {
      const int id = pending[next++];
      const auto pdir = point_dir(dir, id);
      make_output_dir(pdir);
      std::ostringstream config;
      config << point_config(spec, points[id]) << "\n";
      write_file_atomically(pdir / "config.toml", config.str());
      running[spawn_point(spec, pdir, jobs > 1)] = {id, std::chrono::steady_clock::now()};
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) throw std::runtime_error("sweep: waitpid failed");
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const Running r = it->second;
    running.erase(it);
    const auto pdir = point_dir(dir, r.id);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
    std::string error, values;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      error = last_line(pdir / "log.txt");
    } else {
      try {
        for (const SweepOutput& o : spec.outputs) values += "," + json_field(pdir / o.file, o.path);
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
    if (!error.empty()) values = std::string(spec.outputs.size(), ',');
    std::string row = std::to_string(r.id);
    for (double v : points[r.id]) row += "," + exact(v);
    row += std::string(",") + (error.empty() ? "ok" : "failed") + "," + (error.empty() ? "" : csv_quoted(error)) + "," +
           exact(wall) + values;
    append << row << '\n' << std::flush;  // the row is kept the moment the point is done
    rows[r.id] = row;
    failed += error.empty() ? 0 : 1;
    progress.step("point " + std::to_string(r.id) + (error.empty() ? "" : " failed"));
  }
  progress.done();
  append.close();
  write_rows(results, head, rows);
  std::printf("sweep: %zu points (%d failed this run) -> %s\n", points.size(), failed, results.string().c_str());
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("sweep", "parameter study: one tribo command over axes of config keys, resumable");
  cmd->add_option("spec", args->spec, "SPEC.toml: [base] command, config; [[axis]] key, values or from/to/count/scale; "
                                      "[sweep] combine, jobs; [outputs] columns")
      ->required();
  cmd->add_option("--out", args->out, "output directory (results.csv, sweep.json, points/)")->capture_default_str();
  cmd->callback([args] { run_sweep(*args); });
}

}  // namespace tribo::cli
