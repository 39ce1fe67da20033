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
#include "solver/blas_info.hpp"

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
  return fmt::format("inpact {}\nBLAS: {}", INPACT_VERSION, inpact::solver::blas_description());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (auto translated = translate_abaqus_args(args)) args = *translated;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "inpact: %s\n", e.what());
    return kUsage;
  }

  CLI::App app{"inpact: an Abaqus-style input deck solver for contact problems"};
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);

  RunOptions run;
  std::vector<std::string> run_params;
  CLI::App* run_cmd = app.add_subcommand("run", "Analyse a deck and write JOB.h5, JOB.sta, JOB.dat");
  run_cmd->add_option("deck", run.deck, "Input deck (.inp)")->required()->check(CLI::ExistingFile);
  run_cmd->add_option("-j,--job", run.job, "Job name (default: the deck's name)");
  run_cmd->add_option("-o,--output-dir", run.output_dir, "Folder for the results (default: .)");
  run_cmd->add_option("--threads", run.threads, "Threads for assembly and factorisation")->check(CLI::PositiveNumber);
  run_cmd->add_option("-P", run_params, "Override a *PARAMETER: -P name=value");
  run_cmd->add_flag("-q,--quiet", run.quiet, "Print nothing but errors");
  run_cmd->add_flag("-v,--verbose", run.verbose, "Print every Newton iteration");

  CheckOptions check;
  std::vector<std::string> check_params;
  CLI::App* check_cmd = app.add_subcommand("check", "Read and validate a deck, print the model summary; no analysis");
  check_cmd->add_option("deck", check.deck, "Input deck (.inp)")->required()->check(CLI::ExistingFile);
  check_cmd->add_option("-P", check_params, "Override a *PARAMETER: -P name=value");

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
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inpact: internal error: %s\n", e.what());
    return kAnalysisFailed;
  }
  return kUsage;
}
