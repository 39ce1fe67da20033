/// The `inpact` executable: options in, exit code out. The only place where exceptions
/// become exit codes; everything else lives in the libraries.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "abaqus_args.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "process_setup.hpp"
#include "solver/blas_info.hpp"
#include "solver/linear/petsc_module.hpp"
#include "solver/linear_solver_choice.hpp"

using namespace inpact::app;

namespace {

/// `-P name=value` pairs into a map; throws CLI::ValidationError on a malformed pair.
std::map<std::string, std::string> parameter_overrides(const std::vector<std::string>& pairs) {
  std::map<std::string, std::string> out;
  for (const auto& p : pairs) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0) throw CLI::ValidationError("-P", "expected name=value, got '" + p + "'");
    out[p.substr(0, eq)] = p.substr(eq + 1);
  }
  return out;
}

std::string version_text() {
  return fmt::format("inpact {}\nBLAS: {}\n{}", INPACT_VERSION, inpact::solver::blas_description(),
                     inpact::solver::petsc_availability());
}

}  // namespace

int main(int argc, char** argv) {
  set_up_process();
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (auto translated = translate_abaqus_args(args)) args = *translated;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "inpact: %s\n", e.what());
    return kUsage;
  }

  // The name is given, not taken from argv[0]: parse() gets the arguments without it, and the
  // usage lines ("Usage: inpact run [OPTIONS] deck") need it.
  CLI::App app{"inpact: an Abaqus-style input deck solver for contact problems", "inpact"};
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);

  RunOptions run;
  std::vector<std::string> run_params;
  CLI::App* run_cmd = app.add_subcommand("run", "Analyse a deck and write JOB.h5, JOB.sta, JOB.dat");
  run_cmd->add_option("deck", run.deck, "Input deck (.inp)")->required()->check(CLI::ExistingFile);
  run_cmd->add_option("-j,--job", run.job, "Job name (default: the deck's name)");
  run_cmd->add_option("-o,--output-dir", run.output_dir, "Folder for the results (default: .)");
  run_cmd->add_option("--threads", run.threads, "Threads for assembly, factorisation and surface-to-surface contact")->check(CLI::PositiveNumber);
  run_cmd->add_option("-P", run_params, "Override a *PARAMETER: -P name=value");
  run_cmd->add_flag("-q,--quiet", run.quiet, "Print nothing but errors");
  run_cmd->add_flag("-v,--verbose", run.verbose, "Print every Newton iteration");
  run_cmd->add_option("--solver", run.solver,
                      "Linear solver: direct (CHOLMOD/UMFPACK), petsc (CG/GMRES + GAMG, MUMPS), auto (by size and dimension)")
      ->check(CLI::IsMember({"direct", "petsc", "auto"}));
  run_cmd->add_option("--timings", run.timings,
                      "Write the wall time of each phase (read, create, solve, output, finish) and of the Newton "
                      "iterations' parts (contact update, element assembly, factorisation) to this file");

  CheckOptions check;
  std::vector<std::string> check_params;
  CLI::App* check_cmd = app.add_subcommand("check", "Read and validate a deck, print the model summary; no analysis");
  check_cmd->add_option("deck", check.deck, "Input deck (.inp)")->required()->check(CLI::ExistingFile);
  check_cmd->add_option("-P", check_params, "Override a *PARAMETER: -P name=value");
  check_cmd->add_option("--solver", check.solver, "The linear solver `run --solver` would use: direct, petsc, auto")
      ->check(CLI::IsMember({"direct", "petsc", "auto"}));

  CompareOptions compare;
  CLI::App* compare_cmd = app.add_subcommand("compare", "Compare two results files: exit 0 same, 1 different, 5 I/O");
  compare_cmd->add_option("a", compare.a, "Results file A (JOB.h5)")->required();
  compare_cmd->add_option("b", compare.b, "Results file B (JOB.h5)")->required();
  compare_cmd->add_option("--tolerances", compare.tolerances, "Per-field tolerances (.toml or .yaml)");
  compare_cmd->add_option("--report", compare.report, "Write a JSON report here");
  compare_cmd->add_flag("--allow-incomplete", compare.allow_incomplete, "Accept files whose status is RUNNING or ABORTED");
  compare_cmd->add_flag("-q,--quiet", compare.quiet, "Print nothing but errors (the exit code tells)");

  StudyOptions study;
  CLI::App* study_cmd = app.add_subcommand("study", "Run a deck over a grid or samples of *PARAMETER values");
  study_cmd->add_option("deck", study.deck, "Input deck (.inp) with *PARAMETER definitions")->check(CLI::ExistingFile);
  study_cmd->add_option("--grid", study.grids, "name=v1,v2,... (repeat: the cases are the product)");
  study_cmd->add_option("--samples", study.samples, "CSV file: header of parameter names, one case per row")
      ->check(CLI::ExistingFile);
  study_cmd->add_option("--collect", study.collect,
                        "OP:VAR[@NSET] per case, OP max|min|maxabs|sum (max:CPRESS, max:-COPEN, sum:RF2@TOP)");
  study_cmd->add_option("-j,--jobs", study.jobs, "Worker processes")->check(CLI::PositiveNumber);
  study_cmd->add_option("--threads", study.threads, "Threads of each case")->check(CLI::PositiveNumber);
  study_cmd->add_option("--ranks-per-case", study.ranks_per_case,
                        "MPI ranks of each case: a distributed run, mpirun -np N inpact run ... (needs PETSc)")
      ->check(CLI::PositiveNumber);
  study_cmd->add_option("--shard", study.shard, "Run shard i of n: cases k with k mod n = i-1");
  study_cmd->add_option("-o,--output-dir", study.dir, "Study folder (default: DECK-stem.study)");
  study_cmd->add_option("--inpact", study.executable,
                        "Run each case as an exec of this inpact executable (default: forked workers)");
  study_cmd->add_flag("--manifest-only", study.manifest_only, "Write DIR/manifest.csv and run nothing (Slurm arrays)");
  study_cmd->add_flag("-q,--quiet", study.quiet, "No progress lines");
  CLI::App* run_case_cmd = study_cmd->add_subcommand("run-case", "Run one case of the manifest in -o DIR (default .)");
  run_case_cmd->add_option("id", study.run_case, "Case id (c0001, ...)")->required();
  run_case_cmd->add_option("-o,--output-dir", study.dir, "Study folder");
  run_case_cmd->add_option("--threads", study.threads, "Threads of the case")->check(CLI::PositiveNumber);
  run_case_cmd->add_option("--ranks-per-case", study.ranks_per_case, "MPI ranks of the case (mpirun -np N)")
      ->check(CLI::PositiveNumber);
  CLI::App* collect_cmd = study_cmd->add_subcommand("collect", "Write results.csv of the study in -o DIR (default .)");
  collect_cmd->add_option("-o,--output-dir", study.dir, "Study folder");

  try {
    std::reverse(args.begin(), args.end());  // CLI11 takes a vector of arguments last-first
    app.parse(args);
    run.parameters = parameter_overrides(run_params);
    check.parameters = parameter_overrides(check_params);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints help/version (rc 0) or the usage error
    return rc == 0 ? kOk : kUsage;
  }

  try {
    if (*check_cmd) return run_check(check);
    if (*run_cmd) return run_analysis(run);
    if (*compare_cmd) return run_compare(compare);
    if (*study_cmd) {
      study.collect_only = static_cast<bool>(*collect_cmd);
      return run_study(study);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inpact: internal error: %s\n", e.what());
    // The other ranks of a distributed run would wait for this one in their next collective.
    inpact::solver::rank_world().abort(kAnalysisFailed);
    return kAnalysisFailed;
  }
  return kUsage;
}
