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

/// *STATIC, STABILIZE[=fraction][, FACTOR=c][, ALLSDTOL=tol][, CONTINUE=YES|NO]: automatic
/// stabilization with viscous forces c M* Δu/Δt (solver/stabilization.hpp) [K16 *STATIC].
struct Stabilization {
  /// STABILIZE=: the dissipated energy fraction that sets c from the first increment (2e-4).
  double energy_fraction = 2e-4;
  std::optional<double> damping_factor;  ///< FACTOR=: c given directly (the fraction is then unused)
  std::optional<double> allsdtol;  ///< ALLSDTOL=: adaptive, c lowered to keep ALLSD ≤ tol·ALLSE
  bool continue_previous = false;  ///< CONTINUE=YES: start from the previous step's damping factor
};

/// *STATIC: its data line (initial increment, time period, minimum, maximum increment).
/// The parser always fills every field, blanks with the Abaqus defaults (parser/kw_step.cpp).
struct StaticProcedure {
  bool direct = false;  ///< DIRECT: fixed increments of `initial_increment`
  bool direct_no_stop = false;  ///< DIRECT=NO STOP: accept an increment after IC iterations
  double initial_increment = 1.0;  ///< Abaqus default: the time period
  double time_period = 1.0;
  std::optional<double> min_increment;  ///< default min(initial, 1e-5 × period)
  std::optional<double> max_increment;  ///< default the time period (no upper limit)
  std::optional<Stabilization> stabilize;  ///< STABILIZE: automatic stabilization
  SourceLoc loc;
};

/// The data fields of a *CONTROLS block as given: a blank field stays unset, which means the
/// Abaqus default for that position.
using ControlFields = std::vector<std::optional<double>>;

/// *CONTROLS, PARAMETERS=TIME INCREMENTATION: up to four data lines [K16 §3.75]. Line 1 holds
/// the iteration counts I0, IR, IP, IC, IL, IG, IS, IA, IJ, IT, ?, ?, I_A^c (1-based positions;
/// see parser/KEYWORDS.md for their meaning and defaults); line 2 the cutback and growth
/// factors D_f, D_C, D_B, D_A, D_S, D_H, D_D, W_G, ...; lines 3-4 further factors.
struct TimeIncrementationControls {
  ControlFields line1;
  ControlFields line2;
  ControlFields line3;
  ControlFields line4;
  SourceLoc loc;

  /// Line 1, field 13 (I_A^c): the maximum number of augmentations for *SURFACE BEHAVIOR,
  /// AUGMENTED LAGRANGE [IG "Modifying the Number of Allowed Augmentations"]. Unset: the
  /// solver's default (50 in current Abaqus prints, 6 in older ones).
  std::optional<double> max_augmentations() const {
    return line1.size() >= 13 ? line1[12] : std::nullopt;
  }
};

/// *CONTROLS, PARAMETERS=FIELD: residual and correction tolerances. Line 1: R_n^α, C_n^α,
/// q_0^α, q_u^α, R_p^α, ε^α, C_ε^α, R_l^α (CalculiX names, same as Abaqus); line 2 as given.
struct FieldControls {
  std::string field = "GLOBAL";  ///< FIELD=: GLOBAL or DISPLACEMENT (the only field inpact has)
  ControlFields values;  ///< line 1
  ControlFields line2;
  SourceLoc loc;
};

/// *CONTROLS, PARAMETERS=LINE SEARCH: N_ls, s_max, s_min, f_s, η_ls (Abaqus order; UNCONFIRMED).
struct LineSearchControls {
  ControlFields values;
  SourceLoc loc;
};

/// The *CONTROLS blocks of one step. RESET returns every control to its default before the
/// blocks after it in the step apply.
struct Controls {
  bool reset = false;
  bool analysis_discontinuous = false;  ///< ANALYSIS=DISCONTINUOUS: expect many severe iterations
  std::optional<TimeIncrementationControls> time_incrementation;
  std::optional<FieldControls> field;
  std::optional<LineSearchControls> line_search;
};

/// One output request: *NODE/*ELEMENT/*CONTACT OUTPUT under *OUTPUT, or a print/file request.
struct OutputRequest {
  enum class Kind : std::uint8_t {
    NodeField, ElementField, ContactField,    ///< under *OUTPUT, FIELD
    NodeHistory, ElementHistory, ContactHistory,  ///< under *OUTPUT, HISTORY
    NodePrint, ElementPrint, ContactPrint,    ///< *NODE PRINT / *EL PRINT / *CONTACT PRINT (.dat)
    NodeFile, ElementFile, ContactFile,       ///< *NODE FILE / *EL FILE / *CONTACT FILE
    /// *OUTPUT, FIELD|HISTORY, VARIABLE=PRESELECT|ALL on its own: the whole model's preselected
    /// (or all) variables, without a *NODE/*ELEMENT/*CONTACT OUTPUT naming them.
    ModelField, ModelHistory
  };
  /// OP= of the *OUTPUT block: ADD keeps the requests of earlier steps, NEW removes them all,
  /// REPLACE replaces earlier requests of the same kind.
  enum class Op : std::uint8_t { Add, New, Replace };
  /// POSITION= of element output; Default = the keyword's own default (integration points for
  /// *ELEMENT OUTPUT and *EL PRINT, nodes for *EL FILE in CalculiX).
  enum class Position : std::uint8_t { Default, IntegrationPoints, Centroidal, Nodes, AveragedAtNodes };
  Kind kind;
  std::vector<std::string> variables;  ///< upper-case Abaqus identifiers (U, RF, S, CPRESS, ...)
  bool preselect = false;              ///< VARIABLE=PRESELECT (or no data line)
  bool all = false;                    ///< VARIABLE=ALL
  int frequency = 1;                   ///< every n-th increment and the last; 0 = no output at all
  std::optional<int> number_interval;  ///< NUMBER INTERVAL: n evenly spaced times in the step
  bool time_marks = false;             ///< TIME MARKS=YES: at exact multiples of the interval
  Op op = Op::Add;
  Position position = Position::Default;
  std::string set;      ///< NSET / ELSET restriction, upper case; empty = whole model
  std::string surface;  ///< contact output: SLAVE (SECONDARY) or SURFACE restriction, upper case
  std::string master;   ///< contact output: MASTER (MAIN) surface, upper case
  bool totals = false;  ///< *NODE PRINT, TOTALS=YES (CalculiX TOTALS=ONLY also sets totals_only)
  bool totals_only = false;
  bool summary = true;  ///< *NODE PRINT, SUMMARY
  bool global = false;  ///< GLOBAL=YES: a transformed node's values in global axes (else its local ones)
  /// *ELEMENT OUTPUT's section-point line: the shell and beam section points to report (1-based,
  /// sorted, unique); empty = Abaqus's default (a shell's SNEG and SPOS, a beam's output points).
  std::vector<int> section_points;
  SourceLoc loc;
};

/// The note of a step whose NLGEOM the reader switched on (Step::nlgeom_switched_on).
inline constexpr const char* nlgeom_switched_on_note() {
  return "NOTE: NLGEOM IS SWITCHED ON FOR THIS STEP: THE MODEL HAS HYPERELASTIC MATERIALS, WHICH NEED GEOMETRIC "
         "NONLINEARITY";
}

/// One *MODEL CHANGE, TYPE=ELEMENT: elements removed from this step on, or reactivated [K16
/// *MODEL CHANGE], [CCX]. A removed element carries no stiffness; the forces it exerted at the end
/// of the previous step ramp to zero over this one. A reactivated one starts from a virgin
/// material state, STRAIN FREE (the default) with its strain measured from where its nodes are
/// at the step start, WITH STRAIN from the original configuration.
struct ElementChange {
  bool add = false;            ///< ADD; else REMOVE
  bool with_strain = false;    ///< ADD=WITH STRAIN
  std::vector<std::int32_t> elements;  ///< element rows
  SourceLoc loc;
};

struct Step {
  std::string name;         ///< NAME, as written; default "Step-N" (N = 1-based position)
  std::string description;  ///< the optional data line of *STEP
  bool nlgeom = false;
  /// NLGEOM was off in the deck and the reader switched it on: a hyperelastic material needs
  /// it (Abaqus does the same and says so); the run notes it in the .dat, .sta and stdout.
  bool nlgeom_switched_on = false;
  int max_increments = 100;  ///< INC
  bool unsymm = false;
  enum class DefaultAmplitude : std::uint8_t { Ramp, Step } amplitude = DefaultAmplitude::Ramp;
  /// EXTRAPOLATION: how the first guess of an increment is predicted from the previous ones
  /// (Abaqus default LINEAR; PARABOLIC uses two previous increments; None = no extrapolation).
  enum class Extrapolation : std::uint8_t { Linear, Parabolic, None } extrapolation = Extrapolation::Linear;
  /// CONVERT SDI=YES (default per KEYWORDS.md): iterations with severe discontinuities (contact
  /// status changes) are checked for convergence like equilibrium iterations; NO counts them apart.
  bool convert_sdi = true;
  std::optional<StaticProcedure> static_procedure;  ///< the procedure (only static for now)

  std::vector<BoundaryBlock> boundaries;
  std::vector<CloadBlock> cloads;
  std::vector<DloadBlock> dloads;
  std::vector<TemperatureBlock> temperatures;
  std::vector<ContactControls> contact_controls;
  std::vector<ContactStabilizationBlock> contact_stabilizations;  ///< *CONTACT STABILIZATION
  Controls controls;
  std::vector<OutputRequest> output;
  std::vector<ContactPair> contact_pairs;  ///< pairs added in this step (*CONTACT PAIR in a step)
  // Contact changes from this step on (contact/step_changes.hpp applies them).
  std::vector<FrictionChange> friction_changes;         ///< *CHANGE FRICTION
  std::vector<SurfaceBehaviorChange> behavior_changes;  ///< *CHANGE SURFACE BEHAVIOR
  std::vector<ContactPairChange> pair_changes;          ///< *MODEL CHANGE, TYPE=CONTACT PAIR
  std::vector<ElementChange> element_changes;           ///< *MODEL CHANGE, TYPE=ELEMENT
  SourceLoc loc;
};

/// The first step with NLGEOM (it stays on in every later one), or null: the one test of
/// whether an analysis is geometrically nonlinear anywhere.
inline const Step* first_nlgeom_step(const std::vector<Step>& steps) {
  for (const Step& s : steps)
    if (s.nlgeom) return &s;
  return nullptr;
}

}  // namespace inpact::model
