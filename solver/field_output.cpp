#include "field_output.hpp"

#include <array>
#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <fmt/format.h>

#include "assembler.hpp"
#include "elements/beam_section_points.hpp"
#include "elements/element_kernel.hpp"
#include "elements/material.hpp"
#include "elements/material_orientation.hpp"
#include "elements/shell_section.hpp"
#include "material_states.hpp"
#include "model/reference_nodes.hpp"

namespace inpact::solver {

namespace {

using model::OutputRequest;
using Kind = OutputRequest::Kind;

/// Output database requests (*OUTPUT, FIELD|HISTORY and what it holds): OP= applies to them.
bool is_odb(Kind k) {
  switch (k) {
    case Kind::NodeField: case Kind::ElementField: case Kind::ContactField: case Kind::ModelField:
    case Kind::NodeHistory: case Kind::ElementHistory: case Kind::ContactHistory: case Kind::ModelHistory:
      return true;
    default: return false;
  }
}

/// Requests written to the results file as fields; CalculiX's *... FILE ones included (inpact
/// writes them into JOB.h5, not a .frd file).
bool is_field(Kind k) {
  switch (k) {
    case Kind::NodeField: case Kind::ElementField: case Kind::ContactField: case Kind::ModelField:
    case Kind::NodeFile: case Kind::ElementFile: case Kind::ContactFile:
      return true;
    default: return false;
  }
}

bool is_print(Kind k) { return k == Kind::NodePrint || k == Kind::ElementPrint || k == Kind::ContactPrint; }

/// Print and file requests: a step that gives one of a kind replaces the carried-over ones.
bool replaced_by_kind(Kind k) { return is_print(k) || k == Kind::NodeFile || k == Kind::ElementFile || k == Kind::ContactFile; }

enum class Domain : std::uint8_t { Node, Element, Contact, Model };

Domain domain_of(Kind k) {
  switch (k) {
    case Kind::NodeField: case Kind::NodeFile: case Kind::NodePrint: case Kind::NodeHistory: return Domain::Node;
    case Kind::ElementField: case Kind::ElementFile: case Kind::ElementPrint: case Kind::ElementHistory:
      return Domain::Element;
    case Kind::ContactField: case Kind::ContactFile: case Kind::ContactPrint: case Kind::ContactHistory:
      return Domain::Contact;
    default: return Domain::Model;
  }
}

bool all_digits(std::string_view s, std::size_t n) {
  return s.size() == n && std::all_of(s.begin(), s.end(), [](char c) { return c >= '1' && c <= '3'; });
}

/// "U", "U2" → true for base "U" (one component digit); "S", "S12" for tensors (two digits).
bool is_variable(std::string_view v, std::string_view base, std::size_t digits) {
  if (v.substr(0, base.size()) != base) return false;
  const std::string_view rest = v.substr(base.size());
  return rest.empty() || all_digits(rest, digits);
}

/// The results-file key a field request's variable asks for, or "" when inpact has none.
std::string field_key(std::string_view v, Domain d) {
  const bool node = d == Domain::Node || d == Domain::Model;
  const bool element = d == Domain::Element || d == Domain::Model;
  if (node) {
    for (std::string_view k : {"UR", "RM", "U", "RF", "COORD"})
      if (is_variable(v, k, 1)) return std::string(k);
  }
  if (d == Domain::Contact || d == Domain::Model) {
    if (v == "CSTRESS" || v == "CSTR") return "CPRESS";  // CSTR, CDIS: CalculiX's *CONTACT FILE
    if (v == "CDISP" || v == "CDIS") return "COPEN";
    if (v == "CFN1" || v == "CFN2" || v == "CFN3") return "CFN";
    if (v == "CFS1" || v == "CFS2" || v == "CFS3") return "CFS";
    for (std::string_view k : {"CPRESS", "COPEN", "CSTATUS", "CNAREA", "CFN", "CSHEAR1", "CSHEAR2", "CSLIP1", "CSLIP2", "CFS"})
      if (v == k) return std::string(k);
  }
  if (element) {
    if (v == "MISES") return "S";
    if (v == "PEEQ" || v == "PEMAG") return std::string(v);
    // Section forces and moments: trusses' axial force SF1, beams' SF1..SF3 and SM1..SM3.
    if (is_variable(v, "SF", 1)) return "SF";
    if (is_variable(v, "SM", 1)) return "SM";
    for (std::string_view k : {"PE", "LE", "S", "E"})
      if (is_variable(v, k, 2)) return std::string(k);
  }
  return "";
}

/// Abaqus's components: 3D 11 22 33 12 13 23; plane and axisymmetric 11 22 33 12.
std::vector<std::string> tensor_labels(const std::string& key, int dim) {
  std::vector<std::string> l = {key + "11", key + "22", key + "33", key + "12"};
  if (dim == 3) l.insert(l.end(), {key + "13", key + "23"});
  return l;
}

std::vector<std::string> vector_labels(const std::string& key, int dim) {
  std::vector<std::string> l;
  for (int c = 1; c <= dim; ++c) l.push_back(key + std::to_string(c));
  return l;
}

/// A rotation vector's components: UR1 UR2 UR3 in 3D, UR3 alone in 2D (the in-plane rotation).
std::vector<std::string> rotation_labels(const std::string& key, int dim) {
  if (dim == 2) return {key + "3"};
  return vector_labels(key, 3);
}

bool rotation_key(const std::string& key) { return key == "UR" || key == "RM"; }

/// The printed columns of a print request's variable (U → U1 U2 U3, S33 → S33), or none
/// when inpact does not print it.
std::vector<std::string> print_columns(const std::string& v, Domain d, int dim) {
  auto component = [&](const std::vector<std::string>& labels) -> std::vector<std::string> {
    if (std::find(labels.begin(), labels.end(), v) != labels.end()) return {v};
    return {};
  };
  if (d == Domain::Node) {
    for (const char* k : {"UR", "RM"}) {
      if (v == k) return rotation_labels(k, dim);
      if (is_variable(v, k, 1)) return component(rotation_labels(k, dim));
    }
    for (const char* k : {"U", "RF", "COORD"}) {
      if (v == k) return vector_labels(k, dim);
      if (is_variable(v, k, 1)) return component(vector_labels(k, dim));
    }
  } else if (d == Domain::Contact) {
    // Abaqus's CSTRESS / CDISP and CalculiX's CSTR / CDIS: the pressure (opening) and the two
    // shear (slip) components; CFN its three components; the rest one column each.
    if (v == "CSTRESS" || v == "CSTR") return {"CPRESS", "CSHEAR1", "CSHEAR2"};
    if (v == "CDISP" || v == "CDIS") return {"COPEN", "CSLIP1", "CSLIP2"};
    if (v == "CFN") return {"CFN1", "CFN2", "CFN3"};
    for (const char* k : {"CPRESS", "COPEN", "CSTATUS", "CNAREA", "CSHEAR1", "CSHEAR2", "CSLIP1", "CSLIP2", "CFN1", "CFN2", "CFN3"})
      if (v == k) return {v};
  } else if (d == Domain::Element) {
    if (v == "MISES" || v == "PEEQ" || v == "PEMAG") return {v};
    for (const char* k : {"SF", "SM"}) {
      if (v == k) return vector_labels(k, 3);
      if (is_variable(v, k, 1)) return component(vector_labels(k, 3));
    }
    if (v == "COORD") return vector_labels(v, dim);
    if (is_variable(v, "COORD", 1)) return component(vector_labels("COORD", dim));
    for (const char* k : {"PE", "LE", "S", "E"}) {
      if (v == k) return tensor_labels(k, dim);
      if (is_variable(v, k, 2)) return component(tensor_labels(k, dim));
    }
  }
  return {};
}

void add_unique(std::vector<std::string>& list, const std::string& v) {
  if (std::find(list.begin(), list.end(), v) == list.end()) list.push_back(v);
}

/// LE is E's values under Abaqus's name for them with NLGEOM (the logarithmic strain; without
/// NLGEOM the small strain, which it equals to first order).
constexpr const char* kFieldKeys[] = {"U", "UR", "RF", "RM", "COORD", "S", "E", "LE", "PE", "PEEQ", "PEMAG", "SF", "SM"};

bool nodal_key(const std::string& key) { return key == "U" || key == "RF" || key == "COORD" || rotation_key(key); }

/// Keys of integration-point values (computed by the element kernels).
bool point_key(const std::string& key) {
  return key == "S" || key == "E" || key == "LE" || key == "PE" || key == "PEEQ" || key == "PEMAG" || key == "SF" ||
         key == "SM";
}

/// Plastic strain keys and print variables: PE (PE11, ...), PEEQ, PEMAG.
bool plastic_key(const std::string& key) { return key.rfind("PE", 0) == 0; }

/// Some element a request reports (its ELSET's, or the model's) satisfies `pred`.
template <class Pred>
bool any_reported(const AnalysisModel& am, const ActiveRequest& a, Pred&& pred) {
  if (a.whole_model || domain_of(a.request.kind) != Domain::Element)  // (a node set's rows are nodes)
    return std::any_of(am.elements.begin(), am.elements.end(), pred);
  return std::any_of(a.rows.begin(), a.rows.end(), [&](std::int32_t e) { return pred(am.elements[static_cast<std::size_t>(e)]); });
}

/// Beams are elastic: their plastic strains are noted as not computed (their S and E are at
/// their section points, SF and SM at their integration points).
bool reports_beams(const AnalysisModel& am, const ActiveRequest& a) {
  return any_reported(am, a, [](const ElementSetup& s) { return model::is_beam(*s.type); });
}

/// Whether a field key is reported at a beam's section points (S, E or LE; MISES comes with S).
bool at_section_points(const std::string& key) { return key == "S" || key == "E" || key == "LE"; }

/// A printed variable a beam reports at its section points (S11, S12, E11, E12, LE11, LE12,
/// MISES; defined with the print columns below).
bool beam_section_point_column(const std::string& variable);

/// A beam whose general section has no *SECTION POINTS has nowhere to report S and E.
bool reports_beams_without_section_points(const AnalysisModel& am, const ActiveRequest& a) {
  return any_reported(am, a, [](const ElementSetup& s) { return s.section.beam && s.section.beam->output_points.empty(); });
}

/// An element the request reports has section point `number`: its shell section has that many
/// points or more, or its beam reports that point.
bool reports_section_point(const AnalysisModel& am, const ActiveRequest& a, int number) {
  return any_reported(am, a, [&](const ElementSetup& s) {
    if (s.section.shell) return static_cast<int>(s.section.shell->zeta.size()) >= number;
    if (!s.section.beam) return false;
    const auto& points = s.section.beam->output_points;
    return std::any_of(points.begin(), points.end(), [&](const auto& q) { return q.number == number; });
  });
}

/// Beams and shells make SF a vector (SF1..SF3); with trusses alone it stays their axial force SF1.
bool model_has_section_vectors(const AnalysisModel& am) {
  return std::any_of(am.elements.begin(), am.elements.end(),
                     [](const ElementSetup& s) { return model::has_rotations(*s.type); });
}

/// A section's material has plasticity (*PLASTIC): only then does the preselection bring PE,
/// PEEQ and PEMAG (Abaqus writes them for elements with plasticity), so an elastic model's
/// results stay as they were.
bool model_has_plasticity(const AnalysisModel& am) {
  return std::any_of(am.elements.begin(), am.elements.end(), [](const ElementSetup& s) {
    return s.material && s.material->state_size() > 0 && s.material->as_isotropic_elastic() == nullptr;
  });
}

constexpr const char* kContactKeys[] = {"CPRESS", "COPEN", "CSTATUS", "CNAREA", "CFN",
                                        "CSHEAR1", "CSHEAR2", "CSLIP1", "CSLIP2", "CFS"};

/// Contact pairs (model or step data) or general contact with inclusions: the model has contact
/// rows, and Abaqus's preselection (CSTRESS, CDISP) applies to both kinds alike.
bool model_has_contact(const model::Model& m) {
  if (!m.contact_pairs.empty()) return true;
  if (m.general_contact.defined && !m.general_contact.inclusions.empty()) return true;
  return std::any_of(m.steps.begin(), m.steps.end(), [](const model::Step& s) { return !s.contact_pairs.empty(); });
}

/// Does some interaction carry friction (μ > 0 or ROUGH)? Only then do CSTRESS and CDISP (and
/// the preselection) bring the tangential fields CSHEAR1/2 and CSLIP1/2 along: a frictionless
/// model's results stay as they were (they would be zeros).
bool model_has_friction(const model::Model& m) {
  return std::any_of(m.interactions.begin(), m.interactions.end(), [](const auto& kv) {
    const auto& f = kv.second.friction;
    return f && (f->mu > 0.0 || f->rough);
  });
}

}  // namespace

// --- Which requests are in force --------------------------------------------------------

std::vector<OutputRequest> requests_in_force(const model::Model& model, std::size_t step_index) {
  std::vector<OutputRequest> in_force;
  auto remove = [&](auto pred) { std::erase_if(in_force, pred); };
  for (std::size_t s = 0; s <= step_index && s < model.steps.size(); ++s) {
    const auto& given = model.steps[s].output;
    // OP=NEW: "discontinue all requests from previous steps" (output database requests).
    if (std::any_of(given.begin(), given.end(), [](const auto& r) { return is_odb(r.kind) && r.op == OutputRequest::Op::New; }))
      remove([](const OutputRequest& r) { return is_odb(r.kind); });
    for (const auto& g : given) {
      if (is_odb(g.kind) && g.op == OutputRequest::Op::Replace) remove([&](const OutputRequest& r) { return r.kind == g.kind; });
      if (replaced_by_kind(g.kind)) remove([&](const OutputRequest& r) { return r.kind == g.kind; });
    }
    // The first step without field requests gets Abaqus's default: the preselected variables.
    if (s == 0 && std::none_of(given.begin(), given.end(), [](const auto& r) { return is_field(r.kind); })) {
      OutputRequest preselect;
      preselect.kind = Kind::ModelField;
      preselect.preselect = true;
      in_force.push_back(std::move(preselect));
    }
    in_force.insert(in_force.end(), given.begin(), given.end());
  }
  return in_force;
}

// --- Timing -----------------------------------------------------------------------------

OutputTiming::OutputTiming(const OutputRequest& r, double period)
    : frequency_(r.frequency), n_interval_(r.number_interval.value_or(0)), time_marks_(r.time_marks),
      period_(period), tol_(1e-9 * period) {}

bool OutputTiming::would_be_due(int increment, double t, bool last) const {
  if (n_interval_ > 0) return last || (next_ <= n_interval_ && t >= mark(next_) - tol_);
  if (frequency_ <= 0) return false;
  return last || increment % frequency_ == 0;
}

bool OutputTiming::due(int increment, double t, bool last) {
  const bool is_due = would_be_due(increment, t, last);
  while (n_interval_ > 0 && next_ <= n_interval_ && t >= mark(next_) - tol_) ++next_;
  return is_due;
}

std::optional<double> OutputTiming::next_mark(double t) const {
  if (!time_marks_ || n_interval_ <= 0) return std::nullopt;
  for (int k = next_; k <= n_interval_; ++k)
    if (mark(k) > t + tol_) return mark(k);
  return std::nullopt;
}

bool OutputDue::any_field() const { return std::find(field.begin(), field.end(), true) != field.end(); }
bool OutputDue::any_print() const { return std::find(print.begin(), print.end(), true) != print.end(); }

// --- The step's output ------------------------------------------------------------------

StepOutput::StepOutput(const AnalysisModel& am, std::size_t step_index) {
  const model::Model& model = *am.model;
  const model::Step& step = model.steps.at(step_index);
  const double period = step.static_procedure ? step.static_procedure->time_period : 1.0;
  for (const OutputRequest& r : requests_in_force(model, step_index)) {
    const bool field = is_field(r.kind), print = is_print(r.kind);
    if (!field && !print) continue;  // history output is not written yet
    ActiveRequest a;
    a.request = r;
    const Domain d = domain_of(r.kind);
    if (!r.set.empty() && d != Domain::Contact) {
      const auto& sets = d == Domain::Node ? model.mesh.nsets : model.mesh.elsets;
      a.whole_model = false;
      if (auto it = sets.find(r.set); it != sets.end()) a.rows = it->second.rows;
      std::sort(a.rows.begin(), a.rows.end());
    }
    if (field) {
      if (r.preselect || r.all) {
        if (d == Domain::Node || d == Domain::Model) a.variables.insert(a.variables.end(), {"U", "RF"});
        if (r.all && (d == Domain::Node || d == Domain::Model)) a.variables.push_back("COORD");
        if (d == Domain::Element || d == Domain::Model) a.variables.insert(a.variables.end(), {"S", "E"});
        if ((d == Domain::Element || d == Domain::Model) && model_has_plasticity(am))
          a.variables.insert(a.variables.end(), {"PE", "PEEQ", "PEMAG"});
        // Abaqus's preselection holds CSTRESS and CDISP: inpact's CPRESS and COPEN.
        if (d == Domain::Contact || (d == Domain::Model && model_has_contact(model))) {
          a.variables.insert(a.variables.end(), {"CPRESS", "COPEN"});
          if (model_has_friction(model)) a.variables.insert(a.variables.end(), {"CSHEAR1", "CSHEAR2", "CSLIP1", "CSLIP2"});
        }
        if (r.all && d == Domain::Contact) a.variables.insert(a.variables.end(), {"CSTATUS", "CNAREA", "CFN"});
        if (r.all && d == Domain::Contact && model_has_friction(model)) a.variables.push_back("CFS");
      }
      for (const std::string& v : r.variables) {
        const std::string key = field_key(v, d);
        if (key.empty()) add_unique(not_computed_, v);
        else add_unique(a.variables, key);
        if (plastic_key(key) && reports_beams(am, a))
          add_unique(not_computed_, key + " of beam elements (their sections are elastic)");
        if (at_section_points(key) && reports_beams_without_section_points(am, a))
          add_unique(not_computed_, key + " of beams with a general section without *SECTION POINTS");
        // CSTRESS = CPRESS + CSHEAR1/2, CDISP = COPEN + CSLIP1/2 (with friction).
        const bool stress = v == "CSTRESS" || v == "CSTR", disp = v == "CDISP" || v == "CDIS";
        if ((stress || disp) && (d == Domain::Contact || d == Domain::Model) && model_has_friction(model))
          for (const char* t : stress ? std::array{"CSHEAR1", "CSHEAR2"} : std::array{"CSLIP1", "CSLIP2"})
            add_unique(a.variables, t);
      }
      // Abaqus's U and RF hold the rotations and moments too: UR and RM of the reference nodes.
      if (!model::rotating_nodes(model, am.dim).empty()) {
        const auto& v = a.variables;
        if (std::find(v.begin(), v.end(), "U") != v.end()) add_unique(a.variables, "UR");
        if (std::find(v.begin(), v.end(), "RF") != v.end()) add_unique(a.variables, "RM");
      }
      for (int number : r.section_points)
        if (!reports_section_point(am, a, number))
          add_unique(not_computed_, a.whole_model ? fmt::format("element output at section point {} (no shell or beam "
                                                                "section has it)", number)
                                                  : fmt::format("element output at section point {} of element set {} "
                                                                "(none of its shell or beam sections has it)",
                                                                number, r.set));
      field_timing_.emplace_back(r, period);
      field_.push_back(std::move(a));
    } else {
      for (const std::string& v : r.variables) {
        const auto columns = print_columns(v, d, am.dim);
        if (columns.empty()) add_unique(not_computed_, v);
        if (d == Domain::Element && !columns.empty() && plastic_key(v) && reports_beams(am, a))
          add_unique(not_computed_, v + " of beam elements (their sections are elastic)");
        if (d == Domain::Element && reports_beams_without_section_points(am, a) &&
            std::any_of(columns.begin(), columns.end(), beam_section_point_column))
          add_unique(not_computed_, v + " of beams with a general section without *SECTION POINTS");
        for (const auto& c : columns) add_unique(a.variables, c);
      }
      print_timing_.emplace_back(r, period);
      print_.push_back(std::move(a));
    }
  }
}

std::set<std::string> StepOutput::field_keys() const {
  std::set<std::string> keys;
  for (const auto& a : field_) keys.insert(a.variables.begin(), a.variables.end());
  return keys;
}

double StepOutput::limit_increment(double t, double dt) const {
  for (const auto* timings : {&field_timing_, &print_timing_})
    for (const OutputTiming& timing : *timings)
      if (auto m = timing.next_mark(t); m && t + dt > *m) dt = *m - t;
  return dt;
}

OutputDue StepOutput::due(int increment, double t, bool last) {
  OutputDue d;
  for (auto& timing : field_timing_) d.field.push_back(timing.due(increment, t, last));
  for (auto& timing : print_timing_) d.print.push_back(timing.due(increment, t, last));
  return d;
}

bool StepOutput::points_due(int increment, double t, bool last) const {
  for (std::size_t i = 0; i < field_.size(); ++i) {
    const auto& v = field_[i].variables;
    const bool element_key = std::any_of(v.begin(), v.end(), [](const std::string& k) { return point_key(k); });
    if (element_key && field_timing_[i].would_be_due(increment, t, last)) return true;
  }
  for (std::size_t i = 0; i < print_.size(); ++i)
    if (domain_of(print_[i].request.kind) == Domain::Element && !print_[i].variables.empty() &&
        print_timing_[i].would_be_due(increment, t, last))
      return true;
  return false;
}

double von_mises(std::span<const double, 6> s) {
  const double d1 = s[0] - s[1], d2 = s[1] - s[2], d3 = s[2] - s[0];
  return std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// --- Values -----------------------------------------------------------------------------

namespace {

/// Element point results: those the assembly kept at this state, or else computed on first use
/// for the elements a due request covers.
class PointCache {
 public:
  PointCache(const AnalysisModel& am, std::span<const double> u, bool nlgeom, std::span<const double> delta_t,
             const ElementPoints* kept, const MaterialStates* states)
      : am_(am), u_(u), delta_t_(delta_t), kept_(kept), states_(states), points_(am.model->mesh.elements.size()),
        have_(am.model->mesh.elements.size(), 0) {
    request_.stiffness = false;
    request_.internal_force = false;
    request_.point_output = true;
    request_.nlgeom = nlgeom;
  }

  /// An oriented section's points come in its material axes (Abaqus's output frame).
  std::span<const elements::PointResult> of(std::size_t el) {
    if (have_[el]) return points_[el];
    const ElementSetup& setup = am_.elements[el];
    const auto kept = kept_ ? kept_->of(el) : std::span<const elements::PointResult>();
    if (!kept.empty() && !setup.orientation) return kept;
    if (setup.rigid) return {};  // no points: an element following a rigid body is not integrated
    points_[el] = kept.empty() ? computed(el) : std::vector<elements::PointResult>(kept.begin(), kept.end());
    if (setup.orientation)
      for (elements::PointResult& p : points_[el]) elements::to_material_axes(setup.orientation->axes_at(p.coords), p);
    have_[el] = 1;
    return points_[el];
  }

  /// S and E at a beam's or a shell's section points, integration point after integration
  /// point, with each one's integration point, section point number and whether the section
  /// reports it by default (SectionPointChoice). A beam's come from its integration points'
  /// results (elements/beam_section_points.hpp), all defaults; a shell's are its kernel's points
  /// (shell_elements.hpp: every section point at each in-plane point), SNEG and SPOS the defaults.
  struct SectionPoints {
    std::vector<elements::PointResult> own;  ///< a beam's (a shell's stay in the cache)
    std::span<const elements::PointResult> results;
    std::vector<std::int32_t> ip, number;
    std::vector<char> is_default;
  };
  const SectionPoints& section_points_of(std::size_t el) {
    auto [it, inserted] = section_points_.try_emplace(el);
    SectionPoints& sp = it->second;
    if (!inserted) return sp;
    const auto ips = of(el);
    if (const elements::ShellProperties* shell = am_.elements[el].section.shell) {
      const std::size_t n = shell->zeta.size();
      const int last = static_cast<int>(n);
      for (std::size_t p = 0; p < ips.size(); ++p) {
        const int number = static_cast<int>(p % n) + 1;
        sp.ip.push_back(static_cast<std::int32_t>(p / n + 1));
        sp.number.push_back(number);
        sp.is_default.push_back(number == 1 || number == last);
      }
      sp.results = ips;
      return sp;
    }
    const elements::BeamProperties& beam = *am_.elements[el].section.beam;
    for (std::size_t p = 0; p < ips.size(); ++p) {
      elements::beam_section_point_results(beam, ips[p], sp.own);
      for (const elements::BeamSectionPoint& q : beam.output_points) {
        sp.ip.push_back(static_cast<std::int32_t>(p + 1));
        sp.number.push_back(q.number);
        sp.is_default.push_back(1);
      }
    }
    sp.results = sp.own;
    return sp;
  }

 private:
  std::vector<elements::PointResult> computed(std::size_t el) const {
    const ElementSetup& setup = am_.elements[el];
    std::vector<double> u_el, dt_el, temperature_el;
    std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;  // a beam's rotations too
    for (std::size_t a = 0, n = am_.element_rows(el, rows); a < n; ++a)
      for (int c = 0; c < am_.dim; ++c) u_el.push_back(u_[static_cast<std::size_t>(rows[a]) * am_.dim + c]);
    dt_el.resize(2 * am_.model->mesh.elements.nodes_of(el).size());
    dt_el.resize(am_.element_temperature_changes(el, delta_t_, dt_el));
    elements::ElementRequest request = request_;
    if (am_.reads_temperatures(el)) {
      temperature_el.resize(2 * am_.model->mesh.elements.nodes_of(el).size());
      temperature_el.resize(am_.element_temperatures(el, delta_t_, temperature_el));
      request.temperature = temperature_el;
    }
    // From the committed history: the output of a converged increment comes before its commit.
    std::vector<double> trial;
    const elements::ElementHistory history = states_ ? states_->output_history(el, trial) : elements::ElementHistory{};
    elements::ElementSystem sys;
    elements::compute_element(*setup.type, am_.coords(el), u_el, *setup.material, setup.section, request, dt_el,
                              history, sys);
    return std::move(sys.points);
  }

  const AnalysisModel& am_;
  std::span<const double> u_, delta_t_;
  const ElementPoints* kept_;
  const MaterialStates* states_;
  elements::ElementRequest request_;
  std::vector<std::vector<elements::PointResult>> points_;
  std::vector<char> have_;
  std::unordered_map<std::size_t, SectionPoints> section_points_;
};

/// The section points a request reports: Abaqus's default (a shell's SNEG and SPOS, a beam's
/// output points) unless its *ELEMENT OUTPUT lists them; several requests report the union.
struct SectionPointChoice {
  bool defaults = false;
  std::set<int> numbers;
  void add(const OutputRequest& r) {
    if (r.section_points.empty()) defaults = true;
    numbers.insert(r.section_points.begin(), r.section_points.end());
  }
  bool keeps(int number, bool is_default) const { return (defaults && is_default) || numbers.count(number) > 0; }
};

SectionPointChoice section_point_choice(const OutputRequest& r) {
  SectionPointChoice c;
  c.add(r);
  return c;
}

/// Where a field key is written in this step: the union of the sets (and of the section points)
/// of every request that asks for it (not only the due ones), so that its locations are the same
/// in every frame.
struct KeyRegion {
  bool whole = false;
  std::vector<std::int32_t> rows;
  std::string region;
  SectionPointChoice section_points;
};

KeyRegion key_region(const StepOutput& output, const std::string& key) {
  KeyRegion k;
  std::set<std::int32_t> rows;
  std::vector<std::string> names;
  for (const ActiveRequest& a : output.field_requests()) {
    if (std::find(a.variables.begin(), a.variables.end(), key) == a.variables.end()) continue;
    // A set of the other domain (an ELSET on a model-wide request) does not restrict.
    const bool same_domain = nodal_key(key) ? domain_of(a.request.kind) == Domain::Node
                                            : domain_of(a.request.kind) == Domain::Element;
    if (a.whole_model || !same_domain) k.whole = true;
    k.section_points.add(a.request);
    rows.insert(a.rows.begin(), a.rows.end());
    if (!a.whole_model && same_domain) add_unique(names, a.request.set);
  }
  if (!k.whole) {
    k.rows.assign(rows.begin(), rows.end());
    for (const auto& n : names) k.region += (k.region.empty() ? "" : ",") + n;
  }
  return k;
}

bool key_due(const StepOutput& output, const OutputDue& due, const std::string& key) {
  const auto& reqs = output.field_requests();
  for (std::size_t i = 0; i < reqs.size(); ++i)
    if (due.field[i] && std::find(reqs[i].variables.begin(), reqs[i].variables.end(), key) != reqs[i].variables.end())
      return true;
  return false;
}

/// A nodal value: U, RF or COORD (current coordinates under NLGEOM, original otherwise, as
/// Abaqus's COORD), component c.
enum class NodalKey : std::uint8_t { U, RF, Coord, UR, RM };

/// UR, RM: component c of rotation_labels() (c = 0 is UR3 in 2D).
double rotation_value(const AnalysisModel& am, NodalKey key, std::size_t row, int c, std::span<const double> u,
                      std::span<const double> rf) {
  const std::int64_t d = am.dof_index(static_cast<std::int32_t>(row), am.dim == 3 ? 4 + c : 6);
  if (d < 0) return 0.0;  // a node without rotations
  return key == NodalKey::UR ? u[d] : rf[d];
}

double nodal_value(const AnalysisModel& am, NodalKey key, std::size_t row, int c, std::span<const double> u,
                   std::span<const double> rf, bool nlgeom) {
  if (key == NodalKey::UR || key == NodalKey::RM) return rotation_value(am, key, row, c, u, rf);
  const std::size_t dof = row * am.dim + c;
  if (key == NodalKey::U) return u[dof];
  if (key == NodalKey::RF) {
    // A transformed node's reactions are its local node's (its own DOFs are eliminated into
    // them): turned back into the global axes, Σ_k (e_k)_c RF_local,k.
    const std::int32_t local = am.local_node_of.empty() ? -1 : am.local_node_of[row];
    std::array<std::array<double, 3>, 3> e;
    if (local < 0 || !am.local_axes(static_cast<std::int32_t>(row), e)) return rf[dof];
    double v = 0.0;
    for (int k = 0; k < 3; ++k) v += e[k][c] * rf[static_cast<std::size_t>(local) * 3 + static_cast<std::size_t>(k)];
    return v;
  }
  return am.model->mesh.nodes.coords[row][c] + (nlgeom ? u[dof] : 0.0);
}

/// A printed U or RF component: in the node's *TRANSFORM axes unless `global` (or it has none),
/// e_c · v.
double printed_nodal_value(const AnalysisModel& am, NodalKey key, std::size_t row, int c, std::span<const double> u,
                           std::span<const double> rf, bool global) {
  std::array<std::array<double, 3>, 3> e;
  if (global || (key != NodalKey::U && key != NodalKey::RF) || !am.local_axes(static_cast<std::int32_t>(row), e))
    return nodal_value(am, key, row, c, u, rf, false);
  double v = 0.0;
  for (int k = 0; k < 3; ++k) v += e[c][k] * nodal_value(am, key, row, k, u, rf, false);
  return v;
}

/// UR and RM are written at the nodes with rotations only (the rigid bodies' reference nodes).
FieldData rotation_field(const AnalysisModel& am, const std::string& key, const KeyRegion& where,
                         std::span<const double> u, std::span<const double> rf) {
  FieldData f;
  f.key = key;
  f.position = Position::Nodal;
  f.component_labels = rotation_labels(key, am.dim);
  f.region = where.region;
  const NodalKey k = key == "UR" ? NodalKey::UR : NodalKey::RM;
  const int n_comp = static_cast<int>(f.component_labels.size());
  for (const model::RotatingNode& r : model::rotating_nodes(*am.model, am.dim)) {
    if (!where.whole && !std::binary_search(where.rows.begin(), where.rows.end(), r.ref_node)) continue;
    f.nodes.push_back(r.ref_node);
    for (int c = 0; c < n_comp; ++c) f.values.push_back(rotation_value(am, k, static_cast<std::size_t>(r.ref_node), c, u, rf));
  }
  return f;
}

FieldData nodal_field(const AnalysisModel& am, const std::string& key, const KeyRegion& where,
                      std::span<const double> u, std::span<const double> rf, bool nlgeom) {
  if (rotation_key(key)) return rotation_field(am, key, where, u, rf);
  FieldData f;
  f.key = key;
  f.position = Position::Nodal;
  f.component_labels = vector_labels(key, am.dim);
  f.region = where.region;
  const NodalKey k = key == "U" ? NodalKey::U : key == "RF" ? NodalKey::RF : NodalKey::Coord;
  f.values.reserve((where.whole ? am.n_nodes() : where.rows.size()) * static_cast<std::size_t>(am.dim));
  auto add = [&](std::size_t row) {
    for (int c = 0; c < am.dim; ++c) f.values.push_back(nodal_value(am, k, row, c, u, rf, nlgeom));
  };
  if (where.whole) {
    f.nodes.resize(am.n_nodes());
    for (std::size_t i = 0; i < am.n_nodes(); ++i) {
      f.nodes[i] = static_cast<std::int64_t>(i);
      add(i);
    }
  } else {
    for (std::int32_t row : where.rows) {
      f.nodes.push_back(row);
      add(static_cast<std::size_t>(row));
    }
  }
  return f;
}

/// PEMAG: the plastic strain magnitude √(2/3 εᵖ:εᵖ) (engineering shears halved).
double plastic_magnitude(const elements::PointResult& p) {
  const auto& e = p.plastic_strain;
  const double dot = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + 0.5 * (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]);
  return std::sqrt(2.0 / 3.0 * dot);
}

FieldData element_field(const AnalysisModel& am, const std::string& key, const KeyRegion& where, PointCache& cache) {
  const auto& elements = am.model->mesh.elements;
  const bool with_instance = am.model->instances.size() > 1;
  const bool scalar = key == "PEEQ" || key == "PEMAG" || (key == "SF" && !model_has_section_vectors(am));
  const bool section = key == "SF" || key == "SM";  // PointResult::section, SM from slot 3
  const std::size_t n_comp = scalar ? 1 : section ? 3 : am.dim == 3 ? 6 : 4;  // 2D keeps 11 22 33 12 (Voigt slots 0..3)
  FieldData f;
  f.key = key;
  f.position = Position::IntegrationPoint;
  f.component_labels = section ? vector_labels(key, static_cast<int>(n_comp))
                       : scalar ? std::vector<std::string>{key}
                                : tensor_labels(key, am.dim);
  f.region = where.region;
  const bool stress = key == "S";
  // The locations of every element first, so that the arrays are sized once (a frame of a few
  // thousand elements otherwise regrows them a dozen times). A beam's S and E are at its section
  // points, its SF and SM at its integration points, and it has no plastic strain; a shell's SF
  // and SM are at its in-plane points, everything else at its section points.
  struct Location {
    std::size_t el;
    const elements::PointResult* point;
    std::int32_t ip, section_point;
  };
  std::vector<Location> at;
  bool with_section_points = false;
  auto gather = [&](std::size_t el) {
    const ElementSetup& setup = am.elements[el];
    const bool beam = setup.section.beam != nullptr, shell = setup.section.shell != nullptr;
    if (beam && !section && !at_section_points(key)) return;
    if ((beam || shell) && !section) {
      const auto& sp = cache.section_points_of(el);
      for (std::size_t p = 0; p < sp.results.size(); ++p)
        if (where.section_points.keeps(sp.number[p], sp.is_default[p]))
          at.push_back({el, &sp.results[p], sp.ip[p], sp.number[p]});
      with_section_points = true;
      return;
    }
    const auto points = cache.of(el);
    const std::size_t stride = shell ? setup.section.shell->zeta.size() : 1;  // one per in-plane point
    for (std::size_t p = 0; p < points.size(); p += stride)
      at.push_back({el, &points[p], static_cast<std::int32_t>(p / stride + 1), 0});
  };
  if (where.whole)
    for (std::size_t el = 0; el < elements.size(); ++el) gather(el);
  else
    for (std::int32_t el : where.rows) gather(static_cast<std::size_t>(el));
  const std::size_t n_points = at.size();
  f.elements.resize(n_points);
  f.ip.resize(n_points);
  if (with_section_points) f.section_point.resize(n_points, 0);
  if (with_instance) f.instance.resize(n_points);
  f.values.resize(n_points * n_comp);
  for (std::size_t i = 0; i < n_points; ++i) {
    const Location& l = at[i];
    const elements::PointResult& p = *l.point;
    f.elements[i] = elements.labels[l.el];
    f.ip[i] = l.ip;
    if (with_section_points) f.section_point[i] = l.section_point;
    if (with_instance) f.instance[i] = elements.instance[l.el];
    const auto out = f.values.begin() + static_cast<std::ptrdiff_t>(i * n_comp);
    if (section) {
      std::copy_n(p.section.begin() + (key == "SM" ? 3 : 0), n_comp, out);
      continue;
    }
    if (scalar) {
      *out = key == "PEEQ" ? p.peeq : plastic_magnitude(p);
      continue;
    }
    const auto& v = stress ? p.stress : key == "PE" ? p.plastic_strain : p.strain;
    std::copy_n(v.begin(), n_comp, out);
  }
  return f;
}

/// A printed column: its source and component (0-based).
struct Column {
  enum class Source : std::uint8_t { U, RF, Coord, UR, RM, S, E, Mises, PE, Peeq, Pemag, SF, SM } source;
  int component = 0;
};

Column parse_column(const std::string& name) {
  using S = Column::Source;
  if (name == "MISES") return {S::Mises, 0};
  if (name == "PEEQ") return {S::Peeq, 0};
  if (name == "PEMAG") return {S::Pemag, 0};
  if (name.rfind("SF", 0) == 0) return {S::SF, name[2] - '1'};
  if (name.rfind("SM", 0) == 0) return {S::SM, name[2] - '1'};
  if (name.rfind("COORD", 0) == 0) return {S::Coord, name[5] - '1'};
  // UR3 alone in 2D is component 0 there: node_table maps it (rotation_labels()).
  if (name.rfind("UR", 0) == 0) return {S::UR, name[2] - '1'};
  if (name.rfind("RM", 0) == 0) return {S::RM, name[2] - '1'};
  if (name.rfind("RF", 0) == 0) return {S::RF, name[2] - '1'};
  if (name[0] == 'U') return {S::U, name[1] - '1'};
  // Tensor 11 22 33 12 13 23 → Abaqus-ordered slots 0..5.
  static const std::map<std::string, int> slot = {{"11", 0}, {"22", 1}, {"33", 2}, {"12", 3}, {"13", 4}, {"23", 5}};
  if (name.rfind("PE", 0) == 0) return {S::PE, slot.at(name.substr(2))};
  if (name.rfind("LE", 0) == 0) return {S::E, slot.at(name.substr(2))};
  return {name[0] == 'S' ? S::S : S::E, slot.at(name.substr(1))};
}

PrintTable node_table(const AnalysisModel& am, const ActiveRequest& a, std::span<const double> u,
                      std::span<const double> rf, bool nlgeom) {
  PrintTable t;
  t.domain = PrintTable::Domain::Node;
  t.set = a.request.set;
  t.columns = a.variables;
  t.summary = a.request.summary;
  t.totals = a.request.totals;
  t.totals_only = a.request.totals_only;
  std::vector<Column> cols;
  for (const auto& c : t.columns) cols.push_back(parse_column(c));
  auto add = [&](std::size_t row) {
    t.labels.push_back(am.model->mesh.nodes.labels[row]);
    for (const Column& c : cols) {
      const NodalKey key = c.source == Column::Source::U    ? NodalKey::U
                           : c.source == Column::Source::RF ? NodalKey::RF
                           : c.source == Column::Source::UR ? NodalKey::UR
                           : c.source == Column::Source::RM ? NodalKey::RM
                                                            : NodalKey::Coord;
      const bool rotation = key == NodalKey::UR || key == NodalKey::RM;
      const int component = rotation && am.dim == 2 ? 0 : c.component;  // 2D: UR3 is the one rotation
      t.values.push_back(key == NodalKey::Coord || rotation ? nodal_value(am, key, row, component, u, rf, nlgeom)
                                                            : printed_nodal_value(am, key, row, component, u, rf,
                                                                                  a.request.global));
    }
  };
  if (a.whole_model)
    for (std::size_t row = 0; row < am.n_nodes(); ++row) add(row);
  else
    for (std::int32_t row : a.rows) add(static_cast<std::size_t>(row));
  return t;
}

double point_value(const elements::PointResult& p, const Column& c) {
  switch (c.source) {
    case Column::Source::S: return p.stress[c.component];
    case Column::Source::E: return p.strain[c.component];
    case Column::Source::Mises: return von_mises(p.stress);
    case Column::Source::PE: return p.plastic_strain[c.component];
    case Column::Source::Peeq: return p.peeq;
    case Column::Source::Pemag: return plastic_magnitude(p);
    case Column::Source::SF: return p.section[c.component];
    case Column::Source::SM: return p.section[3 + c.component];
    case Column::Source::Coord: return p.coords[c.component];
    default: return 0.0;
  }
}

/// POSITION=CENTROIDAL: the volume-weighted average of the integration points (exact for
/// one-point elements and for fields linear over the element).
elements::PointResult centroid_of(std::span<const elements::PointResult> points) {
  elements::PointResult c{};
  double total = 0.0;
  for (const auto& p : points) total += p.volume;
  for (const auto& p : points) {
    const double w = total > 0.0 ? p.volume / total : 1.0 / static_cast<double>(points.size());
    for (int i = 0; i < 6; ++i) {
      c.stress[i] += w * p.stress[i];
      c.strain[i] += w * p.strain[i];
      c.plastic_strain[i] += w * p.plastic_strain[i];
    }
    c.peeq += w * p.peeq;
    for (int i = 0; i < 6; ++i) c.section[i] += w * p.section[i];
    for (int i = 0; i < 3; ++i) c.coords[i] += w * p.coords[i];
  }
  c.volume = total;
  return c;
}

std::set<std::int32_t> request_pairs(const AnalysisModel& am, const OutputRequest& r);  // below

/// *CONTACT PRINT: one table per pair the request selects, a row per slave node.
std::vector<PrintTable> contact_tables(const AnalysisModel& am, const ActiveRequest& a, const ContactResults& contact,
                                       const std::vector<std::string>& pair_names) {
  const auto rows = request_pairs(am, a.request);
  std::map<std::int32_t, PrintTable> by_pair;
  for (const ContactNodeResult& c : contact) {
    if (!rows.count(c.pair)) continue;
    PrintTable& t = by_pair[c.pair];
    if (t.columns.empty()) {
      t.domain = PrintTable::Domain::Contact;
      t.set = pair_names[static_cast<std::size_t>(c.pair)];
      t.columns = a.variables;
      t.summary = a.request.summary;
      t.totals = a.request.totals;
      t.totals_only = a.request.totals_only;
    }
    t.labels.push_back(am.model->mesh.nodes.labels[static_cast<std::size_t>(c.node)]);
    for (const std::string& col : t.columns) {
      double v = 0.0;
      if (col == "CPRESS") v = c.cpress;
      else if (col == "COPEN") v = c.copen;
      else if (col == "CSTATUS") v = static_cast<double>(c.cstatus);
      else if (col == "CNAREA") v = c.cnarea;
      else if (col == "CSHEAR1") v = c.cshear[0];
      else if (col == "CSHEAR2") v = c.cshear[1];
      else if (col == "CSLIP1") v = c.cslip[0];
      else if (col == "CSLIP2") v = c.cslip[1];
      else if (col.rfind("CFN", 0) == 0) v = c.cfn[static_cast<std::size_t>(col[3] - '1')];
      t.values.push_back(v);
    }
  }
  std::vector<PrintTable> out;
  for (auto& [row, t] : by_pair) out.push_back(std::move(t));
  return out;
}

bool beam_section_point_column(const std::string& variable) {
  const Column c = parse_column(variable);
  const bool strain_or_stress = c.source == Column::Source::S || c.source == Column::Source::E;
  return c.source == Column::Source::Mises || (strain_or_stress && (c.component == 0 || c.component == 3));
}

/// What the rows of an element table are: integration points, or a beam's or shell's section points.
enum class Rows : std::uint8_t { IntegrationPoints, SectionPoints };

/// The columns of a table of this element type: trusses and springs have the 11 component of
/// a tensor only (Abaqus prints S11 and E11 for them) and SF1; beams S11, S12, E11, E12 and
/// MISES at their section points, and their section forces and moments at their integration
/// points, in two tables; shells the in-plane components 11, 22, 12 of S, E and PE (plane
/// stress), MISES, PEEQ and PEMAG at their section points, their section forces and moments at
/// their in-plane points; continua every column but SF2, SF3 and SM.
std::vector<std::string> columns_for(const model::ElementTypeInfo& type, const std::vector<std::string>& variables,
                                     Rows rows) {
  std::vector<std::string> out;
  for (const std::string& v : variables) {
    const Column c = parse_column(v);
    const bool tensor = c.source == Column::Source::S || c.source == Column::Source::E || c.source == Column::Source::PE;
    const bool section = c.source == Column::Source::SF || c.source == Column::Source::SM;
    const bool axial = c.source == Column::Source::SF && c.component == 0;
    const bool in_plane = c.component == 0 || c.component == 1 || c.component == 3;
    if (model::is_beam(type)) {
      if (rows == Rows::SectionPoints ? beam_section_point_column(v) : section || c.source == Column::Source::Coord)
        out.push_back(v);
      continue;
    }
    const bool plastic_scalar = c.source == Column::Source::Peeq || c.source == Column::Source::Pemag;
    const bool shell_section_point = c.source == Column::Source::Mises || plastic_scalar || (tensor && in_plane);
    const bool keep = model::is_shell(type) ? (rows == Rows::SectionPoints
                                                   ? shell_section_point
                                                   : section || c.source == Column::Source::Coord)
                      : rows == Rows::SectionPoints ? false
                      : model::is_continuum(type)   ? !section || axial
                                                    : (!tensor || c.component == 0) && (!section || axial);
    if (keep) out.push_back(v);
  }
  return out;
}

/// A beam's or shell's section-point results averaged over its integration points, one per
/// section point the request reports (POSITION=CENTROIDAL), with the section point numbers.
std::pair<std::vector<elements::PointResult>, std::vector<std::int32_t>> section_point_centroids(
    const PointCache::SectionPoints& sp, const SectionPointChoice& choice) {
  std::map<std::int32_t, std::vector<elements::PointResult>> by_number;
  for (std::size_t k = 0; k < sp.results.size(); ++k)
    if (choice.keeps(sp.number[k], sp.is_default[k])) by_number[sp.number[k]].push_back(sp.results[k]);
  std::pair<std::vector<elements::PointResult>, std::vector<std::int32_t>> out;
  for (const auto& [number, results] : by_number) {
    out.first.push_back(centroid_of(results));
    out.second.push_back(number);
  }
  return out;
}

/// One table per element type (a beam's section points and integration points apart), in the
/// order the types first appear in the set (Abaqus prints element output by element type).
std::vector<PrintTable> element_tables(const AnalysisModel& am, const ActiveRequest& a, PointCache& cache) {
  const auto& elements = am.model->mesh.elements;
  const SectionPointChoice choice = section_point_choice(a.request);
  const bool centroid = a.request.position == OutputRequest::Position::Centroidal;
  std::vector<std::vector<Column>> table_cols;
  std::vector<PrintTable> tables;
  std::map<std::pair<std::uint8_t, Rows>, std::size_t> table_of;
  auto table = [&](std::uint8_t type, Rows rows) -> std::size_t {
    auto [it, inserted] = table_of.emplace(std::pair{type, rows}, tables.size());
    if (!inserted) return it->second;
    PrintTable t;
    t.domain = PrintTable::Domain::Element;
    t.set = a.request.set;
    t.element_type = std::string(model::element_type(type).name);
    t.centroid = centroid;
    t.at_section_points = rows == Rows::SectionPoints;
    t.columns = columns_for(model::element_type(type), a.variables, rows);
    t.summary = a.request.summary;
    t.totals = a.request.totals;
    t.totals_only = a.request.totals_only;
    std::vector<Column> cols;
    for (const auto& c : t.columns) cols.push_back(parse_column(c));
    table_cols.push_back(std::move(cols));
    tables.push_back(std::move(t));
    return it->second;
  };
  auto add_rows = [&](std::size_t el, Rows rows) {
    const std::uint8_t type = elements.type[el];
    if (columns_for(model::element_type(type), a.variables, rows).empty()) return;
    const std::size_t k = table(type, rows);
    PrintTable& t = tables[k];
    const std::vector<Column>& cols = table_cols[k];
    auto row = [&](const elements::PointResult& p, std::int32_t ip, std::int32_t section_point) {
      t.labels.push_back(elements.labels[el]);
      if (!centroid) t.ip.push_back(ip);
      if (rows == Rows::SectionPoints) t.section_point.push_back(section_point);
      for (const Column& c : cols) t.values.push_back(point_value(p, c));
    };
    if (rows == Rows::SectionPoints) {
      const auto& sp = cache.section_points_of(el);
      if (centroid) {
        const auto [results, numbers] = section_point_centroids(sp, choice);
        for (std::size_t q = 0; q < results.size(); ++q) row(results[q], 0, numbers[q]);
      } else {
        for (std::size_t q = 0; q < sp.results.size(); ++q)
          if (choice.keeps(sp.number[q], sp.is_default[q])) row(sp.results[q], sp.ip[q], sp.number[q]);
      }
      return;
    }
    const auto& points = cache.of(el);
    const elements::ShellProperties* shell = am.elements[el].section.shell;
    const std::size_t stride = shell ? shell->zeta.size() : 1;  // a shell's: one per in-plane point
    if (centroid) {
      row(centroid_of(points), 0, 0);
      return;
    }
    for (std::size_t p = 0; p < points.size(); p += stride) {
      if (stride == 1) {
        row(points[p], static_cast<std::int32_t>(p + 1), 0);
        continue;
      }
      elements::PointResult mid = points[p];  // a shell's in-plane point: halfway between SNEG and SPOS
      for (int c = 0; c < 3; ++c) mid.coords[c] = 0.5 * (points[p].coords[c] + points[p + stride - 1].coords[c]);
      row(mid, static_cast<std::int32_t>(p / stride + 1), 0);
    }
  };
  auto add = [&](std::size_t el) {
    if (am.elements[el].rigid) return;  // an element following a rigid body has no points
    const elements::BeamProperties* beam = am.elements[el].section.beam;
    if ((beam && !beam->output_points.empty()) || am.elements[el].section.shell) add_rows(el, Rows::SectionPoints);
    add_rows(el, Rows::IntegrationPoints);
  };
  if (a.whole_model)
    for (std::size_t el = 0; el < elements.size(); ++el) add(el);
  else
    for (std::int32_t el : a.rows) add(static_cast<std::size_t>(el));
  return tables;
}

}  // namespace

namespace {

/// Rows of the contact pair table (model pairs, then each step's) a contact request covers.
std::set<std::int32_t> request_pairs(const AnalysisModel& am, const OutputRequest& r) {
  std::set<std::int32_t> rows;
  std::int32_t row = 0;
  for (const contact::ContactInteraction& ci : am.contact->rows) {
    const model::ContactPair& p = ci.pair;
    const bool slave_ok = r.surface.empty() || domain_of(r.kind) != Domain::Contact || r.surface == p.slave;
    const bool master_ok = r.master.empty() || domain_of(r.kind) != Domain::Contact || r.master == p.master;
    if (slave_ok && master_ok) rows.insert(row);
    ++row;
  }
  return rows;
}

/// A contact field: one location per slave node per pair of the requests asking for `key`
/// (the same locations in every frame of the step).
FieldData contact_field(const AnalysisModel& am, const StepOutput& output, const std::string& key,
                        const ContactResults& contact) {
  std::set<std::int32_t> pairs;
  for (const ActiveRequest& a : output.field_requests())
    if (std::find(a.variables.begin(), a.variables.end(), key) != a.variables.end()) {
      const auto rows = request_pairs(am, a.request);
      pairs.insert(rows.begin(), rows.end());
    }
  FieldData f;
  f.key = key;
  f.position = Position::Nodal;
  f.component_labels = key == "CFN"   ? std::vector<std::string>{"CFN1", "CFN2", "CFN3"}
                       : key == "CFS" ? std::vector<std::string>{"CFS1", "CFS2", "CFS3"}
                                      : std::vector<std::string>{key};
  for (const ContactNodeResult& c : contact) {
    if (!pairs.count(c.pair)) continue;
    f.nodes.push_back(c.node);
    f.pair.push_back(c.pair);
    if (key == "CPRESS") f.values.push_back(c.cpress);
    else if (key == "COPEN") f.values.push_back(c.copen);
    else if (key == "CSTATUS") f.values.push_back(static_cast<double>(c.cstatus));
    else if (key == "CNAREA") f.values.push_back(c.cnarea);
    else if (key == "CSHEAR1") f.values.push_back(c.cshear[0]);
    else if (key == "CSHEAR2") f.values.push_back(c.cshear[1]);
    else if (key == "CSLIP1") f.values.push_back(c.cslip[0]);
    else if (key == "CSLIP2") f.values.push_back(c.cslip[1]);
    else if (key == "CFS") f.values.insert(f.values.end(), c.cfs.begin(), c.cfs.end());
    else f.values.insert(f.values.end(), c.cfn.begin(), c.cfn.end());
  }
  return f;
}

}  // namespace

OutputValues compute_output(const AnalysisModel& am, const StepOutput& output, const OutputDue& due,
                            std::span<const double> u, std::span<const double> rf, bool nlgeom,
                            std::span<const double> delta_t, const ContactResults* contact,
                            const ElementPoints* points, const MaterialStates* states) {
  OutputValues out;
  if (contact)
    for (const std::string key : kContactKeys)
      if (key_due(output, due, key)) out.fields.push_back(contact_field(am, output, key, *contact));
  PointCache cache(am, u, nlgeom, delta_t, points, states);
  for (const std::string key : kFieldKeys) {
    if (!key_due(output, due, key)) continue;
    const KeyRegion where = key_region(output, key);
    if (nodal_key(key)) out.fields.push_back(nodal_field(am, key, where, u, rf, nlgeom));
    else out.fields.push_back(element_field(am, key, where, cache));
  }
  const auto& prints = output.print_requests();
  std::vector<std::string> pair_names;
  for (const auto& row : am.contact->rows) pair_names.push_back(row.name());
  for (std::size_t i = 0; i < prints.size(); ++i) {
    const ActiveRequest& a = prints[i];
    if (!due.print[i] || a.variables.empty()) continue;
    const Domain d = domain_of(a.request.kind);
    if (d == Domain::Node) {
      out.tables.push_back(node_table(am, a, u, rf, nlgeom));
    } else if (d == Domain::Element) {
      for (auto& t : element_tables(am, a, cache)) out.tables.push_back(std::move(t));
    } else if (d == Domain::Contact && contact) {
      for (auto& t : contact_tables(am, a, *contact, pair_names)) out.tables.push_back(std::move(t));
    }
  }
  return out;
}

}  // namespace inpact::solver
