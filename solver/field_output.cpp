#include "field_output.hpp"

#include <algorithm>

#include "elements/element_kernel.hpp"

namespace inpact::solver {

namespace {

using Kind = model::OutputRequest::Kind;

/// Identifiers the solid mechanics core computes; PRESELECT is Abaqus's default set of them.
const std::set<std::string> kComputed = {"U", "RF", "S", "E"};
const std::set<std::string> kPreselect = {"U", "RF", "S", "E"};

bool is_field_request(Kind k) {
  return k == Kind::NodeField || k == Kind::ElementField || k == Kind::ContactField || k == Kind::ModelField;
}

FieldData nodal_field(const AnalysisModel& am, const std::string& key, std::span<const double> values) {
  FieldData f;
  f.key = key;
  f.position = Position::Nodal;
  for (int c = 1; c <= am.dim; ++c) f.component_labels.push_back(key + std::to_string(c));
  f.nodes.resize(am.n_nodes());
  for (std::size_t i = 0; i < am.n_nodes(); ++i) f.nodes[i] = static_cast<std::int64_t>(i);
  f.values.assign(values.begin(), values.end());
  return f;
}

/// Abaqus's components: 3D 11 22 33 12 13 23; plane and axisymmetric 11 22 33 12.
std::vector<std::string> tensor_labels(const std::string& key, int dim) {
  std::vector<std::string> l = {key + "11", key + "22", key + "33", key + "12"};
  if (dim == 3) l.insert(l.end(), {key + "13", key + "23"});
  return l;
}

}  // namespace

OutputSelection select_output(const model::Model& model, std::size_t step_index) {
  OutputSelection sel;
  for (std::size_t s = step_index + 1; s-- > 0;) {
    const auto& requests = model.steps[s].output;
    if (std::none_of(requests.begin(), requests.end(), [](const auto& r) { return is_field_request(r.kind); }))
      continue;
    int frequency = 0;
    for (const auto& r : requests) {
      if (!is_field_request(r.kind)) continue;
      frequency = frequency == 0 ? r.frequency : std::min(frequency, std::max(r.frequency, 1));
      if (r.preselect || r.all || r.variables.empty()) sel.fields.insert(kPreselect.begin(), kPreselect.end());
      for (const auto& v : r.variables) {
        if (kComputed.count(v)) sel.fields.insert(v);
        else if (std::find(sel.not_computed.begin(), sel.not_computed.end(), v) == sel.not_computed.end())
          sel.not_computed.push_back(v);
      }
    }
    sel.frequency = std::max(frequency, 1);
    return sel;
  }
  sel.fields = {"U", "RF", "S"};
  return sel;
}

std::vector<FieldData> compute_fields(const AnalysisModel& am, const OutputSelection& selection,
                                        std::span<const double> u, std::span<const double> rf, bool nlgeom,
                                        std::span<const double> delta_t) {
  std::vector<FieldData> out;
  if (selection.fields.count("U")) out.push_back(nodal_field(am, "U", u));
  if (selection.fields.count("RF")) out.push_back(nodal_field(am, "RF", rf));
  const bool want_s = selection.fields.count("S") > 0, want_e = selection.fields.count("E") > 0;
  if (!want_s && !want_e) return out;

  const auto& mesh = am.model->mesh;
  const std::size_t n_comp = am.dim == 3 ? 6 : 4;
  FieldData s, e;
  s.key = "S";
  e.key = "E";
  s.position = e.position = Position::IntegrationPoint;
  s.component_labels = tensor_labels("S", am.dim);
  e.component_labels = tensor_labels("E", am.dim);
  elements::ElementRequest request;
  request.stiffness = false;
  request.internal_force = false;
  request.point_output = true;
  request.nlgeom = nlgeom;
  std::vector<double> u_el, dt_el;
  for (std::size_t el = 0; el < mesh.elements.size(); ++el) {
    const ElementSetup& setup = am.elements[el];
    const auto nodes = mesh.elements.nodes_of(el);
    u_el.clear();
    dt_el.clear();
    for (std::int32_t node : nodes) {
      for (int c = 0; c < am.dim; ++c) u_el.push_back(u[static_cast<std::size_t>(node) * am.dim + c]);
      if (!delta_t.empty()) dt_el.push_back(delta_t[node]);
    }
    const auto sys = elements::compute_element(*setup.type, am.coords(el), u_el, setup.material, setup.section,
                                               request, dt_el);
    for (std::size_t p = 0; p < sys.points.size(); ++p) {
      for (FieldData* f : {&s, &e}) {
        f->elements.push_back(mesh.elements.labels[el]);
        f->ip.push_back(static_cast<std::int32_t>(p + 1));
      }
      const auto& pt = sys.points[p];
      // 2D keeps 11 22 33 12 (Voigt slots 0, 1, 2, 3).
      for (std::size_t c = 0; c < n_comp; ++c) {
        s.values.push_back(pt.stress[c]);
        e.values.push_back(pt.strain[c]);
      }
    }
  }
  if (want_s) out.push_back(std::move(s));
  if (want_e) out.push_back(std::move(e));
  return out;
}

}  // namespace inpact::solver
