#pragma once
/// The subcommands of `inpact`, each returning its exit code.
#include <map>
#include <string>

namespace inpact::app {

struct CheckOptions {
  std::string deck;
  std::map<std::string, std::string> parameters;
};

struct RunOptions {
  std::string deck;
  std::string job;
  std::string output_dir = ".";
  int threads = 1;
  std::map<std::string, std::string> parameters;
  bool quiet = false;
  bool verbose = false;
};

/// `inpact check`: parse and validate; print diagnostics and, when valid, the model summary.
int run_check(const CheckOptions& options);
/// `inpact run`: parse, validate, analyse, write results.
int run_analysis(const RunOptions& options);

}  // namespace inpact::app
