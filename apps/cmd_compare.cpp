/// `inpact compare A.h5 B.h5`: structure, then values field by field (io/compare.hpp);
/// exit 0 same, 1 different, 2 usage (a bad tolerance file), 5 I/O.
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/compare.hpp"
#include "io/io_error.hpp"
#include "io/results_reader.hpp"

namespace inpact::app {

int run_compare(const CompareOptions& options) {
  io::Tolerances tolerances;
  try {
    tolerances = options.tolerances.empty() ? io::default_tolerances() : io::read_tolerances(options.tolerances);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "inpact compare: %s\n", e.what());
    return kUsage;
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "inpact compare: I/O error: %s\n", e.what());
    return kIoError;
  }
  try {
    io::ReadResultsOptions read;
    read.allow_incomplete = options.allow_incomplete;
    const io::ResultsFile a = io::read_results(options.a, read);
    const io::ResultsFile b = io::read_results(options.b, read);
    const io::CompareResult result = io::compare_results(a, b, tolerances);
    if (!options.quiet) std::fputs(io::format_summary(result).c_str(), stdout);
    if (!options.report.empty()) {
      const std::filesystem::path tmp = options.report + ".tmp";
      {
        std::ofstream out(tmp, std::ios::binary);
        out << io::format_json(result, tolerances);
        if (!out) throw io::IoError(tmp, "cannot write the report");
      }
      std::filesystem::rename(tmp, options.report);
    }
    return result.same() ? kOk : kDifferences;
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "inpact compare: I/O error: %s\n", e.what());
    return kIoError;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "inpact compare: I/O error: %s\n", e.what());
    return kIoError;
  }
}

}  // namespace inpact::app
