#pragma once
/// The worker processes of `inpact study`: forks of the study that run its cases in-process,
/// one after another, each handed over a pipe.
///
/// A worker outlives its cases, so a case pays neither a process start nor a process exit
/// (the kernel freeing a 20 MB address space page by page: about 2 ms of a 0.2 s case), and
/// its heap is already mapped. Each case still runs apart from the study: a case that crashes
/// or is killed takes its worker with it and nothing else (the study records the case as
/// killed and forks a new worker for the next); a case that fails ends its worker too, so a
/// worker only ever goes on after a case that completed.
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

#include <sys/types.h>

namespace inpact::app::study {

class WorkerPool {
 public:
  /// Runs case k inside a worker and returns its exit code (0: completed).
  using RunCase = std::function<int(std::size_t k)>;

  WorkerPool(int jobs, RunCase run);
  /// Closes the workers' command pipes and waits for them to exit.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  bool has_idle() const;     ///< fewer cases running than workers allowed
  std::size_t running() const;
  /// Hands case k to an idle worker, forking one when none is waiting. Throws on fork failure.
  void start(std::size_t k);

  struct Ended {
    std::size_t k;
    int wait_status;  ///< as waitpid gives it: exit code of the case, or the signal that killed its worker
    double wall;      ///< seconds from start() to the end
    std::chrono::steady_clock::time_point started;
  };
  /// Blocks until a running case ends. Precondition: running() > 0.
  Ended wait();

 private:
  struct Worker {
    pid_t pid = -1;
    int commands = -1;  ///< write end: case numbers to the worker
    int replies = -1;   ///< read end: exit codes from the worker
    bool busy = false;
    std::size_t k = 0;
    std::chrono::steady_clock::time_point started;
  };
  Worker& fork_worker();
  void stop(Worker& w);  ///< close its pipes and reap it; returns its wait status in last_status_
  int jobs_;
  RunCase run_;
  std::vector<Worker> workers_;
  int last_status_ = 0;
};

}  // namespace inpact::app::study
