/// `inpact run`: read the deck, run the analysis, and write JOB.h5 (+ .xdmf), JOB.sta and JOB.dat.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "case_values.hpp"
#include "commands.hpp"
#include "deck_loading.hpp"
#include "exit_codes.hpp"
#include "io/dat_report.hpp"
#include "io/io_error.hpp"
#include "io/results_writer.hpp"
#include "io/sha256.hpp"
#include "io/status_log.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_error.hpp"
#include "solver/linear/mpi_launch.hpp"
#include "solver/linear_solver_choice.hpp"

namespace inpact::app {

namespace {

/// Connects the analysis to the results file, the status log, the print file and the terminal.
class RunObserver final : public solver::AnalysisObserver {
 public:
  RunObserver(io::ResultsWriter& results, io::StatusLog& status, io::DatReport& dat, const RunOptions& options)
      : results_(results),
        status_(status),
        dat_(dat),
        options_(options),
        tty_(isatty(fileno(stdout)) != 0),
        values_(options.collect) {}

  void step_started(const model::Step& step, int number) override {
    results_.begin_step(step);
    dat_.begin_step(step, number);
    status_.note(fmt::format("STEP {} BEGINS ({})", number, step.name));
    if (step.nlgeom_switched_on) status_.note(model::nlgeom_switched_on_note());
    if (!options_.quiet) std::printf("step %d (%s)\n", number, step.name.c_str());
    if (!options_.quiet && step.nlgeom_switched_on) std::printf("  %s\n", model::nlgeom_switched_on_note());
  }
  void contact_interactions(int, const std::vector<std::string>& lines) override {
    results_.write_contact_interactions(lines);
    dat_.contact_interactions(lines);
  }
  void iteration(const solver::IterationRecord& r) override {
    if (options_.verbose)
      std::printf("  inc %d att %d iter %d  max residual %.3e (%.2e of the average force)  max correction %.3e\n",
                  r.increment, r.attempt, r.iteration, r.max_residual, r.residual_ratio, r.max_correction);
  }
  void attempt_finished(const solver::StatusRow& row) override {
    status_.write(row);
    results_.append_status(row);
    if (values_.active()) values_.attempt(row);
    if (options_.quiet) return;
    const std::string line = fmt::format("  step {} inc {} att {}{}  iterations {}  step time {:.4g}  dt {:.3g}",
                                         row.step, row.increment, row.attempt, row.cut_back ? "U" : "",
                                         row.total_iters, row.step_time, row.inc_of_time);
    // On a terminal the progress line is rewritten in place; in a log, one line each.
    if (tty_) std::printf("\r%-78s", line.c_str());
    else std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
  void frame(const solver::Frame& frame) override {
    results_.write_frame(frame);
    if (values_.active()) values_.frame(frame);
  }
  void print_frame(const solver::PrintFrame& frame) override { dat_.write(frame); }
  /// Notes and warnings of the analysis (contact set-up, cutbacks): on stderr unless quiet. A
  /// failure is not a message: run_analysis returns it and it is printed whatever the options.
  void message(std::string_view text) override {
    if (options_.quiet) return;
    if (tty_) std::printf("\n");
    std::fprintf(stderr, "%.*s\n", static_cast<int>(text.size()), text.data());
  }
  void status_note(std::string_view text) override { status_.note(std::string(text)); }
  void end_line() {
    if (tty_ && !options_.quiet) std::printf("\n");
  }
  /// A study's collected values (once the results file is COMPLETED).
  void write_values(const model::Model& model) const {
    if (options_.values.empty()) return;
    const auto nset_rows = [&](const std::string& name) -> std::optional<std::set<std::int64_t>> {
      auto it = model.mesh.nsets.find(name);
      if (it == model.mesh.nsets.end()) return std::nullopt;
      return std::set<std::int64_t>(it->second.rows.begin(), it->second.rows.end());
    };
    study::write_atomically(options_.values, study::format_values(values_.values(nset_rows)));
  }

 private:
  io::ResultsWriter& results_;
  io::StatusLog& status_;
  io::DatReport& dat_;
  const RunOptions& options_;
  bool tty_;
  study::CaseValueRecorder values_;
};

/// Wall time of a run's phases, for `--timings FILE` (the study's cases write one each, and
/// bench/study_overhead.py reads them: what a case spends beside its solve).
class PhaseClock {
 public:
  using Clock = std::chrono::steady_clock;
  /// Seconds since the last mark, added to `phase`.
  void mark(const char* phase) {
    const auto now = Clock::now();
    seconds_.emplace_back(phase, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }
  void add(const char* phase, double s) { seconds_.emplace_back(phase, s); }
  /// The Newton iterations' parts (inside "analysis"), and how often each ran.
  void add_iterations(const solver::IterationSeconds& it) {
    add("contact_update", it.contact_update);
    add("contact_begin", it.contact_begin);
    add("contact_geometry", it.contact_geometry);
    add("contact_assembly", it.contact_assembly);
    add("element_assembly", it.element_assembly);
    add("factorization", it.factorization);
    add("back_solve", it.back_solve);
    counts_ = {{"contact_updates", it.contact_updates},
               {"element_assemblies", it.element_assemblies},
               {"factorizations", it.factorizations},
               {"krylov_iterations", it.krylov_iterations}};
  }
  /// key=value lines: one per phase and total_s (first mark's start to the last mark).
  void write(const std::string& path) const {
    if (path.empty()) return;
    std::ofstream out(path);
    for (const auto& [phase, s] : seconds_) out << phase << "_s=" << fmt::format("{:.6f}", s) << "\n";
    for (const auto& [name, n] : counts_) out << name << "=" << n << "\n";
    out << "total_s=" << fmt::format("{:.6f}", std::chrono::duration<double>(last_ - start_).count()) << "\n";
    out.flush();
    if (!out) std::fprintf(stderr, "inpact: warning: cannot write the timings to %s\n", path.c_str());
  }

 private:
  Clock::time_point start_ = Clock::now(), last_ = start_;
  std::vector<std::pair<const char*, double>> seconds_;
  std::vector<std::pair<const char*, long>> counts_;
};

/// SHA-256 over the deck and every file it included, in reading order.
std::string deck_digest(const model::Model& m) {
  io::Sha256 hash;
  for (const auto& f : m.sources.files) hash.update_file(f.path);
  return hash.hex();
}

/// The linear solver of `--solver`, started (PetscInitialize once per process, before any
/// output is created); nullopt, with the reason printed, when it cannot be had.
std::optional<solver::SolverChoice> start_linear_solver(const RunOptions& options, const model::Model& model) {
  try {
    const solver::SolverChoice choice =
        solver::resolve_linear_solver(options.solver, model);
    solver::start_linear_solver(choice);
    return choice;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inpact: error: %s\n", e.what());
    return std::nullopt;
  }
}

/// The folder a rank writes its results to. Rank 0 of an MPI run (and a run without one) writes
/// to --output-dir. The other ranks hold the same state (every rank follows the same increments,
/// solver/assembler.hpp) and write the same results to a scratch folder that they remove at the
/// end, so that the user gets one set of files and no two processes write the same one.
class RankOutput {
 public:
  RankOutput(const RunOptions& options, solver::LaunchRanks ranks) : writer_(ranks.rank == 0) {
    if (writer_) {
      dir_ = options.output_dir;
      return;
    }
    dir_ = std::filesystem::temp_directory_path() / fmt::format("inpact-rank{}-{}", ranks.rank, ::getpid());
  }
  ~RankOutput() {
    std::error_code ignored;
    if (!writer_) std::filesystem::remove_all(dir_, ignored);
  }
  RankOutput(const RankOutput&) = delete;
  RankOutput& operator=(const RankOutput&) = delete;
  const std::filesystem::path& dir() const { return dir_; }
  /// Whether this rank's files and messages are the run's (the others stay quiet).
  bool writer() const { return writer_; }

 private:
  bool writer_;
  std::filesystem::path dir_;
};

}  // namespace

int run_analysis(const RunOptions& rank_options) {
  const RankOutput output(rank_options, solver::launch_ranks());
  RunOptions options = rank_options;
  if (!output.writer()) {
    options.quiet = true;
    options.verbose = false;
    options.timings.clear();
    options.values.clear();
  }
  PhaseClock clock;
  const auto loaded = load_analysable_deck(options.deck, options.parameters);
  if (!loaded) return kDeckError;
  const parser::ReadResult& result = *loaded;
  const std::string job = options.job.empty() ? std::filesystem::path(options.deck).stem().string() : options.job;
  const std::filesystem::path& dir = output.dir();
  const std::optional<solver::SolverChoice> choice = start_linear_solver(options, result.model);
  if (!choice) return kUsage;
  try {
    std::filesystem::create_directories(dir);
    const std::string digest = deck_digest(result.model);
    clock.mark("read");
    io::ResultsOptions results_options;
    results_options.linear_solver = solver::kind_name(choice->kind);
    results_options.linear_solver_choice = solver::describe(*choice);
    io::ResultsWriter results =
        io::ResultsWriter::create(dir / (job + ".h5"), result.model, digest, INPACT_VERSION, results_options);
    io::StatusLog status(dir / (job + ".sta"), INPACT_VERSION);
    io::DatReport dat(dir / (job + ".dat"), INPACT_VERSION, result.model.heading, solver::describe(*choice));
    clock.mark("create");
    RunObserver observer(results, status, dat, options);
    solver::AnalysisOptions analysis_options;
    analysis_options.threads = options.threads;
    analysis_options.linear_solver = choice->kind;
    solver::AnalysisOutcome outcome;
    try {
      outcome = solver::run_analysis(result.model, observer, analysis_options);
    } catch (const solver::AnalysisError& e) {
      observer.end_line();
      results.finish(io::RunStatus::Aborted);
      status.finish(false);
      dat.finish(false);
      std::fprintf(stderr, "%s\n", e.what());
      return kDeckError;
    }
    clock.mark("analysis");
    clock.add("output", outcome.output_seconds);
    clock.add_iterations(outcome.iteration_seconds);
    observer.end_line();
    results.finish(outcome.completed ? io::RunStatus::Completed : io::RunStatus::Aborted);
    status.finish(outcome.completed);
    dat.finish(outcome.completed);
    if (outcome.completed) observer.write_values(result.model);
    clock.mark("finish");
    clock.write(options.timings);
    if (!outcome.completed) {
      if (output.writer())
        std::fprintf(stderr, "%s: the analysis stopped: %s\n", options.deck.c_str(), outcome.message.c_str());
      return kAnalysisFailed;
    }
    if (!options.quiet) std::printf("%s: completed; results in %s\n", job.c_str(), results.h5_path().c_str());
    return kOk;
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "inpact: I/O error: %s\n", e.what());
    return kIoError;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "inpact: I/O error: %s\n", e.what());
    return kIoError;
  }
}

}  // namespace inpact::app
