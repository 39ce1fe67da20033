#pragma once
/// The subcommands of `inpact`, each returning its exit code.
#include <map>
#include <string>
#include <vector>

namespace inpact::app {

struct CheckOptions {
  std::string deck;
  std::map<std::string, std::string> parameters;
  std::string solver{};  ///< --solver direct|petsc|auto, "" when not given (what `run` would use)
};

struct RunOptions {
  std::string deck;
  std::string job;
  std::string output_dir = ".";
  int threads = 1;
  std::map<std::string, std::string> parameters;
  bool quiet = false;
  bool verbose = false;
  std::string timings;  ///< --timings FILE: the wall time of each phase, key=value lines
  std::string solver{};  ///< --solver direct|petsc|auto, "" when not given (solver/linear_solver_choice.hpp)
  /// A study's forked case: the values to collect (OP:VAR[@NSET]) and where to write them.
  std::vector<std::string> collect;
  std::string values;
};

struct CompareOptions {
  std::string a, b;
  std::string tolerances;  ///< TOML or YAML file of per-field tolerances
  std::string report;      ///< JSON report path
  bool allow_incomplete = false;  ///< accept RUNNING / ABORTED files (never .part)
  bool quiet = false;
};

struct StudyOptions {
  std::string deck;
  std::vector<std::string> grids;    ///< name=v1,v2,...
  std::string samples;               ///< CSV of parameter rows
  std::vector<std::string> collect;  ///< OP:VAR[@NSET]
  int jobs = 1;
  int threads = 1;
  int ranks_per_case = 1;  ///< --ranks-per-case N: each case under mpirun -np N
  std::string shard = "1/1";
  std::string dir;  ///< default: DECK-stem.study (run-case, collect: .)
  std::string run_case;       ///< `study run-case ID`
  bool collect_only = false;  ///< `study collect`
  bool manifest_only = false;  ///< --manifest-only: write the manifest, run nothing
  std::string executable;     ///< --inpact EXE: exec EXE per case (default: forked workers run the cases)
  bool quiet = false;
};

/// `inpact check`: parse and validate; print diagnostics and, when valid, the model summary.
int run_check(const CheckOptions& options);
/// `inpact run`: parse, validate, analyse, write results.
int run_analysis(const RunOptions& options);
/// `inpact compare A.h5 B.h5`: 0 same, 1 different, 2 usage, 5 I/O.
int run_compare(const CompareOptions& options);
/// `inpact study`: 0 every case completed, 4 some failed, 2 usage, 5 I/O.
int run_study(const StudyOptions& options);

}  // namespace inpact::app
