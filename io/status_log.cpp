#include "status_log.hpp"

#include <ctime>

#include <fmt/format.h>

#include "io_error.hpp"

namespace inpact::io {

namespace {

// Abaqus's own header (Abaqus/Standard .sta), column for column, with inpact's
// augmentation count after INC OF TIME where Abaqus puts DOF MONITOR.
constexpr const char* kHeader =
    " SUMMARY OF JOB INFORMATION:\n"
    " STEP  INC ATT SEVERE EQUIL TOTAL  TOTAL      STEP       INC OF   AUGMEN-\n"
    "               DISCON ITERS ITERS  TIME/    TIME/LPF    TIME/LPF  TATIONS\n"
    "               ITERS               FREQ\n";

// Times as Abaqus prints them: 3 significant digits, trailing zeros kept (0.500, 1.00, 0.0250);
// the increment with 4 (0.5000).
std::string sig(double v, int digits) { return fmt::format("{:#.{}g}", v, digits); }

}  // namespace

std::string format_status_row(const StatusRow& r) {
  return fmt::format("{:4d}{:6d}{:4d}{}{:5d}{:6d}{:6d}  {:<11}{:<11}{:<11}{:6d}", r.step, r.increment, r.attempt,
                     r.cut_back ? 'U' : ' ', r.severe_discon_iters, r.equil_iters, r.total_iters,
                     sig(r.total_time, 3), sig(r.step_time, 3), sig(r.inc_of_time, 4), r.augmentations);
}

StatusLog::StatusLog(std::filesystem::path path, const std::string& solver_version) : path_(std::move(path)) {
  out_.open(path_, std::ios::out | std::ios::trunc);
  if (!out_) throw IoError(path_, "cannot create the status file");
  const std::time_t now = std::time(nullptr);
  char date[64] = "";
  std::strftime(date, sizeof date, "DATE %d-%b-%Y TIME %H:%M:%S", std::localtime(&now));
  put(fmt::format("{:<42}{}\n{}", "inpact " + solver_version, date, kHeader));
}

void StatusLog::write(const StatusRow& row) { put(format_status_row(row) + "\n"); }

void StatusLog::note(const std::string& line) { put(line + "\n"); }

void StatusLog::finish(bool completed) {
  put(completed ? "\n\n THE ANALYSIS HAS COMPLETED SUCCESSFULLY\n" : "\n\n THE ANALYSIS HAS NOT BEEN COMPLETED\n");
}

void StatusLog::put(const std::string& text) {
  out_ << text;
  out_.flush();
  if (!out_) throw IoError(path_, "cannot write the status file");
}

}  // namespace inpact::io
