#pragma once
/// Reading a results file JOB.h5 back (shared/DESIGN.md, "Results file (contract)"): the root
/// attributes, node labels, node sets, the .sta table and every step's frames and field
/// outputs, with each field location named by label (not by row), so that two files of the
/// same model numbered differently can be matched. HDF5 stays out of this header.
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io_error.hpp"

namespace inpact::io {

/// One field output of one step: data (n_frames × n_loc × n_comp, row-major), NaN in frames
/// without the field, and one location name per row.
struct ResultsField {
  std::string key;       ///< U, S, CPRESS, ...
  std::string position;  ///< NODAL, INTEGRATION_POINT, ELEMENT_NODAL, CENTROID
  std::string region;
  std::vector<std::string> components;  ///< componentLabels
  std::size_t n_frames = 0, n_loc = 0, n_comp = 0;
  std::vector<double> data;
  /// Location names by label, unique within the field: "node 12", "node PART-1.12",
  /// "node 12 (pair SLAVE/MASTER)", "element 7 ip 3", "element 7 node 2", "element 7".
  std::vector<std::string> locations;
  /// NODAL fields: the node row of each location (-1 otherwise), e.g. to select a node set.
  std::vector<std::int64_t> node_rows;

  double value(std::size_t frame, std::size_t loc, std::size_t comp) const {
    return data[(frame * n_loc + loc) * n_comp + comp];
  }
};

struct ResultsStep {
  std::string name;
  std::vector<double> step_time, total_time;
  std::vector<std::int32_t> increment;
  std::vector<ResultsField> fields;  ///< in the file's creation order
  std::size_t n_frames() const { return step_time.size(); }
  const ResultsField* field(const std::string& key) const;
};

/// The parts of the /status table a study collects.
struct ResultsStatusTotals {
  std::int64_t attempts = 0, cut_backs = 0, increments = 0, iterations = 0, augmentations = 0;
};

struct ResultsFile {
  std::filesystem::path path;
  std::string status;  ///< RUNNING | COMPLETED | ABORTED
  std::string solver_version, deck_sha256;
  std::vector<std::string> node_names;  ///< "12" or "PART-1.12" per node row
  std::vector<std::string> element_names;  ///< "TYPE 7" or "TYPE PART-1.7" per element (any order)
  std::map<std::string, std::vector<std::int64_t>> nsets;  ///< node rows by set name
  std::vector<ResultsStep> steps;  ///< in step order
  ResultsStatusTotals totals;
  const ResultsStep* step(const std::string& name) const;
};

/// What to read: `with_data` false reads everything but the field values (data stays empty).
struct ReadResultsOptions {
  bool with_data = true;
  /// Non-empty: read the values only of fields whose key or one of whose component labels is
  /// in the set (a study collecting max:CPRESS reads no stresses).
  std::set<std::string> data_for;
  /// Accept a file whose status is RUNNING or ABORTED (a .part file is refused regardless).
  bool allow_incomplete = true;
  /// false: no names (node_names, element_names and the fields' locations stay empty, node_rows
  /// is filled), and fields outside a non-empty data_for only by key and components: what a
  /// study's collection needs, at a fraction of the cost.
  bool names = true;
};

/// Reads `path`. Throws IoError, with a message saying which, when the file is missing, is a
/// `.part` file (a run still writing, or killed), is not HDF5, is not an inpact results file
/// (no schema="inpact-results"), or (allow_incomplete false) did not complete.
ResultsFile read_results(const std::filesystem::path& path, const ReadResultsOptions& options = {});

/// Just the root status attribute ("" when the file is not an inpact results file); reads
/// nothing else.
std::string results_status(const std::filesystem::path& path);

}  // namespace inpact::io
