#pragma once
/// The element types inpact knows: node counts, dimension and the Abaqus face numbering
/// (S1..S6 for solids, edges S1..S4 for 2D elements), used by surfaces and loads.
#include <cstdint>
#include <span>
#include <string_view>

namespace inpact::model {

enum class ElementFamily : std::uint8_t {
  Solid3D,      ///< C3D*
  PlaneStrain,  ///< CPE*
  PlaneStress,  ///< CPS*
  Axisymmetric, ///< CAX*
  Truss,        ///< T2D2, T3D2, T3D3: axial force only, cross-section area from *SOLID SECTION
  Spring,       ///< SPRINGA, SPRING1, SPRING2: stiffness from *SPRING; dim 0 (the model's)
  Rigid,        ///< R3D3, R3D4, R2D2, RAX2: no stiffness, a surface of a *RIGID BODY (faces SNEG, SPOS)
  Beam,         ///< B31, B32 (B32R) shear-flexible, B33 Euler–Bernoulli: beams in space, 6 DOFs a node
  Shell         ///< S3, S3R, S4, S4R, S6, S8R, S8: conventional shells, 6 DOFs a node (faces SNEG, SPOS)
};

enum class Integration : std::uint8_t { Full, Reduced, IncompatibleModes };

/// A face of an element: its corner nodes first, then midside nodes, as local indices (0-based),
/// in the Abaqus manual's order. For solids that order turns INTO the element by the right-hand
/// rule (outward normal = -(x1-x0)×(x_last-x0)); for 2D elements the outward normal is the edge
/// direction rotated clockwise. tests/model/test_element_types.cpp pins both.
struct FaceDef {
  std::uint8_t n_nodes = 0;
  std::uint8_t n_corners = 0;
  std::uint8_t nodes[8] = {};
};

struct ElementTypeInfo {
  std::string_view name;     ///< Abaqus name, upper case
  ElementFamily family;
  Integration integration;
  std::uint8_t dim;          ///< 2 or 3 (coordinates used); 0 for springs, which take the model's
  std::uint8_t n_nodes;
  std::uint8_t order;        ///< 1 or 2 (3: B33's cubic deflection)
  std::span<const FaceDef> faces;  ///< faces[0] is S1
  /// Hybrid (…H): mixed displacement–pressure, the pressure condensed in the element
  /// (solver/elements/hybrid.hpp); the rest of the type is the standard element's.
  bool hybrid = false;
  /// A shell's edges, edge n at [n − 1] (Abaqus's E1.., CalculiX's S3..): the corner from which the
  /// edge runs by the element's node order, the next corner, then the midside node. Empty for
  /// other types.
  std::span<const FaceDef> edges{};
};

/// Solids, plane and axisymmetric elements: the types with faces, sections of a material and
/// the continuum kernels (not trusses or springs).
inline bool is_continuum(const ElementTypeInfo& t) {
  return t.family != ElementFamily::Truss && t.family != ElementFamily::Spring && t.family != ElementFamily::Rigid &&
         t.family != ElementFamily::Beam && t.family != ElementFamily::Shell;
}

/// B31, B32, B33.
inline bool is_beam(const ElementTypeInfo& t) { return t.family == ElementFamily::Beam; }

/// S3, S3R, S4, S4R, S6, S8R, S8.
inline bool is_shell(const ElementTypeInfo& t) { return t.family == ElementFamily::Shell; }

/// Beams and shells: elements with rotations at their nodes (model::NodeRotation).
inline bool has_rotations(const ElementTypeInfo& t) { return is_beam(t) || is_shell(t); }

/// R3D3, R3D4, R2D2, RAX2: nodes that follow their *RIGID BODY, faces for contact, no stiffness.
inline bool is_rigid(const ElementTypeInfo& t) { return t.family == ElementFamily::Rigid; }

/// Elements of an axisymmetric model: CAX* and the axisymmetric rigid element RAX2.
inline bool is_axisymmetric(const ElementTypeInfo& t) {
  return t.family == ElementFamily::Axisymmetric || t.name == "RAX2";
}

/// The type with this (upper-case) name, or nullptr when inpact does not support it.
const ElementTypeInfo* find_element_type(std::string_view upper_name);
/// Every supported type, for listing in error messages.
std::span<const ElementTypeInfo> element_types();
/// Type by its index in element_types() (what Elements::type stores).
const ElementTypeInfo& element_type(std::uint8_t index);
std::uint8_t element_type_index(const ElementTypeInfo& info);

}  // namespace inpact::model
