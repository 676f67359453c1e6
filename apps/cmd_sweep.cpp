// `tribo sweep SPEC.toml --out DIR`: a parameter study (apps/sweep_spec.h). Each point runs
// `tribo COMMAND` in a worker process forked from the sweep (a fresh process under MPI; PointStart):
// a rig, contact or reynolds point without artefacts on its config in memory, its JSON sent back
// (no folder unless it fails: apps/sweep_point.h); any other in DIR/points/NNNNN/ (config.toml,
// the command's outputs, log.txt) — or, for the chain "homogenise+rig", two steps one after the
// other in DIR/points/NNNNN/homogenise/ and .../rig/ — `jobs` points at a time with one OpenMP
// thread each; its row is appended to
// DIR/results.csv and flushed as soon as it finishes. Started again with the same command after a
// kill, the sweep skips the points already in results.csv (a torn last line is dropped); a changed
// spec or base config is refused. At the end results.csv is rewritten sorted by point id.
//
// Under `mpirun -np N` (detected from OMPI_COMM_WORLD_SIZE > 1, or forced with --mpi) the points
// are shared out dynamically: rank 0 owns the queue, results.csv and sweep.json, and runs points
// itself; every other rank asks rank 0 for a point id whenever one of its `jobs` slots is free and
// sends back the finished row. Points differ in cost by orders of magnitude, so a static split would
// leave ranks idle. The point folders must be on a file system all ranks see.
#include "numerics/mpi.h"  // first: it keeps mpi.h to its C API

#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
#include "apps/sweep_point.h"
#include "apps/sweep_spec.h"
#include "apps/sweep_state.h"
#include "apps/sweep_workers.h"

extern char** environ;

namespace tribo::cli {
namespace {

struct SweepArgs {
  std::string spec;
  std::string out = "out/sweep";
  bool mpi = false;
  bool dry_run = false;
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

// `head`: the column header (the provenance is beside the file: claim_output).
void write_rows(const std::filesystem::path& file, const std::string& head, const std::map<int, std::string>& rows) {
  std::string text = head + "\n";
  for (const auto& [id, row] : rows) text += row + "\n";
  write_file_atomically(file, text);
}

// The folder holds the sweep of exactly this spec and these configs, or nothing yet. Every start is
// logged in sweep.json's "runs" (date, ranks, jobs per rank), so a week-long study shows its history.
// Writes results.csv's provenance beside it (results.csv.provenance.json): sweep.json's fields as its
// first start wrote them (version, commit, command line, spec and configs with their hashes, date,
// threads per point), the same whichever start finishes the sweep. Not the axes and outputs (the
// columns say them), the runs, or the sweep process's own OpenMP threads (it runs none).
void claim_output(const std::filesystem::path& dir, const SweepSpec& spec, std::size_t points, int ranks, int jobs) {
  const std::string spec_hash = config_hash(spec.spec_file), base_hash = config_hash(spec.base_config);
  const std::string rig_hash = spec.steps.size() > 1 ? config_hash(spec.steps[1].config) : "";
  const auto file = dir / "sweep.json";
  nlohmann::json j;
  if (std::optional<nlohmann::json> claimed = read_sweep_json(dir, spec_hash, base_hash, rig_hash)) {
    j = std::move(*claimed);
  } else {
    InputFiles step_configs;  // the base config and, for a chain, the rig's
    for (const SweepStep& s : spec.steps) step_configs.push_back(s.config);
    j = provenance_json(spec.spec_file, spec_hash, step_configs);
    j["spec_hash"] = spec_hash;
    j["base_config"] = spec.base_config.string();
    j["base_config_hash"] = base_hash;
    if (spec.steps.size() > 1) {
      j["rig_config"] = spec.steps[1].config.string();
      j["rig_config_hash"] = rig_hash;
    }
    j["command"] = spec.command;
    j["points"] = points;
    j["combine"] = spec.zip ? "zip" : "product";
    j["threads_per_point"] = 1;
    for (const SweepSetting& set : spec.settings) j["set"][set.key] = setting_json(set);
    for (const SweepAxis& a : spec.axes) j["axes"].push_back({{"key", a.key}, {"values", a.values}});
    for (const SweepOutput& o : spec.outputs) j["outputs"].push_back({{"column", o.column}, {"file", o.file}, {"path", o.path}});
  }
  nlohmann::json run = provenance_json(spec.spec_file, spec_hash);
  j["runs"].push_back({{"date_utc", run["date_utc"]}, {"git_commit", run["git_commit"]}, {"mpi_ranks", ranks},
                       {"jobs_per_rank", jobs}});
  write_file_atomically(file, j.dump(2) + "\n");
  nlohmann::json made;
  for (const auto& [key, value] : j.items())
    if (key != "axes" && key != "outputs" && key != "runs" && key != "threads") made[key] = value;
  write_csv_provenance(dir / "results.csv", made);
}

std::string last_line(std::istream& in) {
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no message" : last;
}

std::string last_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  return last_line(in);
}

// The environment of a point process: one OpenMP thread when points run side by side, and none of
// the MPI launcher's variables — a child that inherited OMPI_COMM_WORLD_RANK & co. would take itself
// for a rank of the sweep's job when hypre calls MPI_Init in it, and hang or abort the job.
std::vector<std::string> child_environment(bool one_thread) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string s(*e);
    const auto starts = [&s](const char* p) { return s.rfind(p, 0) == 0; };
    if (one_thread && starts("OMP_NUM_THREADS=")) continue;
    if ((starts("OMPI_") && !starts("OMPI_ALLOW_RUN_AS_ROOT")) || starts("PMIX_") || starts("PMI_")) continue;
    env.push_back(s);
  }
  if (one_thread) env.emplace_back("OMP_NUM_THREADS=1");
  return env;
}

// How a point's steps run.
//  - fork (serial sweeps): on `jobs` worker processes forked from this sweep (apps/sweep_workers.h),
//    tribo's 47 shared libraries already loaded and relocated, each running step after step. A
//    fresh `tribo` spends ≈ 36 ms of CPU on loading alone (bench/README.md) — most of a cheap rig
//    point — and a fork and exit per point cost ≈ 5–10 ms more in copy-on-write faults and TLB
//    shootdowns, which two points at a time contend for.
//  - exec (MPI sweeps): a forked child of an MPI rank would inherit the rank's MPI state, which
//    Open MPI does not support, so each step is a fresh `tribo` process.
enum class PointStart { fork, exec };

// `tribo COMMAND dir/config.toml --out dir`: a step's command line. Without `artefacts` a point
// writes only the JSON the columns read (a chain's homogenise step keeps law.json for its rig step).
std::vector<std::string> step_arguments(const std::string& command, const std::filesystem::path& dir, bool artefacts) {
  std::vector<std::string> args{"/proc/self/exe", command, (dir / "config.toml").string(), "--out", dir.string()};
  if (command == "homogenise") args.push_back("--no-plots");
  else if (!artefacts) args.push_back("--summary-only");
  return args;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
  std::vector<char*> p;
  for (std::string& s : strings) p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}

// Starts a fresh `tribo` for one step of a point (MPI sweeps), stdout and stderr in dir/log.txt;
// returns its pid.
pid_t spawn_step(std::vector<std::string> args, const std::string& log, const std::vector<std::string>& env) {
  std::vector<char*> argv = c_strings(args);
  std::vector<std::string> env_strings = env;
  std::vector<char*> envp = c_strings(env_strings);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("sweep: cannot start a point process (posix_spawn error " + std::to_string(rc) + ")");
  return pid;
}

struct Finished {
  int id = 0;
  std::string row;
  bool failed = false;
};

// The points running on this process: up to `jobs` at a time, each a `tribo` child (the chain's
// second step starts when the first exits cleanly).
class PointPool {
 public:
  PointPool(const SweepSpec& spec, const std::vector<std::vector<double>>& points, std::filesystem::path dir, int jobs,
            PointStart how)
      : spec_(spec), points_(points), dir_(std::move(dir)), jobs_(jobs), env_(child_environment(jobs > 1)) {
    if (how == PointStart::fork) workers_ = std::make_unique<SweepWorkers>(jobs, env_, jobs > 1, run_step);
    // MPI ranks start each step as a fresh process (PointStart), which reads its config from a file.
    in_memory_ = workers_ && !spec.artefacts && spec.steps.size() == 1 && runs_in_memory(spec.steps[0].command);
  }

  // Steps of cheap points queue behind each other on a worker (SweepWorkers::kQueue), so no worker
  // waits for the sweep between them; steps that take longer than kQueueBelow_s do not, so the
  // last points of a sweep are not left queued behind a long one while another worker idles.
  static constexpr double kQueueBelow_s = 0.05;
  bool full() const {
    const std::size_t per_job = workers_ && cheap_ ? SweepWorkers::kQueue : 1;
    return running_.size() >= static_cast<std::size_t>(jobs_) * per_job;
  }
  bool empty() const { return running_.empty(); }

  void start(int id) {
    const auto pdir = point_dir(dir_, id);
    if (in_memory_) {
      std::ostringstream config;
      config << point_config(spec_, points_[id], 0) << "\n";
      // Named and anchored as the file a file step would read, so that rows and errors are the same
      // whichever way the point runs (MPI's, serial with artefacts); a failed point gets that file.
      const auto file = pdir / "config.toml";
      const long ticket =
          workers_->start(in_memory_step(spec_.steps[0].command, config.str(), file, pdir.string()), "", cheap_);
      running_[ticket] = {id, 0, std::chrono::steady_clock::now(), 0, config.str()};
      return;
    }
    for (std::size_t s = 0; s < spec_.steps.size(); ++s) {
      const auto sdir = pdir / step_folder(spec_, s);
      make_output_dir(sdir);
      std::ostringstream config;
      config << point_config(spec_, points_[id], s) << "\n";
      write_file_atomically(sdir / "config.toml", config.str());
    }
    running_[launch(0, pdir, cheap_)] = {id, 0, std::chrono::steady_clock::now(), 0, {}};
  }

  // The points finished since the last call. `block`: wait until at least one is (the pool must not
  // be empty); otherwise only collect those already done.
  std::vector<Finished> reap(bool block) {
    std::vector<Finished> done;
    while (done.empty() && !running_.empty()) {
      bool any = false;
      if (workers_) {
        for (const SweepWorkers::Finished& f : workers_->finished(block))
          any = exited(f.ticket, f.wait_status, f.wall_s, done, &f) || any;
        if (!any) break;
      } else if (block) {
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) throw std::runtime_error("sweep: waitpid failed");
        any = exited(pid, status, -1, done);
      } else {
        // Only our own children: an MPI library may have children of its own.
        std::vector<pid_t> pids;
        for (const auto& [pid, r] : running_) pids.push_back(pid);
        for (pid_t pid : pids) {
          int status = 0;
          const pid_t got = waitpid(pid, &status, WNOHANG);
          if (got < 0) throw std::runtime_error("sweep: waitpid failed");
          if (got == pid) any = exited(pid, status, -1, done) || any;
        }
        if (!any) break;
      }
    }
    return done;
  }

 private:
  struct Running {
    int id = 0;
    std::size_t step = 0;
    std::chrono::steady_clock::time_point start;  // of the step
    double earlier_steps_s = 0;                   // a chain's finished steps' wall time
    std::string config;                           // an in-memory point's config text
  };

  // Starts a step (on a worker, may queue behind another; or as a fresh process); returns the
  // handle that names it until it ends: a worker's ticket, or the process's pid.
  long launch(std::size_t step, const std::filesystem::path& pdir, bool queue) const {
    const auto sdir = pdir / step_folder(spec_, step);
    std::vector<std::string> args = step_arguments(spec_.steps[step].command, sdir, spec_.artefacts);
    const std::string log = (sdir / "log.txt").string();
    return workers_ ? workers_->start(command_line_step(args), log, queue) : spawn_step(std::move(args), log, env_);
  }

  // Bookkeeping for a finished step (`wall_s` its own wall time, or -1: measured here, from its
  // start; `worker`: what a worker sent back): the next step, or the point's row.
  bool exited(long handle, int status, double wall_s, std::vector<Finished>& done,
              const SweepWorkers::Finished* worker = nullptr) {
    const auto it = running_.find(handle);
    if (it == running_.end()) return false;
    const Running r = it->second;
    running_.erase(it);
    if (wall_s < 0) wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
    cheap_ = wall_s < kQueueBelow_s;
    const auto pdir = point_dir(dir_, r.id);
    const auto sdir = pdir / step_folder(spec_, r.step);
    std::string error, values;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      if (in_memory_) {
        std::istringstream log(worker->log);
        error = last_line(log);
      } else {
        error = last_line(sdir / "log.txt");
      }
      if (WIFSIGNALED(status)) error = "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + "): " + error;
      if (spec_.steps.size() > 1) error = spec_.steps[r.step].command + ": " + error;
    } else if (r.step + 1 < spec_.steps.size()) {
      // A step just ended, so a worker has room even when steps no longer queue.
      running_[launch(r.step + 1, pdir, true)] = {r.id, r.step + 1, std::chrono::steady_clock::now(), r.earlier_steps_s + wall_s, {}};
      return true;
    } else if (in_memory_) {
      values = in_memory_values(pdir, worker->answer, error);
    } else {
      try {
        for (const SweepOutput& o : spec_.outputs) values += "," + json_field(output_file(pdir, o), o.path);
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
    const double wall = r.earlier_steps_s + wall_s;
    if (!error.empty() && in_memory_) keep_failed_point(pdir, r.config, *worker);
    if (!error.empty()) values = std::string(spec_.outputs.size(), ',');
    std::string row = std::to_string(r.id);
    for (double v : points_[r.id]) row += "," + exact(v);
    row += std::string(",") + (error.empty() ? "ok" : "failed") + "," + (error.empty() ? "" : csv_quoted(error)) + "," +
           exact(wall) + values;
    done.push_back({r.id, row, !error.empty()});
    return true;
  }

  // An in-memory point's columns (",v1,v2,…") from the JSON it sent back, named as the files a
  // file step writes; `error` gets the first missing one.
  std::string in_memory_values(const std::filesystem::path& pdir, const std::vector<std::string>& answer,
                               std::string& error) const {
    std::string values;
    try {
      std::map<std::string, nlohmann::json> files;
      for (std::size_t k = 0; k + 1 < answer.size(); k += 2) files[answer[k]] = nlohmann::json::parse(answer[k + 1]);
      for (const SweepOutput& o : spec_.outputs) {
        const auto it = files.find(o.file);
        if (it == files.end()) throw std::runtime_error((pdir / o.file).string() + ": cannot read");
        values += "," + json_field(it->second, pdir / o.file, o.path);
      }
    } catch (const std::exception& e) {
      error = e.what();
    }
    return values;
  }

  // A failed in-memory point's folder, as a file step leaves it: config.toml, log.txt and its JSON,
  // so the error names files that exist and `tribo COMMAND DIR/points/NNNNN/config.toml` reruns it.
  // Failures are few; a point that succeeds writes nothing.
  void keep_failed_point(const std::filesystem::path& pdir, const std::string& config,
                         const SweepWorkers::Finished& worker) const {
    make_output_dir(pdir);
    write_file_atomically(pdir / "config.toml", config);
    write_file_atomically(pdir / "log.txt", worker.log);
    for (std::size_t k = 0; k + 1 < worker.answer.size(); k += 2)
      write_file_atomically(pdir / worker.answer[k], worker.answer[k + 1]);
  }

  // An output's file: in a chain "STEP/FILE" as written, else FILE of the last step that has it.
  std::filesystem::path output_file(const std::filesystem::path& pdir, const SweepOutput& o) const {
    if (spec_.steps.size() == 1 || o.file.find('/') != std::string::npos) return pdir / o.file;
    for (std::size_t s = spec_.steps.size(); s-- > 0;) {
      const auto f = pdir / step_folder(spec_, s) / o.file;
      if (std::filesystem::exists(f)) return f;
    }
    return pdir / step_folder(spec_, spec_.steps.size() - 1) / o.file;  // absent: the error names it
  }

  const SweepSpec& spec_;
  const std::vector<std::vector<double>>& points_;
  std::filesystem::path dir_;
  int jobs_;
  std::vector<std::string> env_;
  std::unique_ptr<SweepWorkers> workers_;  // PointStart::fork
  bool in_memory_ = false;                 // points run on their config in memory (apps/sweep_point.h)
  bool cheap_ = false;                     // the last step took under kQueueBelow_s
  std::map<long, Running> running_;
};

// results.csv on rank 0: each row appended and flushed the moment its point is done.
class ResultsWriter {
 public:
  ResultsWriter(std::filesystem::path file, std::map<int, std::string> rows, int total)
      : file_(std::move(file)), rows_(std::move(rows)),
        progress_("sweep: " + std::to_string(total) + " points", total), append_(file_, std::ios::app) {
    if (!append_) throw std::runtime_error(file_.string() + ": cannot append");
    for (std::size_t k = 0; k < rows_.size(); ++k) progress_.step("done before");
  }
  void record(const Finished& f) {
    append_ << f.row << '\n' << std::flush;  // the row is kept the moment the point is done
    if (!append_) throw std::runtime_error(file_.string() + ": cannot append");
    rows_[f.id] = f.row;
    failed_ += f.failed ? 1 : 0;
    progress_.step("point " + std::to_string(f.id) + (f.failed ? " failed" : ""));
  }
  // Rewrites results.csv sorted by point id.
  void finish(const std::string& head) {
    progress_.done();
    append_.close();
    write_rows(file_, head, rows_);
  }
  int failed() const { return failed_; }

 private:
  std::filesystem::path file_;
  std::map<int, std::string> rows_;
  Progress progress_;
  std::ofstream append_;
  int failed_ = 0;
};

// Points run at once on this process: the spec's jobs, else the cores this process may use. The
// point processes inherit its CPU affinity, so that is what counts: a rank mpirun bound to one core
// runs one point at a time; an unbound rank shares the node's cores with the other ranks on it
// (so N ranks on one machine do not oversubscribe it). A Slurm or taskset mask counts the same way.
int local_jobs(const SweepSpec& spec) {
  if (spec.jobs > 0) return spec.jobs;
  const int node_cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  int cores = node_cores;
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof mask, &mask) == 0) cores = std::max(1, CPU_COUNT(&mask));
  if (cores < node_cores) return cores;  // bound: the mask is this process's share
  int local_ranks = 1;
  if (const char* s = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE")) local_ranks = std::max(1, std::atoi(s));
  return std::max(1, cores / local_ranks);
}

// ---- MPI ----------------------------------------------------------------------------------------

void mpi_check(int rc, const char* what) {
  if (rc == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(rc, text, &len);
  std::fprintf(stderr, "tribo: failed: sweep: %s: %.*s\n", what, len, text);
  MPI_Abort(MPI_COMM_WORLD, 1);  // a rank that cannot talk would leave the others waiting forever
}

// MPI for the lifetime of an MPI sweep. The thread level hypre's backend asks for
// (lubrication/linear_solver.cpp), should anything in this process ever reach it.
class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    mpi_check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided), "MPI_Init_thread");
    // Errors come back as codes, so mpi_check can say which call failed before the job is aborted
    // (the default handler would abort without naming it).
    mpi_check(MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler");
    mpi_check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
    mpi_check(MPI_Comm_size(MPI_COMM_WORLD, &size), "MPI_Comm_size");
  }
  ~MpiSession() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank = 0, size = 1;
};

constexpr int kTagRequest = 1;  // worker → 0: a slot is free (payload: int 0)
constexpr int kTagAssign = 2;   // 0 → worker: a point id, or -1 for "no more"
constexpr int kTagRow = 3;      // worker → 0: a finished row, first char 'o' (ok) or 'f' (failed)

bool mpi_requested(const SweepArgs& args) {
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  return args.mpi || (size && std::atoi(size) > 1);
}

// Rank 0: its own pool plus the other ranks' requests, until every point is recorded.
void mpi_master(PointPool& pool, ResultsWriter& results, const std::vector<int>& pending, int size) {
  std::size_t next = 0;
  int told_done = 0;    // workers sent -1 (they ask no more)
  long outstanding = 0;  // points handed out whose rows have not come back
  while (true) {
    bool busy = false;
    while (next < pending.size() && !pool.full()) pool.start(pending[next++]);
    for (const Finished& f : pool.reap(false)) {
      results.record(f);
      busy = true;
    }
    for (int flag = 1; flag;) {
      MPI_Status st;
      mpi_check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st), "MPI_Iprobe");
      if (!flag) break;
      busy = true;
      if (st.MPI_TAG == kTagRequest) {
        int ignored = 0;
        mpi_check(MPI_Recv(&ignored, 1, MPI_INT, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
        const int id = next < pending.size() ? pending[next++] : -1;
        if (id < 0) {
          ++told_done;
        } else {
          ++outstanding;
        }
        mpi_check(MPI_Send(&id, 1, MPI_INT, st.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD), "MPI_Send");
      } else if (st.MPI_TAG == kTagRow) {
        int count = 0;
        mpi_check(MPI_Get_count(&st, MPI_CHAR, &count), "MPI_Get_count");
        std::string msg(static_cast<std::size_t>(count), '\0');
        mpi_check(MPI_Recv(msg.data(), count, MPI_CHAR, st.MPI_SOURCE, kTagRow, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
        const std::string row = msg.substr(1);
        results.record({std::stoi(row.substr(0, row.find(','))), row, msg[0] == 'f'});
        --outstanding;
      } else {
        std::fprintf(stderr, "tribo: failed: sweep: unexpected MPI message tag %d from rank %d\n", st.MPI_TAG, st.MPI_SOURCE);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    }
    if (next >= pending.size() && pool.empty() && outstanding == 0 && told_done == size - 1) return;
    // Nothing to do: a short nap instead of spinning on a core the points need. 1 ms is far below
    // any point's cost and the per-point overhead budget.
    if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

// Ranks > 0: ask for a point whenever a slot is free, run it, send its row back.
void mpi_worker(PointPool& pool) {
  bool more = true;
  while (true) {
    while (more && !pool.full()) {
      int id = 0;
      mpi_check(MPI_Send(&id, 1, MPI_INT, 0, kTagRequest, MPI_COMM_WORLD), "MPI_Send");
      mpi_check(MPI_Recv(&id, 1, MPI_INT, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
      if (id < 0) {
        more = false;
      } else {
        pool.start(id);
      }
    }
    if (pool.empty()) return;
    for (const Finished& f : pool.reap(true)) {
      std::string msg = (f.failed ? "f" : "o") + f.row;
      mpi_check(MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_CHAR, 0, kTagRow, MPI_COMM_WORLD), "MPI_Send");
    }
  }
}

// CPU time of this process alone (not its children): what the sweep itself costs, whatever the load.
double own_cpu_ms() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0.0;
  return 1e3 * (u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-3 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// ---- the sweep ----------------------------------------------------------------------------------

void run_serial(const SweepArgs& args) {
  const SweepSpec spec = load_sweep_spec(args.spec);
  const auto points = sweep_points(spec);
  const std::filesystem::path dir(args.out), results = dir / "results.csv";
  const int jobs = local_jobs(spec);
  make_output_dir(dir);
  claim_output(dir, spec, points.size(), 1, jobs);
  const std::string head = header(spec);
  std::map<int, std::string> rows = finished_sweep_rows(results, head);
  write_rows(results, head, rows);  // drops a torn line before appending

  std::vector<int> pending;
  for (int k = 0; k < static_cast<int>(points.size()); ++k)
    if (!rows.count(k)) pending.push_back(k);
  ResultsWriter writer(results, std::move(rows), static_cast<int>(points.size()));
  PointPool pool(spec, points, dir, jobs, PointStart::fork);
  std::size_t next = 0;
  while (next < pending.size() || !pool.empty()) {
    while (next < pending.size() && !pool.full()) pool.start(pending[next++]);
    for (const Finished& f : pool.reap(true)) writer.record(f);
  }
  writer.finish(head);
  std::printf("sweep: %zu points (%d failed this run) -> %s\n", points.size(), writer.failed(), results.string().c_str());
  // What the sweep itself cost (bench/README.md: the per-point overhead), start-up included.
  if (!pending.empty())
    std::printf("sweep: %zu points run; the sweep's own CPU time %.2f ms per point run\n", pending.size(),
                own_cpu_ms() / static_cast<double>(pending.size()));
}

void run_mpi(const SweepArgs& args) {
  MpiSession mpi;
  const std::filesystem::path dir(args.out), results = dir / "results.csv";
  // Rank 0 checks the spec and claims DIR first; the others learn whether to go on, so a bad spec
  // gives one message and status 2 from rank 0, not one per rank.
  int ok = 1;
  std::unique_ptr<SweepSpec> spec;
  std::vector<std::vector<double>> points;
  std::map<int, std::string> rows;
  std::string head;
  if (mpi.rank == 0) {
    try {
      spec = std::make_unique<SweepSpec>(load_sweep_spec(args.spec));
      points = sweep_points(*spec);
      make_output_dir(dir);
      claim_output(dir, *spec, points.size(), mpi.size, local_jobs(*spec));
      head = header(*spec);
      rows = finished_sweep_rows(results, head);
      write_rows(results, head, rows);  // drops a torn line before appending
    } catch (...) {
      ok = 0;
      mpi_check(MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
      throw;  // main prints it; MpiSession finalises
    }
  }
  mpi_check(MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  if (!ok) {
    // Rank 0 has the message and exits 2, which becomes mpirun's status. This rank leaves quietly
    // with 0: a non-zero exit here could reach mpirun first, and mpirun then kills rank 0 before
    // it has printed why.
    mpi_check(MPI_Finalize(), "MPI_Finalize");
    std::exit(0);
  }
  try {
    if (mpi.rank != 0) {
      spec = std::make_unique<SweepSpec>(load_sweep_spec(args.spec));
      points = sweep_points(*spec);
    }
    PointPool pool(*spec, points, dir, local_jobs(*spec), PointStart::exec);
    if (mpi.rank == 0) {
      std::vector<int> pending;
      for (int k = 0; k < static_cast<int>(points.size()); ++k)
        if (!rows.count(k)) pending.push_back(k);
      ResultsWriter writer(results, std::move(rows), static_cast<int>(points.size()));
      mpi_master(pool, writer, pending, mpi.size);
      writer.finish(head);
      std::printf("sweep: %zu points on %d MPI ranks (%d failed this run) -> %s\n", points.size(), mpi.size,
                  writer.failed(), results.string().c_str());
    } else {
      mpi_worker(pool);
    }
  } catch (const std::exception& e) {
    // One rank out means the rest would wait for it forever: take the job down. Rows already
    // written stay; the same command resumes.
    std::fprintf(stderr, "tribo: failed: sweep (MPI rank %d): %s\n", mpi.rank, e.what());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
}

// --dry-run: the spec checked, every point's configs built (a bad value shows now, not a week in),
// the points listed; nothing written.
void dry_run(const SweepArgs& args) {
  const SweepSpec spec = load_sweep_spec(args.spec);
  const auto points = sweep_points(spec);
  std::string steps;
  for (const SweepStep& s : spec.steps) {
    if (!steps.empty()) steps += " -> ";
    steps += s.command;
    steps += ' ';
    steps += s.config.string();
  }
  std::printf("sweep: %zu points of %s, %d at a time per process\n", points.size(), steps.c_str(), local_jobs(spec));
  for (const SweepSetting& set : spec.settings)
    std::printf("set %s = %s\n", set.key.c_str(), setting_json(set).dump().c_str());
  std::printf("%s\n", header(spec).c_str());
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (std::size_t s = 0; s < spec.steps.size(); ++s) point_config(spec, points[k], s);
    std::string row = std::to_string(k);
    for (double v : points[k]) {
      row += ',';
      row += exact(v);
    }
    std::printf("%s\n", row.c_str());
  }
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand("sweep", "parameter study: one tribo command (or the homogenise+rig chain) over "
                                              "axes of config keys, resumable, serial or under mpirun");
  cmd->add_option("spec", args->spec, "SPEC.toml: [base] command, config, rig_config; [base.set] fixed values; [[axis]] key, values or "
                                      "from/to/count/scale; [sweep] combine, jobs; [outputs] columns, names (docs/sweep.md)")
      ->required();
  cmd->add_option("--out", args->out, "output directory (results.csv, sweep.json, points/)")->capture_default_str();
  cmd->add_flag("--mpi", args->mpi, "share the points over MPI ranks (automatic under Open MPI's mpirun with -np > 1)");
  cmd->add_flag("--dry-run", args->dry_run, "check the spec, print the points and their commands, run nothing");
  cmd->callback([args] {
    if (args->dry_run) {
      dry_run(*args);
    } else if (mpi_requested(*args)) {
      run_mpi(*args);
    } else {
      run_serial(*args);
    }
  });
}

}  // namespace tribo::cli
