#pragma once
/// `inpact study`: running the cases of a manifest on worker processes, and the results table.
///
/// Each case runs as its own process, a fork of the study that runs what
///   inpact run DECK -j ID -o DIR/cases/ID --threads T -q --timings DIR/cases/ID/timings.txt -P name=value ...
/// runs (or that command itself, with --inpact EXE), with its output in DIR/cases/ID/log.txt. When it ends, DIR/cases/ID/case.result (key=value
/// lines: exit code, status, message, wall time and the collected values) is written through a
/// temporary file and a rename, so a killed worker or a killed study loses at most the case
/// that was running. A case whose results file is COMPLETED is not run again (resume); a
/// failed case is run again.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "study_cases.hpp"

namespace inpact::app::study {

struct RunnerOptions {
  std::filesystem::path dir;     ///< the study folder (manifest.csv, cases/, results.csv)
  std::string executable;        ///< --inpact EXE: exec EXE for each case (default: fork and run in-process)
  int jobs = 1;                  ///< worker processes
  int threads = 1;               ///< --threads of each case
  /// --ranks-per-case N: each case a distributed run, `mpirun -np N EXE run ...` (exec'd; EXE
  /// the --inpact executable or this one). 1: a case is one process.
  int ranks_per_case = 1;
  Shard shard;
  bool quiet = false;
};

/// What became of one case (the content of its case.result file).
struct CaseOutcome {
  std::string id;
  std::string status = "pending";  ///< completed | failed | pending
  int exit_code = -1;
  std::string message;
  double wall_time = -1;           ///< seconds, handed to a worker to ended; < 0 unknown
  double started = -1;             ///< seconds from the first case of this run of the study to this one's start
  std::map<std::string, std::string> values;  ///< increments, iterations, cutbacks + collected specs
};

/// Runs the cases of `manifest` in `options.shard` on `options.jobs` workers, skipping those
/// already COMPLETED; writes each case.result and then DIR/results.csv. Returns the number of
/// cases of the shard that failed.
int run_cases(const Manifest& manifest, const RunnerOptions& options);
/// Runs one case (`inpact study run-case ID`); returns its exit code (0 when it was already
/// completed).
int run_one_case(const Manifest& manifest, const Case& c, const RunnerOptions& options);

std::string format_outcome(const CaseOutcome& o);
CaseOutcome parse_outcome(const std::string& text);
/// DIR/results.csv: one row per case of the manifest (pending ones too):
/// id, parameters..., status, exit_code, wall_time_s, increments, iterations, cutbacks,
/// collected values..., message.
std::string format_table(const Manifest& manifest, const std::vector<CaseOutcome>& outcomes);
/// Reads every case.result under `dir` and writes DIR/results.csv; returns the outcomes.
std::vector<CaseOutcome> write_table(const Manifest& manifest, const std::filesystem::path& dir);

}  // namespace inpact::app::study
