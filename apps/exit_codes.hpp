#pragma once
/// The exit codes of the command line contract (shared/DESIGN.md).
namespace inpact::app {

enum ExitCode : int {
  kOk = 0,
  kDifferences = 1,  ///< compare: the results differ
  kUsage = 2,
  kDeckError = 3,
  kAnalysisFailed = 4,  ///< did not converge, or aborted
  kIoError = 5,
};

}  // namespace inpact::app
