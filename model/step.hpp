#pragma once
/// *STEP and the history data it holds.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "contact.hpp"
#include "loads.hpp"
#include "source_loc.hpp"

namespace inpact::model {

/// *STATIC: its data line (initial increment, time period, minimum, maximum increment).
struct StaticProcedure {
  bool direct = false;  ///< DIRECT: fixed increments of `initial_increment`
  double initial_increment = 1.0;  ///< Abaqus default: the time period
  double time_period = 1.0;
  std::optional<double> min_increment;  ///< unset: min(initial, 1e-5 × period)
  std::optional<double> max_increment;  ///< unset: the time period
  SourceLoc loc;
};

/// *CONTROLS, PARAMETERS=TIME INCREMENTATION (only the fields that were given are set).
struct TimeIncrementationControls {
  std::vector<std::optional<double>> line1;  ///< I0, IR, IP, IC, IL, IG, IS, IA, IJ, IT, ISC?...
  std::vector<std::optional<double>> line2;  ///< Df, DC, DB, DA, DS, DH, DD, WG
  SourceLoc loc;
};

/// *CONTROLS, PARAMETERS=FIELD: residual and correction tolerances (R_n^α, C_n^α, ...).
struct FieldControls {
  std::vector<std::optional<double>> values;
  SourceLoc loc;
};

struct Controls {
  bool reset = false;
  bool analysis_discontinuous = false;
  std::optional<TimeIncrementationControls> time_incrementation;
  std::optional<FieldControls> field;
};

/// One output request: *NODE/*ELEMENT/*CONTACT OUTPUT under *OUTPUT, or a print/file request.
struct OutputRequest {
  enum class Kind : std::uint8_t {
    NodeField, ElementField, ContactField,    ///< under *OUTPUT, FIELD
    NodeHistory, ElementHistory, ContactHistory,  ///< under *OUTPUT, HISTORY
    NodePrint, ElementPrint, ContactPrint,    ///< *NODE PRINT / *EL PRINT / *CONTACT PRINT (.dat)
    NodeFile, ElementFile, ContactFile        ///< *NODE FILE / *EL FILE / *CONTACT FILE
  };
  Kind kind;
  std::vector<std::string> variables;  ///< upper-case Abaqus identifiers (U, RF, S, CPRESS, ...)
  bool preselect = false;              ///< VARIABLE=PRESELECT (or no data line)
  bool all = false;                    ///< VARIABLE=ALL
  int frequency = 1;                   ///< every n-th increment; 0 = none (last only)
  std::optional<int> number_interval;
  bool time_marks = false;
  std::string set;      ///< NSET / ELSET restriction, upper case; empty = whole model
  std::string surface;  ///< contact output: SLAVE / MASTER / SURFACE restriction
  bool totals = false;  ///< *NODE PRINT, TOTALS=YES
  bool summary = true;  ///< *NODE PRINT, SUMMARY
  SourceLoc loc;
};

struct Step {
  std::string name;
  bool nlgeom = false;
  int max_increments = 100;  ///< INC
  bool unsymm = false;
  enum class DefaultAmplitude : std::uint8_t { Ramp, Step } amplitude = DefaultAmplitude::Ramp;
  std::optional<StaticProcedure> static_procedure;  ///< the procedure (only static for now)

  std::vector<BoundaryBlock> boundaries;
  std::vector<CloadBlock> cloads;
  std::vector<DloadBlock> dloads;
  std::vector<TemperatureBlock> temperatures;
  std::vector<ContactControls> contact_controls;
  Controls controls;
  std::vector<OutputRequest> output;
  std::vector<ContactPair> contact_pairs;  ///< pairs added in this step (*CONTACT PAIR in a step)
  SourceLoc loc;
};

}  // namespace inpact::model
