#pragma once
/// The results file JOB.h5 (shared/DESIGN.md, "Results file (contract)"): the model, one group
/// per step with its converged frames and field outputs, the .sta table, a /VTKHDF view for
/// ParaView and the JOB.xdmf sidecar for readers without VTKHDF (ParaView 5.11's XDMF reader,
/// VisIt, meshio).
///
/// The file is written as JOB.h5.part and flushed after every frame, so a run that dies keeps
/// every converged frame readable; finish() renames it to JOB.h5. HDF5 stays out of this header.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io_error.hpp"
#include "model/model.hpp"
#include "status_log.hpp"

namespace inpact::io {

/// The frame types are the solver's (solver/results_frame.hpp): io writes what it hands out.
using solver::FieldData;
using solver::Frame;
using solver::Position;

const char* position_name(Position p);  ///< "NODAL", "INTEGRATION_POINT", ...

enum class RunStatus : std::uint8_t { Completed, Aborted };

struct ResultsOptions {
  /// Names for /model/contact/pairs, "SLAVE/MASTER", in the row order the contact fields'
  /// `pair` index uses; unset: contact_pair_names(model).
  std::optional<std::vector<std::string>> contact_pairs;
  /// Flush the file after every frame (a killed run keeps every frame). Off: frames reach
  /// the disk when HDF5's caches spill and at finish() (measured in tests/io: the flush is
  /// a small part of a frame's cost).
  bool flush_each_frame = true;
  /// Root attributes linear_solver ("direct" | "petsc") and linear_solver_choice (the line
  /// solver::describe gives: what and why); not written when empty.
  std::string linear_solver, linear_solver_choice;
};

/// The contact pairs of a model in their default row order: model-level *CONTACT PAIR lines,
/// then those of each step in step order, then general-contact inclusions (an empty surface
/// name shows as "ALL_EXTERIOR"). Names are "SLAVE/MASTER" as Abaqus shows them.
std::vector<std::string> contact_pair_names(const model::Model& model);

/// VTK cell type for an element type (VTK_HEXAHEDRON = 12, ...).
std::uint8_t vtk_cell_type(const model::ElementTypeInfo& type);
/// VTK (and XDMF, meshio) node i of a cell is Abaqus node order[i]; empty: the same order.
/// Abaqus's order is VTK's for every supported type but the wedge (C3D6: 0 2 1 3 5 4);
/// tests/io/check_paraview.py pins this with VTK's own cell validator.
std::span<const std::uint8_t> vtk_node_order(const model::ElementTypeInfo& type);
/// XDMF topology type number of an element type (Hexahedron = 9, Hexahedron_20 = 48, ...).
std::int32_t xdmf_cell_type(const model::ElementTypeInfo& type);
/// XDMF topology type name of an element type ("Hexahedron", "Hexahedron_20", ...).
const char* xdmf_topology_name(const model::ElementTypeInfo& type);

/// Starts the HDF5 library (the first results file does otherwise). A study calls it before it
/// forks its cases, so that each case inherits a started library instead of starting its own.
void start_results_library();

class ResultsWriter {
 public:
  /// Creates `h5_path` + ".part" (removing a stale `h5_path` and its .xdmf sidecar) and writes
  /// the root attributes (status RUNNING), /model and the /VTKHDF geometry. Throws IoError.
  /// `model` must outlive the writer (frames are checked against it and mapped onto it).
  static ResultsWriter create(const std::filesystem::path& h5_path, const model::Model& model,
                              std::string deck_sha256, std::string solver_version,
                              const ResultsOptions& options = {});
  ResultsWriter(ResultsWriter&&) noexcept;
  ResultsWriter& operator=(ResultsWriter&&) noexcept;
  /// Closes the file if finish() was not called; the .part file stays (status RUNNING).
  ~ResultsWriter();

  /// Opens /steps/<NAME> (attrs procedure, nlgeom, time_period, number); frames go there.
  void begin_step(const model::Step& step);
  /// /steps/<NAME>/contact_interactions: the current step's contact rows as the analysis
  /// enforces them (contact::describe(), the text `inpact check` prints).
  void write_contact_interactions(const std::vector<std::string>& lines);
  /// Appends one frame to the current step and flushes the file. Every field is checked first
  /// (sizes, node rows, element labels, same locations as in earlier frames of the step): a
  /// bad frame throws IoError and leaves the file as it was.
  void write_frame(const Frame& frame);
  /// Appends rows to the /status table (written with the next flush, or finish()).
  void append_status(std::span<const StatusRow> rows);
  void append_status(const StatusRow& row) { append_status(std::span<const StatusRow>(&row, 1)); }
  /// Sets the status attribute, closes the file, renames .part → .h5 and writes the .xdmf.
  void finish(RunStatus status);

  const std::filesystem::path& part_path() const;
  const std::filesystem::path& h5_path() const;
  std::filesystem::path xdmf_path() const;
  std::size_t n_frames() const;  ///< frames written so far, all steps

 private:
  struct Impl;
  explicit ResultsWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace inpact::io
