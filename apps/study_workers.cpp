#include "study_workers.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace inpact::app::study {

namespace {

using Clock = std::chrono::steady_clock;

/// Reads or writes exactly n bytes (retrying on EINTR and short transfers); false on EOF or error.
bool read_all(int fd, void* data, std::size_t n) {
  auto* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t got = read(fd, p, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got;
    n -= static_cast<std::size_t>(got);
  }
  return true;
}

bool write_all(int fd, const void* data, std::size_t n) {
  const auto* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t put = write(fd, p, n);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    p += put;
    n -= static_cast<std::size_t>(put);
  }
  return true;
}

int reap(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

WorkerPool::WorkerPool(int jobs, RunCase run) : jobs_(std::max(jobs, 1)), run_(std::move(run)) {
  // A worker killed between two cases: handing it the next one must fail with EPIPE (and go to
  // a new worker), not end the study with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
}

WorkerPool::~WorkerPool() {
  for (Worker& w : workers_) stop(w);
}

bool WorkerPool::has_idle() const { return static_cast<int>(running()) < jobs_; }

std::size_t WorkerPool::running() const {
  return static_cast<std::size_t>(std::count_if(workers_.begin(), workers_.end(), [](const Worker& w) { return w.busy; }));
}

WorkerPool::Worker& WorkerPool::fork_worker() {
  int commands[2], replies[2];
  if (pipe2(commands, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  if (pipe2(replies, O_CLOEXEC) != 0) {
    close(commands[0]);
    close(commands[1]);
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
  std::fflush(nullptr);  // the worker must not print this process's buffered lines again
  const pid_t pid = fork();
  if (pid < 0) {
    for (int fd : {commands[0], commands[1], replies[0], replies[1]}) close(fd);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // The worker: only its own pipe ends stay open (another worker's command pipe held open
    // here would keep that worker from seeing the end of the study).
    for (const Worker& w : workers_)
      if (w.pid >= 0) {
        close(w.commands);
        close(w.replies);
      }
    close(commands[1]);
    close(replies[0]);
    std::uint64_t k = 0;
    while (read_all(commands[0], &k, sizeof k)) {
      const std::int32_t rc = run_(static_cast<std::size_t>(k));
      std::fflush(nullptr);
      if (!write_all(replies[1], &rc, sizeof rc) || rc != 0) break;  // a failed case ends its worker
    }
    _exit(0);  // not exit(): the study's atexit handlers and static objects are not the worker's
  }
  close(commands[0]);
  close(replies[1]);
  Worker w;
  w.pid = pid;
  w.commands = commands[1];
  w.replies = replies[0];
  workers_.push_back(w);
  return workers_.back();
}

void WorkerPool::stop(Worker& w) {
  if (w.pid < 0) return;
  close(w.commands);
  close(w.replies);
  w.commands = w.replies = -1;  // their numbers go to the next pipes opened
  last_status_ = reap(w.pid);
  w.pid = -1;
}

void WorkerPool::start(std::size_t k) {
  Worker* idle = nullptr;
  for (Worker& w : workers_)
    if (!w.busy && w.pid >= 0) idle = &w;
  if (!idle) {
    // Forget the workers that ended, then fork one.
    workers_.erase(std::remove_if(workers_.begin(), workers_.end(), [](const Worker& w) { return w.pid < 0; }),
                   workers_.end());
    idle = &fork_worker();
  }
  const std::uint64_t message = k;
  idle->busy = true;
  idle->k = k;
  idle->started = Clock::now();
  if (!write_all(idle->commands, &message, sizeof message)) {
    // The worker died between cases: the case never started there; record how it ended.
    idle->busy = false;
    stop(*idle);
    idle = &fork_worker();
    idle->busy = true;
    idle->k = k;
    idle->started = Clock::now();
    if (!write_all(idle->commands, &message, sizeof message)) throw std::runtime_error("cannot reach a new worker");
  }
}

WorkerPool::Ended WorkerPool::wait() {
  for (;;) {
    std::vector<pollfd> fds;
    std::vector<Worker*> who;
    for (Worker& w : workers_)
      if (w.busy) {
        fds.push_back({w.replies, POLLIN, 0});
        who.push_back(&w);
      }
    if (fds.empty()) throw std::logic_error("WorkerPool::wait with no case running");
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Worker& w = *who[i];
      w.busy = false;
      const double wall = std::chrono::duration<double>(Clock::now() - w.started).count();
      std::int32_t rc = 0;
      if (read_all(w.replies, &rc, sizeof rc)) {
        if (rc != 0) stop(w);  // it ends after a failed case
        return {w.k, (rc & 0xff) << 8, wall, w.started};  // as waitpid reports an exit code
      }
      stop(w);  // the worker died in the case: its wait status says how
      return {w.k, last_status_, wall, w.started};
    }
  }
}

}  // namespace inpact::app::study
