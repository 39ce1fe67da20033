#pragma once
/// What a step writes, and when: the output requests in force for a step, their timing, and
/// the values they ask for. Only what is requested is computed (shared/DESIGN.md, Principles).
///
/// Semantics (Abaqus Analysis User's Guide, "Output" chapter; pages cited by title):
///  - Carry-over. "Output requests apply to the step in which they are defined and to all
///    subsequent steps until they are respecified" ("Requesting Output in Multiple Steps").
///    *OUTPUT, OP=ADD (default) adds to the requests carried over; OP=NEW removes every
///    carried-over output database request first; OP=REPLACE removes the carried-over requests
///    of the same kind (*NODE OUTPUT replaces *NODE OUTPUT, ...). Abaqus matches REPLACE by the
///    request's NAME, which inpact does not read: the kind stands in for it.
///  - Print and file requests (*NODE PRINT, *EL PRINT, *CONTACT PRINT; CalculiX's *NODE FILE,
///    *EL FILE, *CONTACT FILE) carry over too; a step that gives a request of one of these
///    kinds replaces every carried-over request of that kind (CalculiX: "the first *... in a
///    step replaces the earlier selections", parser/KEYWORDS.md).
///  - Default. When the first step has no field request (*OUTPUT, FIELD or *NODE/*EL FILE),
///    the preselected variables are requested every increment ("Writing Default Output to the
///    Output Database"); that default request carries over like any other (OP=NEW drops it).
///  - FREQUENCY=n: every n-th increment and always the last increment of the step; FREQUENCY=0
///    no output at all ("Output to the data and results files": "Unless a frequency of zero is
///    specified to suppress output, the variables will always be output at the last increment").
///  - NUMBER INTERVAL=n: n evenly spaced times t_k = k·period/n. With TIME MARKS=YES the
///    increment is cut so that it ends on the next t_k and output is written there (exact
///    times); without, output is written at the first increment that ends at or after each t_k
///    ("TIME MARKS=YES writes at the specified times, NO at the increment after them", the
///    *OUTPUT keyword). Either way the last increment writes.
///  - NSET / ELSET restrict a request to that set. A field key asked for by several requests is
///    written on the union of their sets, the same locations in every frame of the step (the
///    results file keeps a field's locations within a step).
///  - VARIABLE=PRESELECT: Abaqus's preselection for a static step is S, PE, PEEQ, PEMAG, LE, U,
///    RF, CF, CSTRESS, CDISP. inpact writes the ones it computes: U, RF (nodes) and S, E
///    (integration points; E is the kernel's strain, logarithmic under NLGEOM), PE, PEEQ and
///    PEMAG when a section has plasticity (*PLASTIC: Abaqus writes them for such elements) and, when the
///    model has contact pairs or general contact, CPRESS and COPEN (+ CSHEAR1/2 and CSLIP1/2
///    with friction) for CSTRESS and CDISP. VARIABLE=ALL adds COORD (nodal). Variables named explicitly that inpact does not compute are listed
///    by not_computed(), which the analysis reports once per step.
///  - Field output of a component (U1, S11) writes the whole variable (Abaqus field output has
///    complete sets only); MISES asks for S (its invariants come with it).
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "analysis_model.hpp"
#include "contact_results.hpp"
#include "results_frame.hpp"

namespace inpact::solver {

class MaterialStates;

struct ElementPoints;  // assembler.hpp

/// The output requests in force for step `step_index` after the carry-over rules above, in
/// the order they were given (the default preselect request first when it applies).
std::vector<model::OutputRequest> requests_in_force(const model::Model& model, std::size_t step_index);

/// When one request writes within a step of length `period`.
class OutputTiming {
 public:
  OutputTiming(const model::OutputRequest& request, double period);
  /// Whether output is due at the converged increment `increment` (1-based) that ended at step
  /// time `t`; `last` marks the step's last increment. Advances past the time marks t reached.
  bool due(int increment, double t, bool last);
  /// Whether due() would say yes, without advancing.
  bool would_be_due(int increment, double t, bool last) const;
  /// TIME MARKS=YES: the next mark after step time t (the increment is cut to end there).
  std::optional<double> next_mark(double t) const;

 private:
  double mark(int k) const { return period_ * k / n_interval_; }
  int frequency_ = 1;
  int n_interval_ = 0;  ///< NUMBER INTERVAL; 0 = by FREQUENCY
  bool time_marks_ = false;
  double period_ = 1.0;
  double tol_ = 1e-9;
  int next_ = 1;  ///< the first mark not reached yet
};

/// One request in force, resolved against the model.
struct ActiveRequest {
  model::OutputRequest request;
  /// Field requests: the keys it writes (U, RF, COORD, S, E). Print requests: the columns
  /// inpact prints (U → U1 U2 U3, S33, MISES, COORD1, ...).
  std::vector<std::string> variables;
  bool whole_model = true;
  std::vector<std::int32_t> rows;  ///< node or element rows of NSET/ELSET (sorted) unless whole_model
};

/// Which requests are due at one increment (indices as in StepOutput's request lists).
struct OutputDue {
  std::vector<bool> field;
  std::vector<bool> print;
  bool any_field() const;
  bool any_print() const;
};

/// The output of one step: requests in force, their timing, and what each frame holds.
class StepOutput {
 public:
  /// The requests in force for step `step_index` of `am.model`, resolved against its sets.
  StepOutput(const AnalysisModel& am, std::size_t step_index);

  const std::vector<ActiveRequest>& field_requests() const { return field_; }
  const std::vector<ActiveRequest>& print_requests() const { return print_; }
  /// Requested identifiers inpact does not compute (each once), for the step's message.
  const std::vector<std::string>& not_computed() const { return not_computed_; }
  /// Every field key some request of this step writes.
  std::set<std::string> field_keys() const;

  /// The increment dt starting at step time t, shortened to end on the next TIME MARKS time.
  double limit_increment(double t, double dt) const;
  /// Which requests write at this converged increment; advances the timings.
  OutputDue due(int increment, double t, bool last);
  /// Whether an increment that converges at step time t would write element point values
  /// (S, E, *EL PRINT): its assemblies then keep them (AssemblyRequest::points).
  bool points_due(int increment, double t, bool last) const;

 private:
  std::vector<ActiveRequest> field_, print_;
  std::vector<OutputTiming> field_timing_, print_timing_;
  std::vector<std::string> not_computed_;
};

/// The values of one converged increment for the requests due.
struct OutputValues {
  std::vector<FieldData> fields;    ///< for the results file
  std::vector<PrintTable> tables;   ///< for the .dat file
};

/// Computes the fields and print tables `due` asks for at displacement u with reactions `rf`
/// (full DOF vectors); `delta_t` the nodal temperature change, as for the assembly. Element
/// point values are taken from `points` (kept by the assembly at this very state) when given,
/// else computed, only for the elements a due request covers, from the committed history in
/// `states` (null: none has state).
/// `contact`: the contact values of the increment (null without contact), written as the
/// NODAL contact fields CPRESS, COPEN, CSTATUS, CNAREA, CFN and, for friction, CSHEAR1/2,
/// CSLIP1/2 and CFS (one location per slave node per pair, `pair` and `nodes` filled) for
/// *CONTACT OUTPUT requests (SLAVE/MASTER restrict the pairs; CSTRESS asks for CPRESS, CDISP for
/// COPEN, each with CSHEAR1/2 resp. CSLIP1/2 when the model has friction; PRESELECT gives
/// CPRESS and COPEN (+ CSHEAR, CSLIP with friction), ALL also CSTATUS, CNAREA, CFN (+ CFS)).
OutputValues compute_output(const AnalysisModel& am, const StepOutput& output, const OutputDue& due,
                            std::span<const double> u, std::span<const double> rf, bool nlgeom,
                            std::span<const double> delta_t, const ContactResults* contact = nullptr,
                            const ElementPoints* points = nullptr, const MaterialStates* states = nullptr);

/// Von Mises equivalent stress of Abaqus-ordered components 11 22 33 12 13 23:
/// q = sqrt(½[(s11−s22)² + (s22−s33)² + (s33−s11)²] + 3(s12² + s13² + s23²)).
double von_mises(std::span<const double, 6> s);

}  // namespace inpact::solver
