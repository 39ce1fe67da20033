#pragma once
/// What the reader knows between keywords: the model being filled, where in the deck it is
/// (model, part, assembly, instance, step), and which parent keyword sub-options attach to.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace inpact::parser {

/// Where a keyword may appear (bit set).
enum Scope : unsigned {
  kModelScope = 1,     ///< model data outside parts and assembly (or a deck without parts)
  kPartScope = 2,      ///< between *PART and *END PART
  kAssemblyScope = 4,  ///< between *ASSEMBLY and *END ASSEMBLY
  kInstanceScope = 8,  ///< between *INSTANCE and *END INSTANCE
  kStepScope = 16,     ///< between *STEP and *END STEP (history data)
};
constexpr unsigned kMeshScopes = kModelScope | kPartScope | kAssemblyScope | kInstanceScope;
constexpr unsigned kModelDataScopes = kModelScope | kAssemblyScope;
constexpr unsigned kAnyScope = 31;

/// An element node given by label before the node was defined: resolved when the mesh closes.
struct PendingNode {
  std::size_t conn_index;
  std::int64_t label;
  std::int32_t instance;
  model::SourceLoc loc;
};

/// A mesh being filled (the model's own, or a part's) with its unresolved element nodes.
struct MeshBuild {
  model::Mesh mesh;
  std::vector<PendingNode> pending;
};

struct PartDef {
  std::string name;
  MeshBuild build;
  model::SourceLoc loc;
};

/// An open *INSTANCE: a copy of its part's mesh, to which an independent instance (as
/// Abaqus/CAE writes them) adds its own nodes, elements, sets and sections before *END INSTANCE.
struct OpenInstance {
  std::string name;  ///< as written
  std::string part;  ///< upper case
  PartDef def;
  std::array<double, 3> translation{0, 0, 0};
  bool has_rotation = false;
  std::array<double, 7> rotation{};  ///< point a, point b, angle in degrees
  model::SourceLoc loc;
  /// Rigid bodies and analytical surfaces defined inside the instance (an analytical rigid part,
  /// as Abaqus/CAE writes it) start at these indices: their node and element rows are the
  /// instance's own until *END INSTANCE moves them into the model's mesh.
  std::size_t first_rigid_body = 0, first_analytical_surface = 0;
};

struct BuildState {
  explicit BuildState(model::Model& m) : model(m) {}

  model::Model& model;
  MeshBuild model_mesh;  ///< moved into model.mesh when reading ends
  unsigned scope = kModelScope;

  std::map<std::string, PartDef> parts;  ///< key: upper-case name
  PartDef* part = nullptr;               ///< open *PART
  std::optional<OpenInstance> instance;  ///< open *INSTANCE
  bool assembly_seen = false;

  /// The parent keyword sub-options attach to ("*MATERIAL", "*SURFACE INTERACTION", "*OUTPUT",
  /// "*CONTACT", ...); cleared by any keyword that is not one of its sub-options.
  std::string open_parent;
  model::Material* material = nullptr;
  model::SurfaceInteraction* interaction = nullptr;
  /// The open *CHANGE FRICTION / *CHANGE SURFACE BEHAVIOR of the step (its *FRICTION or
  /// *SURFACE BEHAVIOR sub-option fills it).
  model::FrictionChange* friction_change = nullptr;
  model::SurfaceBehaviorChange* behavior_change = nullptr;
  bool output_is_history = false;  ///< the open *OUTPUT is HISTORY
  int output_frequency = 1;
  std::optional<int> output_number_interval;
  bool output_time_marks = false;
  model::OutputRequest::Op output_op = model::OutputRequest::Op::Add;
  std::optional<std::string> smoothing;  ///< the open *SURFACE SMOOTHING name

  model::Step* step = nullptr;  ///< open *STEP

  /// *ELEMENT, TYPE=DCOUP3D | DCOUP2D by ELSET (upper case): each element's label, its one node's
  /// label and line. Not mesh elements: *DISTRIBUTING COUPLING, ELSET= takes the node as a
  /// distributing coupling's reference node.
  struct CouplingElement {
    std::int64_t label = 0, node_label = 0;
    model::SourceLoc loc;
  };
  std::map<std::string, std::vector<CouplingElement>> coupling_elements;

  MeshBuild& mesh_build() { return part ? part->build : model_mesh; }
  model::Mesh& mesh() { return mesh_build().mesh; }
};

}  // namespace inpact::parser
