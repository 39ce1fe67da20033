#pragma once
/// The `.dat` print file JOB.dat: the tables of *NODE PRINT and *EL PRINT in Abaqus/Standard's
/// data-file layout, at each increment a print request is due (its FREQUENCY, always the last
/// increment of a step unless FREQUENCY=0), for its NSET / ELSET. The solver computes the
/// values (solver::PrintFrame, see solver/field_output.hpp); this class only formats them.
///
/// Layout, after Abaqus 6.14's data file as the Getting Started guide prints it (§2.3.8, the
/// overhead hoist frame) and the column headers real .dat readers match on:
///
///                                     INCREMENT     1 SUMMARY
///
///      TIME INCREMENT COMPLETED   1.00    ,  FRACTION OF STEP COMPLETED   1.00
///      STEP TIME COMPLETED        1.00    ,  TOTAL TIME COMPLETED         1.00
///
///                                        E L E M E N T   O U T P U T
///
///        THE FOLLOWING TABLE IS PRINTED AT THE INTEGRATION POINTS FOR ELEMENT TYPE C3D8 AND ELEMENT SET BAR
///
///         ELEMENT  PT FOOT-       S11         S22   ...   MISES
///                     NOTE
///
///                1   1           0.000       0.000  ...   100.0
///      MAXIMUM                   ...
///      ELEMENT                   ...
///      MINIMUM / ELEMENT, TOTAL  (SUMMARY=YES: MAXIMUM/MINIMUM lines; TOTALS=YES: TOTAL line)
///
///                                            N O D E   O U T P U T
///
///        THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET TOP
///
///            NODE FOOT-  U1          U2          U3
///                 NOTE
///
///             5      -2.5000E-05 ...
///      MAXIMUM ...  / AT NODE ...  / MINIMUM ... / AT NODE ... / TOTAL ...
///
/// Numbers are Fortran 1PG12.4 (E format 7.3531E-04 outside [0.1, 10⁴), else F with 4
/// significant digits: 5000., 0.000). As in that printout, a value below 1e-12 of its column's
/// largest magnitude prints as zero and a row of zeros is left out, while MAXIMUM, MINIMUM and
/// TOTAL still count every row. Element tables come before node tables, one table per element
/// type; rows are sorted by label (then integration point).
///
/// Where inpact deviates from Abaqus:
///  - One table per request: every variable of a *NODE PRINT / *EL PRINT is a column of one
///    table, where Abaqus makes one table per data line (the parser does not keep lines apart).
///  - Labels are the deck's own node and element labels; Abaqus prints internal numbers for
///    models with part instances (and a table mapping them).
///  - Element COORD is the point's original position, also under NLGEOM (Abaqus: current).
///    POSITION=CENTROIDAL prints the volume-weighted average of the integration points;
///    NODES / AVERAGED AT NODES print the integration points.
///  - The increment summary is printed only for increments with tables; no page headers, no
///    echo of the model and history data, no memory estimates.
///  - Column widths follow the printout above; later Abaqus releases print wider columns.
///  - S and E of a section with an *ORIENTATION are in the global frame, as every other
///    output; Abaqus prints them in the material axes (CalculiX's EL PRINT, GLOBAL=YES prints
///    the global ones). The *SOLID SECTION warns about it.
///
/// *NODE FILE, *EL FILE and *CONTACT FILE write a .frd file in CalculiX (and the .fil results
/// file in Abaqus): inpact writes their variables into JOB.h5 instead, as field output with
/// the request's FREQUENCY and set (solver/field_output.hpp). *CONTACT PRINT prints nothing
/// yet (contact output is not computed by the solver).
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "model/step.hpp"
#include "solver/results_frame.hpp"

#include "io_error.hpp"

namespace inpact::io {

using solver::PrintFrame;
using solver::PrintTable;

/// Fortran 1PGw.d of v (Abaqus's number format in the data file), `width` characters.
std::string fortran_g(double v, int width, int digits);

/// One table as it appears in the data file (the title line to the last summary line, each
/// line ending in '\n').
std::string format_print_table(const PrintTable& table);

class DatReport {
 public:
  /// Creates (truncates) `path` and writes the header (`solver_line`, when given, under the
  /// version: the linear solver of the run). Throws IoError when it cannot.
  DatReport(std::filesystem::path path, const std::string& solver_version, const std::string& heading = "",
            const std::string& solver_line = "");
  /// The step banner (S T E P  n  S T A T I C   A N A L Y S I S) and the step's description.
  void begin_step(const model::Step& step, int number);
  /// The step's contact rows as the analysis enforces them (contact::describe() lines).
  void contact_interactions(const std::vector<std::string>& lines);
  /// The increment summary and every table of `frame`; flushed.
  void write(const PrintFrame& frame);
  /// The closing line: THE ANALYSIS HAS (NOT) BEEN COMPLETED.
  void finish(bool completed);
  const std::filesystem::path& path() const { return path_; }

 private:
  void put(const std::string& text);
  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace inpact::io
