#pragma once
/// Nodes, elements, sets and surfaces: the geometric part of the model database.
/// Rows are 0-based positions in these arrays; labels are the user's numbers. A label is unique
/// only within its instance (Abaqus parts/instances), so every lookup takes both.
#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "label_map.hpp"
#include "beam_section.hpp"
#include "shell_section.hpp"
#include "source_loc.hpp"

namespace inpact::model {

struct Nodes {
  std::vector<std::int64_t> labels;
  std::vector<std::array<double, 3>> coords;
  std::vector<std::int32_t> instance;  ///< index into Model::instances
  LabelMap index;                      ///< (instance, label) → row

  std::size_t size() const { return labels.size(); }
};

/// All elements of all types in one compressed-row table; `type` indexes element_types().
struct Elements {
  std::vector<std::uint8_t> type;
  std::vector<std::int64_t> labels;
  std::vector<std::int32_t> instance;
  std::vector<std::int64_t> offsets{0};  ///< connectivity of row e: conn[offsets[e] .. offsets[e+1])
  std::vector<std::int32_t> conn;        ///< node rows
  std::vector<SourceLoc> loc;            ///< the data line that defined the element
  LabelMap index;

  std::size_t size() const { return labels.size(); }
  std::span<const std::int32_t> nodes_of(std::size_t e) const {
    return {conn.data() + offsets[e], static_cast<std::size_t>(offsets[e + 1] - offsets[e])};
  }
};

/// A node or element set: sorted, unique rows.
struct Set {
  std::string name;  ///< as written (upper-case key in the map)
  std::vector<std::int32_t> rows;
  bool internal = false;
  SourceLoc loc;
};

/// One face of a solid or one edge of a 2D element: face 0 = S1.
struct Face {
  std::int32_t element;
  std::uint8_t face;
  bool operator==(const Face&) const = default;
};

struct Surface {
  /// Analytical: *SURFACE, TYPE=SEGMENTS | CYLINDER | REVOLUTION (model/analytical_surface.hpp),
  /// no faces and no nodes.
  enum class Kind : std::uint8_t { Element, Node, Analytical };
  std::string name;
  Kind kind = Kind::Element;
  std::vector<Face> faces;          ///< Kind::Element
  /// Kind::Element: shell edges (`face` indexes ElementTypeInfo::edges), Abaqus's edge-based
  /// surface; a surface has faces or edges, not both.
  std::vector<Face> edges;
  std::vector<std::int32_t> nodes;  ///< Kind::Node (rows)
  std::vector<double> node_areas;   ///< Kind::Node: area per node (1.0 when not given)
  std::int32_t analytical = -1;     ///< Kind::Analytical: index into Model::analytical_surfaces
  SourceLoc loc;
};

/// *SOLID SECTION: which material the elements of an element set are made of.
struct SolidSection {
  std::string elset;     ///< upper-case set name
  std::string material;  ///< upper-case material name
  double thickness = 1.0;  ///< plane elements: out-of-plane thickness (Abaqus default 1); trusses: area
  std::string orientation;
  SourceLoc loc;
  bool value_given = false;  ///< the data line gave the first field (a truss needs its area)
  SourceLoc value_loc{};     ///< where (the keyword line when not given)
};

/// *SPRING, ELSET=: the behaviour of the spring elements of a set. Linear: `stiffness`;
/// NONLINEAR: the (force, relative displacement) table in ascending displacement.
struct SpringSection {
  std::string elset;  ///< upper-case set name
  /// SPRING1/SPRING2: the DOFs (1-based) at the first and second node; 0 = not given.
  int dof1 = 0, dof2 = 0;
  SourceLoc dof_loc;  ///< the DOF line (the keyword line when there is none)
  bool nonlinear = false;
  double stiffness = 0.0;
  std::vector<std::array<double, 2>> table;  ///< NONLINEAR: {force, relative displacement}
  SourceLoc value_loc;                       ///< the (first) stiffness or table line
  SourceLoc loc;
};

/// Everything a *PART holds; also the model's own mesh (parts are merged into it per instance).
struct Mesh {
  Nodes nodes;
  Elements elements;
  std::map<std::string, Set> nsets;  ///< key: upper-case name ("INST.NAME" for instance sets)
  std::map<std::string, Set> elsets;
  std::map<std::string, Surface> surfaces;
  std::vector<SolidSection> sections;
  std::vector<SpringSection> springs;
  std::vector<BeamSection> beam_sections;
  std::vector<ShellSection> shell_sections;
  /// *NODAL THICKNESS: a shell thickness per node row, for sections with NODAL THICKNESS.
  std::map<std::int32_t, double> nodal_thickness;
  /// *NORMAL: a shell's director at one of its nodes, in place of the averaged normal.
  struct GivenNormal {
    std::int32_t element = 0;  ///< element row
    int local = 0;             ///< the node's place in the element
    std::array<double, 3> direction{};  ///< as given (not yet unit)
    SourceLoc loc;
  };
  std::vector<GivenNormal> normals;
  /// *NODE's fifth to seventh fields: a normal at the node, for every shell element there that
  /// *NORMAL does not give one (Abaqus). Key: node row; element and local unused.
  std::map<std::int32_t, GivenNormal> node_normals;
};

}  // namespace inpact::model
