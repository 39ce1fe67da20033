#pragma once
/// What the analysis hands out: the fields of each converged increment, named by Abaqus output
/// identifiers, and one status row per increment attempt. Plain data with no dependencies:
/// io/ writes these types (it uses them as its own), the solver never includes io/.
#include <cstdint>
#include <string>
#include <vector>

namespace inpact::solver {

/// Where a field's values live (Abaqus's output positions).
enum class Position : std::uint8_t { Nodal, IntegrationPoint, ElementNodal, Centroid };

/// One field output of one frame: nloc locations × ncomp components.
struct FieldData {
  std::string key;  ///< Abaqus identifier: U, RF, S, E, CPRESS, COPEN, CSTATUS, ...
  Position position = Position::Nodal;
  std::vector<std::string> component_labels;  ///< U1 U2 U3, S11 S22 S33 S12 S13 S23, CPRESS, ...
  std::string region;  ///< "" for the whole model, else a set, surface or "SLAVE/MASTER"
  /// NODAL: rows of the model's nodes (empty = every node in row order).
  std::vector<std::int64_t> nodes;
  /// Element-based: element labels, with their instance indices when the model has parts
  /// (`instance` empty = instance 0 for every location).
  std::vector<std::int64_t> elements;
  std::vector<std::int32_t> instance;
  /// INTEGRATION_POINT: 1-based integration point; ELEMENT_NODAL: 1-based local node.
  std::vector<std::int32_t> ip;
  /// INTEGRATION_POINT fields at beams' or shells' section points (S, E, LE; a shell's PE, PEEQ,
  /// PEMAG too): the section point of each such location (elements/beam_section_points.hpp; a
  /// shell's from 1 = SNEG up, shell_elements.hpp), 0 elsewhere; empty when there is none. `ip`
  /// is then the (in-plane) integration point.
  std::vector<std::int32_t> section_point;
  /// Contact fields: rows of the contact pair table (one location per slave node per pair).
  std::vector<std::int32_t> pair;
  std::vector<double> values;  ///< nloc × ncomp, row-major
};

/// One whole-model scalar of a frame (Abaqus history output: ALLSE, ALLSD).
struct HistoryValue {
  std::string key;
  double value = 0.0;
};

/// One converged increment's output.
struct Frame {
  double step_time = 0.0;
  double total_time = 0.0;
  int increment = 0;
  std::vector<FieldData> fields;
  /// Written as /steps/<STEP>/frames/<KEY> (nf,), beside step_time (NaN in frames without it).
  std::vector<HistoryValue> history;
};

/// One printed table of a *NODE PRINT or *EL PRINT request at one increment: the values the
/// .dat file shows (io::DatReport formats them). The solver fills it; it is plain data.
struct PrintTable {
  enum class Domain : std::uint8_t { Node, Element, Contact };
  Domain domain = Domain::Node;
  std::string set;           ///< NSET / ELSET as written in the deck; "" = the whole model;
                             ///< contact tables: the pair, "SLAVE/MASTER"
  std::string element_type;  ///< element tables: one table per element type (C3D8, ...)
  bool centroid = false;     ///< element tables: POSITION=CENTROIDAL (no integration point column)
  std::vector<std::string> columns;  ///< U1 U2 U3, RF1.., COORD1.., S11.., E11.., MISES
  std::vector<std::int64_t> labels;  ///< node or element label of each row
  std::vector<std::int32_t> ip;      ///< element tables at integration points: 1-based point
  bool at_section_points = false;  ///< a beam's or shell's table of S and E: a SEC PT column
  std::vector<std::int32_t> section_point;  ///< at_section_points: the section point of each row
  std::vector<double> values;        ///< rows × columns, row-major
  bool summary = true;      ///< SUMMARY=YES: MAXIMUM / MINIMUM lines under each column
  bool totals = false;      ///< TOTALS=YES|ONLY: the column sums
  bool totals_only = false; ///< TOTALS=ONLY (CalculiX): the sums without the rows
};

/// The printed output of one converged increment (only increments with a print request due).
struct PrintFrame {
  int step = 1;  ///< 1-based
  int increment = 0;
  double step_time = 0.0;
  double total_time = 0.0;
  double inc_of_time = 0.0;
  double time_period = 1.0;  ///< of the step (the "fraction of step completed")
  std::vector<PrintTable> tables;
};

/// One row of the status (.sta) table: one attempt of one increment.
struct StatusRow {
  std::int32_t step = 1;       ///< 1-based step number
  std::int32_t increment = 1;  ///< 1-based increment number within the step
  std::int32_t attempt = 1;    ///< 1-based attempt of this increment
  bool cut_back = false;       ///< the attempt failed and the increment was cut back (`U`)
  std::int32_t severe_discon_iters = 0;
  std::int32_t equil_iters = 0;
  std::int32_t total_iters = 0;  ///< severe + equilibrium
  /// Total and step time reached; for a cut-back attempt, the time at the start of the
  /// increment (as Abaqus shows it).
  double total_time = 0.0;
  double step_time = 0.0;
  double inc_of_time = 0.0;  ///< the time increment attempted
  std::int32_t augmentations = 0;
};

}  // namespace inpact::solver
