// The worker processes of a serial `tribo sweep` (issue 17): `count` children forked from the sweep,
// each running step after step in its own process — the sweep's Task on each step's message
// (apps/sweep_point.h), stdout and stderr into the step's log: a file, or the worker's log in
// memory, which comes back with the step's answer. A worker lives for the whole sweep, so
// a cheap point costs its own work, not a fork, copy-on-write faults and an exit: on the 2-core
// machine those kernel costs, serialised by TLB-shootdown interrupts, held two points at a time to
// ≈ 1.1–1.8× the throughput of one (bench/README.md).
//
// A worker is forked when first needed and again after one dies: a step that crashes its worker
// (a signal, or exit() inside a command) ends with the worker's wait status, and the step queued
// behind it goes to a fresh worker. When the sweep ends the workers read end-of-file and exit; when it is killed they
// are killed too (PR_SET_PDEATHSIG), so no step outlives the sweep that started it.
#pragma once

#include <sys/types.h>

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace tribo::cli {

class SweepWorkers {
 public:
  // What a worker does with a step's `message`, its stdout and stderr already on the step's log:
  // returns the exit status (0 done, 1 failed, 2 bad input), and fills `answer` (sent back).
  using Task = std::function<int(std::vector<std::string>& message, std::vector<std::string>& answer)>;

  // `env`: the environment a worker runs in; `one_thread`: one OpenMP thread per step.
  SweepWorkers(int count, std::vector<std::string> env, bool one_thread, Task task);
  ~SweepWorkers();
  SweepWorkers(const SweepWorkers&) = delete;
  SweepWorkers& operator=(const SweepWorkers&) = delete;

  // A worker holds at most this many steps: the one it runs and one queued behind it, which it
  // starts without waiting for the sweep to hand it over (what cheap points wait on).
  static constexpr std::size_t kQueue = 2;

  // Hands `message` (the Task's) to the least busy worker, its output into the file `log`, or with
  // "" into the worker's log in memory (Finished::log: nothing per step on disk); `queue`: whether
  // it may wait behind a running step (else an idle worker must exist). Returns the step's ticket,
  // which names it until it finishes.
  long start(const std::vector<std::string>& message, const std::string& log, bool queue);

  struct Finished {
    long ticket = 0;
    int wait_status = 0;  // as waitpid gives it: the Task's exit status, or the dead worker's
    double wall_s = -1;   // the step's own wall time, as the worker measured it (-1: it died)
    std::vector<std::string> answer;  // the Task's (empty when the worker died)
    std::string log;      // the step's output when its log was in memory (a dead worker's too)
  };
  // The steps finished since the last call. `block`: wait until at least one is (one must be running).
  std::vector<Finished> finished(bool block);

 private:
  struct Step {
    long ticket = 0;
    std::vector<std::string> message;  // the log ("": in memory), then the Task's message
  };
  struct Worker {
    pid_t pid = 0;  // 0: not started, or dead and reaped
    int socket = -1;
    int memory_log = -1;  // a memfd the worker writes in-memory logs to, readable here after it dies
    std::deque<Step> steps;  // sent to it, in order; the first is running
  };
  void fork_worker(Worker& w);
  void send(Worker& w, const Step& step);
  [[noreturn]] void serve(int socket, int memory_log) const;
  void bury(Worker& w, std::vector<Finished>& done);

  std::vector<Worker> workers_;
  std::vector<std::string> env_;
  bool one_thread_;
  Task task_;
  long next_ticket_ = 0;
};

}  // namespace tribo::cli
