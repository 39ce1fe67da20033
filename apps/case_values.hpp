#pragma once
/// The values a study collects from a case (`--collect OP:VAR[@NSET]`, plus increments,
/// iterations and cutbacks), from either source:
///   - while the case runs, in memory: the case keeps a copy of the wanted fields of each
///     frame (the last one wins) and counts the attempts, and writes the values beside its
///     results (cases/ID/values.txt), so the study reads a few lines instead of the HDF5 file;
///   - afterwards, from its COMPLETED results file (a case run by `--inpact EXE`, or one whose
///     values were lost).
/// Both evaluate the same way: on the last frame of the last step that has frames.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "study_cases.hpp"

namespace inpact::solver {
struct Frame;
struct StatusRow;
}  // namespace inpact::solver

namespace inpact::app::study {

/// One field of the last frame, as far as the collection needs it.
struct KeptField {
  std::string key;
  std::vector<std::string> components;
  std::vector<double> values;            ///< locations × components, row-major
  std::vector<std::int64_t> node_rows;   ///< NODAL: the node row of each location; else empty
};

struct AttemptTotals {
  long increments = 0, iterations = 0, cutbacks = 0;
};

/// The rows of a node set by its upper-case name; nullopt when there is no such set.
using NodeSetRows = std::function<std::optional<std::set<std::int64_t>>(const std::string&)>;

/// spec text → value ("" when the field, the component or the set is missing, or every value
/// is NaN), and "increments", "iterations", "cutbacks".
std::map<std::string, std::string> evaluate_values(const std::vector<KeptField>& fields, const AttemptTotals& totals,
                                                   const std::vector<std::string>& specs, const NodeSetRows& nsets);

/// Gathers the collected fields while a case runs.
class CaseValueRecorder {
 public:
  explicit CaseValueRecorder(std::vector<std::string> specs);
  bool active() const { return !specs_.empty(); }
  /// Keeps this frame's wanted fields in place of the previous frame's.
  void frame(const solver::Frame& frame);
  void attempt(const solver::StatusRow& row);
  std::map<std::string, std::string> values(const NodeSetRows& nsets) const;

 private:
  std::vector<std::string> specs_;
  std::set<std::string> vars_;  ///< what the specs name: field keys or component labels
  std::vector<KeptField> fields_;
  AttemptTotals totals_;
};

/// key=value lines, one per value (values.txt), and back.
std::string format_values(const std::map<std::string, std::string>& values);
std::map<std::string, std::string> parse_values(const std::string& text);

/// The collected values of a finished case's results file. Throws IoError when the file is
/// missing, unreadable or not COMPLETED.
std::map<std::string, std::string> collect_values(const std::filesystem::path& h5, const std::vector<std::string>& specs);

}  // namespace inpact::app::study
