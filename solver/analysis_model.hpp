#pragma once
/// What the analysis needs per element, resolved once from the model database: its type,
/// material law and section data, and the model's number of DOFs per node.
#include <array>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "contact/interaction_table.hpp"
#include "contact/resolved_interaction.hpp"
#include "contact/tie.hpp"

#include "elements/element_kernel.hpp"
#include "model/model.hpp"

namespace inpact::solver {

namespace elements {
class Material;
class MaterialOrientation;
struct SpringBehavior;
struct BeamProperties;
struct ShellProperties;
}

struct ElementSetup {
  const model::ElementTypeInfo* type = nullptr;
  /// The law at the element's points (material.hpp), one per section and element family,
  /// owned by AnalysisModel::materials.
  const elements::Material* material = nullptr;
  elements::SectionData section;
  double density = 0.0;
  /// The material axes of an oriented *SOLID SECTION (owned by AnalysisModel::orientations),
  /// into which its S, E and PE are reported; null: the global axes.
  const elements::MaterialOrientation* orientation = nullptr;
  /// Its nodes follow a rigid body: a rigid element (R3D4, ...) or any element of a *RIGID BODY
  /// ELSET. Not integrated (a rigid motion strains nothing) and without points; its body loads
  /// still reach its nodes, and through them the body.
  bool rigid = false;
};

struct AnalysisModel {
  // Not copyable: SectionData's spans view shell_nodal_thickness, which a copy would not move.
  AnalysisModel() = default;
  AnalysisModel(const AnalysisModel&) = delete;
  AnalysisModel& operator=(const AnalysisModel&) = delete;
  AnalysisModel(AnalysisModel&&) = default;
  AnalysisModel& operator=(AnalysisModel&&) = default;
  const model::Model* model = nullptr;
  int dim = 3;  ///< DOFs per node: 3 for solids and T3D*, 2 for plane, axisymmetric and T2D2 models (springs take it)
  bool axisymmetric = false;
  std::vector<ElementSetup> elements;  ///< per element row
  std::vector<std::shared_ptr<const elements::Material>> materials;  ///< what ElementSetup::material points to
  std::vector<std::shared_ptr<const elements::SpringBehavior>> springs;  ///< what SectionData::spring points to
  std::vector<std::shared_ptr<const elements::BeamProperties>> beams;     ///< what SectionData::beam points to
  std::vector<std::shared_ptr<const elements::ShellProperties>> shells;   ///< what SectionData::shell points to
  /// What SectionData::nodal_thickness views, one array per shell with *NODAL THICKNESS (a deque:
  /// growing it keeps the earlier arrays in place).
  std::deque<std::array<double, 8>> shell_nodal_thickness;
  /// What SectionData::shell_directors views: one array per shell whose directors are averaged.
  std::deque<std::array<elements::Vec3, 8>> shell_directors;
  std::vector<std::shared_ptr<const elements::MaterialOrientation>> orientations;  ///< ElementSetup::orientation's
  double size = 0.0;  ///< diagonal of the nodes' bounding box: the model's length scale
  /// The contact interactions: pairs and what general contact expands to (pair rows).
  std::shared_ptr<const contact::InteractionTable> contact;
  /// Per step (index), the rows in force as they are enforced: what `check` prints and the
  /// analysis uses (contact/resolved_interaction.hpp).
  std::vector<std::vector<contact::ResolvedInteraction>> interactions;
  /// The *TIE constraints resolved on the reference geometry (contact/tie.hpp): the DOF map
  /// eliminates each tied slave node's translations into its master nodes.
  std::vector<contact::ResolvedTie> ties;
  /// Warnings about the model as given (e.g. volumetric locking), for `check` and `run`.
  std::vector<std::string> warnings;

  /// Per node row: its rotation node (a rigid body's or coupling's reference node, a beam or shell node;
  /// model/reference_nodes.hpp), else −1. Only these nodes have rotations.
  std::vector<std::int32_t> rotation_node_of;
  /// Per node row: the local node that holds its *TRANSFORM components (model/transform.hpp),
  /// else −1; and the index of its *TRANSFORM, else −1 (printed output turns into its axes).
  std::vector<std::int32_t> local_node_of, transform_of;
  /// Per node row: T_initial (*INITIAL CONDITIONS, TYPE=TEMPERATURE; 0 where none is given).
  std::vector<double> initial_temperature;
  /// Per node row: the initial gradient through the thickness of the shells there (the third
  /// field of *INITIAL CONDITIONS, TYPE=TEMPERATURE); empty when none is given (all 0).
  std::vector<double> initial_temperature_gradient;

  std::size_t n_nodes() const { return model->mesh.nodes.size(); }
  std::size_t n_dof() const { return n_nodes() * static_cast<std::size_t>(dim); }
  /// The global DOF of a node's Abaqus DOF `dof` (1-based): a translation 1..dim, or a rotation
  /// of a rigid body's reference node (4–6 in 3D, 6 in 2D: the rotation node's translations);
  /// −1 when the node has no such DOF.
  /// A node of a *TRANSFORM that the deck refers to: its translations are its local node's.
  std::int64_t dof_index(std::int32_t node, int dof) const;
  /// The local axes e_1..e_3 (rows) of node `node`'s *TRANSFORM at its position; false when it
  /// has none.
  bool local_axes(std::int32_t node, std::array<std::array<double, 3>, 3>& e) const;
  /// The node rows element e's system lives on: its nodes, and for a beam or shell its nodes'
  /// rotation nodes after them (elements/beam_elements.hpp, elements/shell_elements.hpp). Writes at most kMaxElementRows; returns the
  /// count.
  static constexpr std::size_t kMaxElementRows = 32;
  std::size_t element_rows(std::size_t e, std::span<std::int32_t> rows) const;
  /// The temperature T_initial + ΔT of a node (on a shell's reference surface), ΔT from
  /// `delta_t` (StepConditions::temperature_change; empty: no change).
  double temperature(std::int32_t node, std::span<const double> delta_t) const {
    const auto n = static_cast<std::size_t>(node);
    return initial_temperature[n] + (delta_t.empty() ? 0.0 : delta_t[n]);
  }
  /// Element e's temperatures, for temperature-dependent data (elements::ElementRequest::
  /// temperature): T at its nodes, and for a shell the gradient ∂T/∂n at them after them (the
  /// initial one plus its change in `delta_t`). Writes into `out` (room for twice the nodes) and
  /// returns the count.
  std::size_t element_temperatures(std::size_t e, std::span<const double> delta_t, std::span<double> out) const;
  /// Whether element e's laws read its temperatures (element_temperatures): its material's, or a
  /// COMPOSITE layer's.
  bool reads_temperatures(std::size_t e) const;
  /// Element e's temperature changes from the nodal `delta_t` (StepConditions::
  /// temperature_change: ΔT of every node, then, when the model has shell temperature
  /// gradients, the change of the gradient of every node): ΔT at its nodes, and for a shell the
  /// gradient's change at its nodes after them. Writes into `out` (room for twice the nodes) and
  /// returns the count; 0 when `delta_t` is empty.
  std::size_t element_temperature_changes(std::size_t e, std::span<const double> delta_t, std::span<double> out) const;
  /// Reference coordinates of element e's nodes.
  std::vector<elements::Vec3> coords(std::size_t e) const;
};

/// Resolves sections and materials per element; throws AnalysisError (citing the deck) when
/// the model cannot be analysed: 2D and 3D elements mixed, axisymmetric mixed with plane.
AnalysisModel build_analysis_model(const model::Model& model);

}  // namespace inpact::solver
