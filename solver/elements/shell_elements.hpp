#pragma once
/// The conventional shells S4, S4R, S3, S3R, S8R, S8 and S6: small strain (finite rotations through
/// corotation.hpp under NLGEOM), linear elastic sections (shell_section.hpp) or a plastic law at
/// every section point (ShellMaterial below).
///
/// Unknowns: at each node its displacement u and its rotation vector θ (global components).
/// The element's DOFs are the translations of its nodes, then the rotations of the same nodes
/// in the same order, three values each (the rotation node's translations, model::NodeRotation).
///
/// Degenerated-solid kinematics (Ahmad, Irons and Zienkiewicz): with the nodal directors V_a
/// (the element's unit normal at each node, by the right-hand rule of its node order),
///   X(ξ, η, ζ) = Σ N_a (X_a + z(ζ) V_a),  u = Σ N_a (u_a + z(ζ) θ_a × V_a),
///   z(ζ) = t (ζ/2 − offset)
/// so the reference surface (the nodes) lies offset·t above the midsurface along V. The lamina is in
/// plane stress (σ33 = 0) in the local shell axes: 1 the projection of global x on the surface
/// (global z when x is within 0.1° of the normal), 3 the normal, 2 = 3 × 1 (Abaqus's default).
/// Transverse shear: 5/6·G unless *TRANSVERSE SHEAR STIFFNESS gives it.
///
/// Locking: S4 and S4R tie the transverse shear to the edge midpoints (MITC4, Dvorkin and Bathe
/// 1984), S3 and S3R to the MITC3 points (Lee and Bathe 2004), both at 2×2 (quad) or 3 (triangle)
/// in-plane points: S4R is integrated as S4 (no hourglass modes to control). S8R takes 2×2
/// points, S8 (CalculiX's) 3×3, S6 (CalculiX's six-node triangle) 3, untied. Through the
/// thickness: Simpson at the section points.
///
/// Drilling: θ·V has no stiffness in this kinematics; each node gets k_d (θ·V_a − ω_a)² / 2, ω_a
/// the membrane rotation about V_a at the node (a rigid rotation costs nothing, flat or curved),
/// k_d = 10⁻⁴ · E t³ / (12 (1 − ν²)), 10⁻⁴ of the plate's bending stiffness (a moment per
/// radian, as a node's bending stiffness is): enough to keep a flat mesh non-singular.
///
/// Layers (shell_section.hpp): each section point takes its layer's lamina turned from the
/// layer's material axes into the local ones (shell_lamina.hpp).
///
/// Point output: at each in-plane point, every section point from SNEG (1) up through the layers
/// (output picks the ones a request reports): PointResult::stress S11, S22, S12 (slots 0, 1, 3;
/// the transverse shears are not reported) in that point's layer's material axes (the local axes
/// for a section neither oriented nor turned), strain likewise (γ12), and PointResult::section
/// SF1..SF3 = N11, N22, N12 and SM1..SM3 = M11, M22, M12 per unit length, about the midsurface,
/// the same at each; volume = the point's Simpson share of t·dA (they sum to t·dA).
#include <span>

#include "element_kernel.hpp"
#include "shell_section.hpp"

namespace inpact::solver::elements {

class Material;

/// A shell's material beyond its section's elasticity: a law with state (plasticity) evaluated at
/// every section point, and the points' history; none (null): the section's linear elastic lamina.
struct ShellMaterial {
  const Material* law = nullptr;
  ElementHistory history;  ///< per_point = law's state size; point = in-plane point × section points + k
};

/// What a shell element takes at its nodes beyond their coordinates: its thickness (the
/// section's, or *NODAL THICKNESS's one per node, interpolated to the points as Abaqus does) and
/// its directors where they are not its own normals (Abaqus averages the normals of the elements
/// that meet at a node, shell_normals.hpp).
struct ShellNodeData {
  double uniform = 0.0;
  std::span<const double> nodal;  ///< empty: `uniform` throughout
  std::span<const Vec3> directors;  ///< one unit vector per node; empty: the element's own normals
  ShellNodeData(double t) : uniform(t) {}  // NOLINT(google-explicit-constructor): a plain thickness
  ShellNodeData(double t, std::span<const double> at_nodes, std::span<const Vec3> at_nodes_directors = {})
      : uniform(t), nodal(at_nodes), directors(at_nodes_directors) {}
};

/// The element's own unit normal at each of its nodes (g1 × g2 of its reference geometry there);
/// false where it vanishes.
bool shell_nodal_normals(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                         std::array<Vec3, 8>& normals);

/// The points that carry a shell's material state: each in-plane point at each section point.
std::size_t shell_material_points(const model::ElementTypeInfo& type, const ShellProperties& section);

/// Stiffness, internal force and point output of a shell. `u` holds 6 values per node in the
/// order above; coords the reference nodes; at_nodes its thickness and directors; delta_t the
/// nodes' temperature change on the reference surface (empty: none), then, when it holds twice
/// the nodes, the change of the temperature's gradient ∂T/∂n through the thickness at them: the
/// thermal strain at a section point z from the reference surface is α (ΔT + z Δg). Linear with
/// the section's elastic lamina; with a law of `material`, its plane stress state at each section
/// point (PE, PEEQ in the points' output) at the temperature T + z g there, T (and g after it,
/// when request.temperature holds twice the nodes) interpolated from request.temperature.
void compute_shell(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                   const ShellProperties& section, const ShellNodeData& at_nodes, const ElementRequest& request,
                   std::span<const double> delta_t, const ShellMaterial& material, ElementSystem& out);

/// The local shell axes {e1, e2, e3} at a point with surface tangents g1, g2 (Abaqus's default
/// projection, above); false when g1 × g2 vanishes.
bool shell_axes(const Vec3& g1, const Vec3& g2, std::array<Vec3, 3>& axes);

}  // namespace inpact::solver::elements
