#include "apps/sweep_workers.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <omp.h>

#include <cassert>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace tribo::cli {
namespace {

// Whole buffers over a stream socket; false when the other side has gone (EOF, EPIPE).
bool send_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t k = send(fd, p, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool receive_all(int fd, void* data, std::size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t k = recv(fd, p, n, 0);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

// A worker's answer to a step: the command's exit status and its wall time.
struct Reply {
  int status = 0;
  double wall_s = 0;
};

// Strings over the socket: their number, then each as its length and bytes (a step: its log first;
// an answer: the log last).
bool send_strings(int fd, const std::vector<std::string>& strings) {
  const auto count = static_cast<std::uint32_t>(strings.size());
  if (!send_all(fd, &count, sizeof count)) return false;
  for (const std::string& s : strings) {
    const auto n = static_cast<std::uint32_t>(s.size());
    if (!send_all(fd, &n, sizeof n) || !send_all(fd, s.data(), s.size())) return false;
  }
  return true;
}

bool receive_strings(int fd, std::vector<std::string>& strings) {
  std::uint32_t count = 0;
  if (!receive_all(fd, &count, sizeof count)) return false;
  strings.assign(count, {});
  for (std::string& s : strings) {
    std::uint32_t n = 0;
    if (!receive_all(fd, &n, sizeof n)) return false;
    s.resize(n);
    if (!receive_all(fd, s.data(), n)) return false;
  }
  return true;
}

// All of a memfd's bytes (pread: the offset the worker writes at stays where it is).
std::string read_memory_log(int fd) {
  struct stat st {};
  if (fd < 0 || fstat(fd, &st) != 0) return {};
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t k = pread(fd, text.data() + got, text.size() - got, static_cast<off_t>(got));
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    got += static_cast<std::size_t>(k);
  }
  text.resize(got);
  return text;
}

}  // namespace

SweepWorkers::SweepWorkers(int count, std::vector<std::string> env, bool one_thread, Task task)
    : workers_(static_cast<std::size_t>(count)), env_(std::move(env)), one_thread_(one_thread), task_(std::move(task)) {
  assert(count >= 1);
}

SweepWorkers::~SweepWorkers() {
  for (Worker& w : workers_) {
    if (w.memory_log >= 0) close(w.memory_log);
    if (w.pid == 0) continue;
    close(w.socket);  // an idle worker reads end-of-file and exits
    int status = 0;
    while (waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
}

void SweepWorkers::fork_worker(Worker& w) {
  // Made here and inherited, so that the log of a step that kills its worker can still be read.
  // A memfd, not a file: nothing on disk per worker either.
  if (w.memory_log < 0 && (w.memory_log = memfd_create("tribo-sweep-step-log", MFD_CLOEXEC)) < 0)
    throw std::runtime_error("sweep: cannot start a worker (memfd_create: " + std::string(std::strerror(errno)) + ")");
  int pair[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
    throw std::runtime_error("sweep: cannot start a worker (socketpair: " + std::string(std::strerror(errno)) + ")");
  std::fflush(nullptr);  // nothing buffered here may be written twice by the child
  const pid_t sweep = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(pair[0]);
    close(pair[1]);
    throw std::runtime_error("sweep: cannot start a worker (fork: " + std::string(std::strerror(errno)) + ")");
  }
  if (pid == 0) {
    // A killed sweep takes its workers with it: a step left running would write its point's folder
    // while the resumed sweep runs that point again.
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != sweep) _exit(1);
    // The other workers' sockets must close here: a worker holding another's would keep it from
    // reading end-of-file when the sweep is killed, and both would wait for ever.
    for (const Worker& other : workers_) {
      if (other.pid != 0) close(other.socket);
      if (&other != &w && other.memory_log >= 0) close(other.memory_log);
    }
    close(pair[0]);
    serve(pair[1], w.memory_log);
  }
  close(pair[1]);
  w.pid = pid;
  w.socket = pair[0];
}

// The worker's side. The sweep process never enters an OpenMP parallel region, so the fork has no
// thread pool to lose (libgomp's pool does not survive fork); the steps start their own.
void SweepWorkers::serve(int socket, int memory_log) const {
  clearenv();
  for (const std::string& e : env_) {
    const std::size_t eq = e.find('=');
    if (eq != std::string::npos) setenv(e.substr(0, eq).c_str(), e.substr(eq + 1).c_str(), 1);
  }
  std::vector<std::string> message, answer;
  while (receive_strings(socket, message) && !message.empty()) {
    const auto start = std::chrono::steady_clock::now();
    const bool in_memory = message[0].empty();
    int status = 127;  // the log cannot be opened: the row says "no message"
    answer.clear();
    int fd = memory_log;
    if (in_memory) {
      if (ftruncate(memory_log, 0) != 0 || lseek(memory_log, 0, SEEK_SET) != 0) fd = -1;
    } else {
      fd = open(message[0].c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    }
    if (fd >= 0 && dup2(fd, STDOUT_FILENO) >= 0 && dup2(fd, STDERR_FILENO) >= 0) {
      if (!in_memory) close(fd);
      // OMP_NUM_THREADS was read when this image was loaded, and a step may have set its own count.
      if (one_thread_) omp_set_num_threads(1);
      message.erase(message.begin());
      status = task_(message, answer);
      std::fflush(nullptr);
    } else if (fd >= 0 && !in_memory) {
      close(fd);
    }
    answer.push_back(in_memory ? read_memory_log(memory_log) : std::string());
    const Reply reply{status, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    if (!send_all(socket, &reply, sizeof reply) || !send_strings(socket, answer)) break;
  }
  std::exit(0);  // atexit handlers run: hypre and MPI finalise if a step started them
}

// Sends a step to `w`, forking it first if needed, or afresh if it died idle (killed from outside).
void SweepWorkers::send(Worker& w, const Step& step) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (w.pid == 0) fork_worker(w);
    if (send_strings(w.socket, step.message)) return;
    std::vector<Finished> none;  // its queue is empty: it was idle
    bury(w, none);
  }
  throw std::runtime_error("sweep: a fresh worker does not take its step");
}

long SweepWorkers::start(const std::vector<std::string>& message, const std::string& log, bool queue) {
  Worker* best = nullptr;
  for (Worker& w : workers_)
    if (!best || w.steps.size() < best->steps.size()) best = &w;
  if (!best || best->steps.size() >= (queue ? kQueue : 1)) throw std::logic_error("SweepWorkers::start: every worker is busy");
  Step step{next_ticket_++, {log}};
  step.message.insert(step.message.end(), message.begin(), message.end());
  send(*best, step);
  best->steps.push_back(std::move(step));
  return best->steps.back().ticket;
}

// A worker whose socket closed: reaped; its running step (if any) ends with the worker's wait
// status, and the steps queued behind it go to a fresh worker.
void SweepWorkers::bury(Worker& w, std::vector<Finished>& done) {
  int status = 0;
  while (waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
  }
  close(w.socket);
  w.pid = 0;
  w.socket = -1;
  if (w.steps.empty()) return;
  const Step& dead = w.steps.front();
  done.push_back({dead.ticket, status, -1, {}, dead.message[0].empty() ? read_memory_log(w.memory_log) : std::string()});
  w.steps.pop_front();
  for (const Step& queued : w.steps) send(w, queued);
}

std::vector<SweepWorkers::Finished> SweepWorkers::finished(bool block) {
  std::vector<Finished> done;
  while (done.empty()) {
    std::vector<pollfd> fds;
    std::vector<Worker*> polled;
    for (Worker& w : workers_)
      if (!w.steps.empty()) {
        fds.push_back({w.socket, POLLIN, 0});
        polled.push_back(&w);
      }
    assert(!(block && fds.empty()) && "SweepWorkers::finished(block) with nothing running");
    if (fds.empty()) break;
    const int ready = poll(fds.data(), fds.size(), block ? -1 : 0);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw std::runtime_error("sweep: poll failed (" + std::string(std::strerror(errno)) + ")");
    for (std::size_t k = 0; k < fds.size(); ++k) {
      if (fds[k].revents == 0) continue;
      Worker& w = *polled[k];
      Reply reply;
      std::vector<std::string> answer;
      if (receive_all(w.socket, &reply, sizeof reply) && receive_strings(w.socket, answer) && !answer.empty()) {
        std::string log = std::move(answer.back());
        answer.pop_back();
        done.push_back({w.steps.front().ticket, W_EXITCODE(reply.status & 0xff, 0), reply.wall_s, std::move(answer),
                        std::move(log)});
        w.steps.pop_front();
      } else {
        bury(w, done);  // died in the step: a signal, or exit() inside the command
      }
    }
    if (!block) break;
  }
  return done;
}

}  // namespace tribo::cli
