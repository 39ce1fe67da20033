#pragma once
/// The `.sta` status file: one row per increment attempt, Abaqus's columns and layout
/// (STEP INC ATT SEVERE-DISCON-ITERS EQUIL-ITERS TOTAL-ITERS TOTAL-TIME STEP-TIME INC-OF-TIME),
/// plus inpact's AUGMENTATIONS column; a `U` after ATT marks an attempt that was cut back.
/// Note lines go between the rows: "STEP n BEGINS", and in a *STATIC, STABILIZE step one
/// "     STABILIZATION ALLSE=… ALLSD=… ALLSD/ALLSE=… FACTOR=…" line below each converged row
/// (the columns stay Abaqus's).
/// Each row is flushed as it is written, so `tail -f JOB.sta` follows a run. The same rows go
/// to the results file's /status table (ResultsWriter::append_status).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "solver/results_frame.hpp"

#include "io_error.hpp"

namespace inpact::io {

/// One increment attempt, as the .sta table shows it.
/// The status table's row type is the solver's (solver/results_frame.hpp).
using solver::StatusRow;

/// Formats one data row exactly as it appears in the .sta file (no newline).
std::string format_status_row(const StatusRow& row);

class StatusLog {
 public:
  /// Creates (truncates) `path` and writes the header. Throws IoError when it cannot.
  StatusLog(std::filesystem::path path, const std::string& solver_version);
  /// Appends one row and flushes it.
  void write(const StatusRow& row);
  /// A free-text line (notes such as "STEP 2 BEGINS"), flushed.
  void note(const std::string& line);
  /// The closing line: Abaqus's "THE ANALYSIS HAS COMPLETED SUCCESSFULLY" or
  /// "THE ANALYSIS HAS NOT BEEN COMPLETED".
  void finish(bool completed);
  const std::filesystem::path& path() const { return path_; }

 private:
  void put(const std::string& text);
  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace inpact::io
