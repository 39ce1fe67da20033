#include "study_runner.hpp"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <deque>
#include <limits>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include "case_values.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/io_error.hpp"
#include "io/results_reader.hpp"
#include "io/results_writer.hpp"
#include "study_workers.hpp"

namespace inpact::app::study {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

fs::path case_dir(const fs::path& dir, const std::string& id) { return dir / "cases" / id; }
fs::path outcome_path(const fs::path& dir, const std::string& id) { return case_dir(dir, id) / "case.result"; }
/// The values a forked case collected in memory (written after its results file COMPLETED).
fs::path values_path(const fs::path& dir, const std::string& id) { return case_dir(dir, id) / "values.txt"; }

/// The options of one case's `inpact run`: job ID in DIR/cases/ID, quiet, the case's
/// parameters, and its phase times in DIR/cases/ID/timings.txt.
RunOptions case_run_options(const Manifest& m, const Case& c, const RunnerOptions& o) {
  RunOptions r;
  r.deck = m.deck;
  r.job = c.id;
  r.output_dir = case_dir(o.dir, c.id).string();
  r.threads = o.threads;
  r.parameters.insert(c.parameters.begin(), c.parameters.end());
  r.quiet = true;
  r.timings = (case_dir(o.dir, c.id) / "timings.txt").string();
  r.collect = m.collect;
  r.values = values_path(o.dir, c.id).string();
  return r;
}

/// The command line of the same run, for an `--inpact EXE` given to the study; under
/// `mpirun -np N` for N ranks per case ($INPACT_MPIRUN names another launcher).
std::vector<std::string> case_command(const RunOptions& r, const std::string& executable, int ranks) {
  std::vector<std::string> args;
  if (ranks > 1) {
    const char* launcher = std::getenv("INPACT_MPIRUN");
    args = {launcher && *launcher ? launcher : "mpirun", "-np", std::to_string(ranks)};
  }
  args.insert(args.end(), {executable, "run", r.deck, "-j", r.job, "-o", r.output_dir, "--threads",
                           std::to_string(r.threads), "-q", "--timings", r.timings});
  for (const auto& [name, value] : r.parameters) {
    args.push_back("-P");
    args.push_back(name + "=" + value);
  }
  return args;
}

/// Points stdout and stderr at the case's DIR/cases/ID/log.txt.
void redirect_output(const fs::path& log) {
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return;
  dup2(fd, STDOUT_FILENO);
  dup2(fd, STDERR_FILENO);
  close(fd);
}

/// A case's BLAS uses the case's threads, not a pool per core on top of the other workers (the
/// user's own setting wins). In a forked worker the libraries are loaded already, so
/// run_analysis sets the threads itself (solver::set_blas_threads); an exec'd case reads these.
void case_thread_environment(const RunnerOptions& o) {
  const std::string threads = std::to_string(o.threads);
  setenv("OPENBLAS_NUM_THREADS", threads.c_str(), 0);
  setenv("OMP_NUM_THREADS", threads.c_str(), 0);
}

/// Runs case c in this process (a worker), its output into its log; returns its exit code.
int run_case_here(const Manifest& m, const Case& c, const RunnerOptions& o) {
  case_thread_environment(o);
  redirect_output(case_dir(o.dir, c.id) / "log.txt");
  int rc = kAnalysisFailed;
  try {
    rc = run_analysis(case_run_options(m, c, o));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inpact: internal error: %s\n", e.what());
  }
  std::fflush(nullptr);
  return rc;
}

/// `--inpact EXE`: each case an exec of EXE in a child process of its own. Same interface as
/// WorkerPool, so that one loop runs the cases either way.
class ExecLauncher {
 public:
  ExecLauncher(const Manifest& m, const RunnerOptions& o) : m_(m), o_(o) {}
  ~ExecLauncher() {
    for (const auto& [pid, r] : running_) {
      int status = 0;
      waitpid(pid, &status, 0);
    }
  }
  bool has_idle() const { return static_cast<int>(running_.size()) < o_.jobs; }
  std::size_t running() const { return running_.size(); }
  void start(std::size_t k) {
    const Case& c = m_.cases[k];
    const std::vector<std::string> args =
        case_command(case_run_options(m_, c, o_), o_.executable, o_.ranks_per_case);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::fflush(nullptr);  // the child must not print this process's buffered lines again
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
      case_thread_environment(o_);
      redirect_output(case_dir(o_.dir, c.id) / "log.txt");
      execvp(argv[0], argv.data());  // mpirun from PATH
      std::fprintf(stderr, "inpact study: cannot run %s: %s\n", argv[0], std::strerror(errno));
      _exit(127);
    }
    running_[pid] = {k, Clock::now()};
  }
  WorkerPool::Ended wait() {
    for (;;) {
      int status = 0;
      const pid_t pid = waitpid(-1, &status, 0);
      if (pid < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
      }
      auto it = running_.find(pid);
      if (it == running_.end()) continue;
      const auto [k, started] = it->second;
      running_.erase(it);
      return {k, status, std::chrono::duration<double>(Clock::now() - started).count(), started};
    }
  }

 private:
  const Manifest& m_;
  const RunnerOptions& o_;
  std::map<pid_t, std::pair<std::size_t, Clock::time_point>> running_;
};

/// What every forked case would set up for itself, done once here: the HDF5 library, and the
/// time zone the .sta and .dat headers read (localtime loads /etc/localtime on first use).
void prepare_for_cases() {
  io::start_results_library();
  tzset();
}

/// The line of a case's log that says why it stopped: the first "error:" line (a deck error
/// cites file:line there), else the last non-empty line.
std::string failure_line(const fs::path& log) {
  std::string text;
  try {
    text = read_text(log);
  } catch (const std::exception&) {
    return "";
  }
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find("error:") != std::string::npos) return line;
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

/// Completes an outcome from the process's wait status and its results file, and writes it.
CaseOutcome finish_case(const Manifest& m, const Case& c, const RunnerOptions& o, int wait_status, double wall,
                        double started = -1.0) {
  CaseOutcome out;
  out.id = c.id;
  out.wall_time = wall;
  out.started = started;
  const fs::path log = case_dir(o.dir, c.id) / "log.txt";
  if (WIFEXITED(wait_status)) {
    out.exit_code = WEXITSTATUS(wait_status);
  } else if (WIFSIGNALED(wait_status)) {
    out.exit_code = 128 + WTERMSIG(wait_status);
    out.message = fmt::format("killed by signal {} ({})", WTERMSIG(wait_status), strsignal(WTERMSIG(wait_status)));
  }
  const fs::path h5 = o.dir / Manifest::results_path(c.id);
  bool completed = false;
  if (out.exit_code == 0) {
    // A forked case wrote its values once its results were COMPLETED: a few lines to read.
    // Otherwise one read of the results file: it refuses a file that is not COMPLETED; only
    // then is the status looked up on its own, to tell a failed case from a failed collection.
    try {
      out.values = parse_values(read_text(values_path(o.dir, c.id)));
      completed = true;
    } catch (const std::exception&) {
      try {
        out.values = collect_values(h5, m.collect);
        completed = true;
      } catch (const std::exception& e) {
        completed = io::results_status(h5) == "COMPLETED";
        if (completed) out.message = std::string("collect: ") + e.what();
      }
    }
  }
  if (completed) {
    out.status = "completed";
  } else {
    out.status = "failed";
    if (out.exit_code == 0) out.message = "exit 0 but no COMPLETED results file";
    if (out.message.empty()) out.message = failure_line(log);
  }
  write_atomically(outcome_path(o.dir, c.id), format_outcome(out));
  return out;
}

/// A case already done: its outcome file says completed and its results are COMPLETED; or its
/// results are COMPLETED but the outcome was lost (the study was killed): collect it again.
bool already_completed(const Manifest& m, const Case& c, const RunnerOptions& o) {
  const fs::path h5 = o.dir / Manifest::results_path(c.id);
  if (io::results_status(h5) != "COMPLETED") return false;
  std::error_code ec;
  if (fs::exists(outcome_path(o.dir, c.id), ec)) {
    try {
      if (parse_outcome(read_text(outcome_path(o.dir, c.id))).status == "completed") return true;
    } catch (const std::exception&) {
    }
  }
  finish_case(m, c, o, 0, -1.0);
  return true;
}

const std::vector<std::string> kBuiltinColumns = {"increments", "iterations", "cutbacks"};

}  // namespace

std::string format_outcome(const CaseOutcome& o) {
  auto one_line = [](std::string s) {
    for (char& c : s)
      if (c == '\n' || c == '\r') c = ' ';
    return s;
  };
  std::string s = fmt::format("id={}\nstatus={}\nexit_code={}\nwall_time={}\nstarted={}\nmessage={}\n", o.id, o.status,
                              o.exit_code, o.wall_time < 0 ? "" : fmt::format("{:.4f}", o.wall_time),
                              o.started < 0 ? "" : fmt::format("{:.4f}", o.started), one_line(o.message));
  for (const auto& [k, v] : o.values) s += "value." + k + "=" + one_line(v) + "\n";
  return s;
}

CaseOutcome parse_outcome(const std::string& text) {
  CaseOutcome o;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string k = line.substr(0, eq), v = line.substr(eq + 1);
    if (k == "id") o.id = v;
    else if (k == "status") o.status = v;
    else if (k == "exit_code") o.exit_code = std::stoi(v);
    else if (k == "wall_time") o.wall_time = v.empty() ? -1.0 : std::stod(v);
    else if (k == "started") o.started = v.empty() ? -1.0 : std::stod(v);
    else if (k == "message") o.message = v;
    else if (k.rfind("value.", 0) == 0) o.values[k.substr(6)] = v;
  }
  return o;
}

std::string format_table(const Manifest& m, const std::vector<CaseOutcome>& outcomes) {
  std::string s = "id";
  for (const auto& n : m.parameter_names) s += "," + csv_field(n);
  s += ",status,exit_code,wall_time_s";
  for (const auto& c : kBuiltinColumns) s += "," + c;
  for (const auto& c : m.collect) s += "," + csv_field(c);
  s += ",message\n";
  for (std::size_t i = 0; i < m.cases.size(); ++i) {
    const Case& c = m.cases[i];
    const CaseOutcome& o = outcomes[i];
    s += c.id;
    for (const auto& [name, value] : c.parameters) s += "," + csv_field(value);
    s += "," + o.status + "," + (o.exit_code >= 0 ? std::to_string(o.exit_code) : "") + "," +
         (o.wall_time >= 0 ? fmt::format("{:.3f}", o.wall_time) : "");
    auto value = [&](const std::string& k) {
      auto it = o.values.find(k);
      return it == o.values.end() ? std::string() : it->second;
    };
    for (const auto& col : kBuiltinColumns) s += "," + value(col);
    for (const auto& col : m.collect) s += "," + csv_field(value(col));
    s += "," + csv_field(o.message) + "\n";
  }
  return s;
}

std::vector<CaseOutcome> write_table(const Manifest& m, const fs::path& dir) {
  std::vector<CaseOutcome> outcomes;
  for (const Case& c : m.cases) {
    CaseOutcome o;
    o.id = c.id;
    std::error_code ec;
    if (fs::exists(outcome_path(dir, c.id), ec)) {
      try {
        o = parse_outcome(read_text(outcome_path(dir, c.id)));
      } catch (const std::exception&) {
        o.status = "pending";
      }
    }
    outcomes.push_back(std::move(o));
  }
  write_atomically(dir / "results.csv", format_table(m, outcomes));
  return outcomes;
}

namespace {

/// Runs the cases k of `pending` on the launcher's workers; returns how many failed.
template <class Launcher>
std::size_t run_on(Launcher& launcher, const Manifest& m, const RunnerOptions& o, std::deque<std::size_t> pending,
                   bool progress) {
  std::size_t n_done = 0, n_failed = 0;
  const std::size_t n_to_run = pending.size();
  const Clock::time_point began = Clock::now();
  // Fills the free worker slots; called before a finished case is collected, so the workers
  // never wait for the collection.
  auto fill = [&] {
    while (!pending.empty() && launcher.has_idle()) {
      const std::size_t k = pending.front();
      pending.pop_front();
      std::error_code ec;
      fs::remove(values_path(o.dir, m.cases[k].id), ec);  // an earlier run's values are not this run's
      launcher.start(k);
    }
  };
  while (!pending.empty() || launcher.running() > 0) {
    fill();
    const WorkerPool::Ended e = launcher.wait();
    fill();
    const Case& c = m.cases[e.k];
    const CaseOutcome out =
        finish_case(m, c, o, e.wait_status, e.wall, std::chrono::duration<double>(e.started - began).count());
    ++n_done;
    if (out.status != "completed") ++n_failed;
    if (progress) {
      std::printf("[%zu/%zu] %s %s (exit %d) %.2f s  running %zu, failed %zu%s%s\n", n_done, n_to_run, c.id.c_str(),
                  out.status.c_str(), out.exit_code, e.wall, launcher.running(), n_failed,
                  out.message.empty() ? "" : ": ", out.message.c_str());
      std::fflush(stdout);
    }
  }
  return n_failed;
}

/// The cases k of `pending` on o.jobs workers: forked workers, or exec'd cases with --inpact.
std::size_t run_pending(const Manifest& m, const RunnerOptions& o, std::deque<std::size_t> pending, bool progress) {
  prepare_for_cases();
  if (!o.executable.empty() || o.ranks_per_case > 1) {
    RunnerOptions exec = o;
    if (exec.executable.empty()) exec.executable = fs::read_symlink("/proc/self/exe").string();
    ExecLauncher launcher(m, exec);
    return run_on(launcher, m, exec, std::move(pending), progress);
  }
  WorkerPool pool(o.jobs, [&](std::size_t k) { return run_case_here(m, m.cases[k], o); });
  return run_on(pool, m, o, std::move(pending), progress);
}

}  // namespace

int run_one_case(const Manifest& m, const Case& c, const RunnerOptions& o) {
  fs::create_directories(case_dir(o.dir, c.id));
  if (already_completed(m, c, o)) return 0;
  RunnerOptions one = o;
  one.jobs = 1;
  run_pending(m, one, {static_cast<std::size_t>(&c - m.cases.data())}, false);
  return parse_outcome(read_text(outcome_path(o.dir, c.id))).exit_code;
}

int run_cases(const Manifest& m, const RunnerOptions& o) {
  std::deque<std::size_t> pending;
  std::size_t n_skipped = 0, n_shard = 0;
  for (std::size_t k = 0; k < m.cases.size(); ++k) {
    if (!o.shard.contains(k)) continue;
    ++n_shard;
    const Case& c = m.cases[k];
    fs::create_directories(case_dir(o.dir, c.id));
    if (already_completed(m, c, o)) ++n_skipped;
    else pending.push_back(k);
  }
  if (!o.quiet)
    std::printf("study: %zu case(s)%s, %zu already completed, %zu to run on %d worker(s)%s\n", n_shard,
                o.shard.count > 1 ? fmt::format(" in shard {}/{}", o.shard.index, o.shard.count).c_str() : "", n_skipped,
                pending.size(), o.jobs,
                o.ranks_per_case > 1 ? fmt::format(" of {} MPI ranks each", o.ranks_per_case).c_str() : "");
  std::fflush(stdout);
  const std::size_t n_failed = run_pending(m, o, std::move(pending), !o.quiet);
  write_table(m, o.dir);
  return static_cast<int>(n_failed);
}

}  // namespace inpact::app::study
