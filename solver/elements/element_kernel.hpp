#pragma once
/// Element kernels for small-strain and total-Lagrangian (NLGEOM) continua: pure functions from
/// element coordinates, displacements, the material (material.hpp) and its points' history to
/// the element stiffness, internal force, integration-point stresses and trial history. No Eigen
/// in this header, no global state, no I/O.
///
/// Conventions (shared by every kernel in solver/elements/):
///  - DOFs are node-major: (u1, u2[, u3]) of node 1, then node 2, …; 2 per node in 2D, 3 in 3D.
///  - 2D elements use x (= r for CAX) and y (= z); the z coordinate of a Vec3 is ignored.
///  - Stress/strain components are stored in Abaqus order 11, 22, 33, 12, 13, 23 with
///    engineering shear strains (γ12 = 2ε12), as Abaqus prints them. For CAX, 33 is the hoop
///    direction θθ; plane-stress elements report σ33 = 0 and the thickness strain ε33.
///  - Axisymmetric quantities are integrated over the full ring (dV = 2πr dA): Abaqus wants
///    point loads and reactions of axisymmetric models "integrated around the circumference;
///    that is, the total value on the ring" (Abaqus Elements Guide, axisymmetric element
///    library, "Conventions").
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "model/element_types.hpp"

namespace inpact::solver::elements {

using Vec3 = std::array<double, 3>;
using Voigt6 = std::array<double, 6>;

/// Isotropic linear elasticity (*ELASTIC) and isotropic expansion (*EXPANSION).
struct ElasticConstants {
  double youngs_modulus = 0.0;
  double poissons_ratio = 0.0;
  double expansion = 0.0;  ///< α; thermal strain α·ΔT on the diagonal
  double shear_modulus() const { return youngs_modulus / (2 * (1 + poissons_ratio)); }
};

/// Section data the kernels need.
struct SpringBehavior;  // line_elements.hpp
struct BeamProperties;  // beam_section.hpp
struct ShellProperties; // shell_section.hpp

struct SectionData {
  double thickness = 1.0;  ///< plane strain / plane stress out-of-plane thickness (Abaqus default 1)
  /// Stiffness of the hourglass control of C3D8R/CPE4R/CPS4R/CAX4R as a fraction of the shear
  /// modulus (see hourglass.hpp); 0.005 mirrors Abaqus's default scaling r_F·G = 0.005·G.
  double hourglass_scale = 0.005;
  double area = 0.0;       ///< trusses: the cross-section area (*SOLID SECTION's data line)
  const SpringBehavior* spring = nullptr;  ///< springs: their *SPRING (owned by the AnalysisModel)
  const BeamProperties* beam = nullptr;    ///< beams: their section (owned by the AnalysisModel)
  const ShellProperties* shell = nullptr;  ///< shells: their section (owned by the AnalysisModel)
  /// Shells with *NODAL THICKNESS: their nodes' thicknesses (owned by the AnalysisModel), which
  /// the kernel interpolates; empty: `thickness` throughout.
  std::span<const double> nodal_thickness{};
  /// Shells whose nodes' normals are averaged with their neighbours' (shell_normals.hpp): the
  /// directors at its nodes (owned by the AnalysisModel); empty: the element's own normals.
  std::span<const Vec3> shell_directors{};
};

struct ElementRequest {
  bool stiffness = true;       ///< fill ElementSystem::stiffness
  bool internal_force = true;  ///< fill ElementSystem::internal_force
  bool point_output = false;   ///< fill ElementSystem::points (stress, strain, coordinates)
  bool nlgeom = false;         ///< total Lagrangian, St. Venant–Kirchhoff (see continuum_kinematics.hpp)
  /// The temperature T of each node of the element, for a material whose data depend on it
  /// (Material::temperature_dependent); empty: T = 0 at every point. A shell's may hold the
  /// gradient ∂T/∂n at its nodes after them (compute_shell).
  std::span<const double> temperature = {};
};

/// Results at one integration point.
struct PointResult {
  Voigt6 stress{};  ///< Cauchy stress (small strain: the engineering stress)
  Voigt6 strain{};  ///< small strain ε (nlgeom: logarithmic strain LE = ½ ln(F Fᵀ)), engineering shear
  Vec3 coords{};    ///< reference coordinates of the point
  double volume = 0.0;  ///< reference volume it represents (Abaqus IVOL; 2πr·dA for CAX)
  Voigt6 plastic_strain{};  ///< PE, engineering shear (0 without plasticity)
  double peeq = 0.0;        ///< PEEQ, the equivalent plastic strain ∫ε̄̇ᵖ dt
  /// Section forces and moments SF1, SF2, SF3, SM1, SM2, SM3: a truss's axial force N in SF1;
  /// a beam's axial force, shear forces along n2 and n1, bending moments about n1 and n2 and
  /// the torque (Abaqus's order, beam_elements.hpp); a shell's membrane forces N11, N22, N12 and
  /// moments M11, M22, M12 per unit length (shell_elements.hpp); 0 for continua.
  std::array<double, 6> section{};
};

/// The history variables of one integration point (material.hpp, material_states.hpp): the
/// committed state the increment started from, and the trial state an evaluation writes. Both
/// empty for a stateless material.
struct PointHistory {
  std::span<const double> committed;
  std::span<double> trial;
};

/// The history of every point of an element, point after point, `per_point` values each
/// (per_point = 0: none).
struct ElementHistory {
  std::span<const double> committed;
  std::span<double> trial;
  std::size_t per_point = 0;
  PointHistory at(std::size_t p) const {
    if (per_point == 0) return {};
    return {committed.subspan(p * per_point, per_point), trial.subspan(p * per_point, per_point)};
  }
};

class Material;

struct ElementSystem {
  int n_dof = 0;
  std::vector<double> stiffness;       ///< n_dof × n_dof, row-major; symmetric
  /// n_dof; ∫ Bᵀ D(ε − ε_th) dV (+ hourglass force): with ΔT ≠ 0 this already includes minus the
  /// equivalent thermal load, so the residual is f_ext − internal_force.
  std::vector<double> internal_force;
  std::vector<PointResult> points;
  /// Smallest det J at an integration point. When ≤ 0 the element is inverted or degenerate and
  /// nothing else is filled; the caller reports it with the element's deck location.
  double min_jacobian = 0.0;
  /// NLGEOM: the smallest det F (current over reference volume) at an integration point; at or
  /// below zero the element is turned inside out, a state no material law may accept (a
  /// St. Venant–Kirchhoff point mirrored through itself has no strain at all). 1 at small strain.
  double min_volume_ratio = 1.0;
  int local_iterations = 0;   ///< nlgeom incompatible modes: Newton iterations on the internal modes

  double k(int i, int j) const { return stiffness[static_cast<std::size_t>(i) * n_dof + j]; }
};

/// Sizes `out` for an element of `n_dof` DOFs as `request` asks, zeroed, with no points: the
/// common start of the line, beam and shell kernels.
inline void begin_element_system(ElementSystem& out, int n_dof, const ElementRequest& request) {
  out.n_dof = n_dof;
  out.local_iterations = 0;
  out.min_volume_ratio = 1.0;  // not measured by these kernels (the systems are reused)
  out.internal_force.assign(request.internal_force ? static_cast<std::size_t>(n_dof) : 0, 0.0);
  out.stiffness.assign(request.stiffness ? static_cast<std::size_t>(n_dof) * n_dof : 0, 0.0);
  out.points.clear();
}

/// Stiffness K = ∂f_int/∂u, internal force f_int(u) = ∫ Bᵀσ dV (plus the hourglass force for
/// reduced integration) and point output for one element.
///
/// coords: reference coordinates of the element's nodes (Abaqus node order).
/// u: nodal displacements, node-major, type.dim values per node.
/// delta_t: nodal temperature change T − T_initial (empty: none); the thermal strain
///          α·ΔT·I enters as an initial strain, σ = D(ε − ε_th), so f_int already contains
///          the equivalent thermal load with the opposite sign.
ElementSystem compute_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                              std::span<const double> u, const ElasticConstants& material,
                              const SectionData& section, const ElementRequest& request,
                              std::span<const double> delta_t = {});

/// The same, written into `out`, whose vectors keep their capacity from one call to the next (the
/// assembler's per-element path: no allocation per element once the buffers have grown).
void compute_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                     const ElasticConstants& material, const SectionData& section, const ElementRequest& request,
                     std::span<const double> delta_t, ElementSystem& out);

/// The points of an element that carry material state: its integration points; a shell's at each
/// of its section points (shell_elements.hpp).
std::size_t material_points(const model::ElementTypeInfo& type, const SectionData& section);

/// The same with any material: each point evaluates `material` from `history`'s committed state
/// and writes its trial state there. An empty history for a material with state: the
/// material's initial state, the trial state discarded.
void compute_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                     const Material& material, const SectionData& section, const ElementRequest& request,
                     std::span<const double> delta_t, const ElementHistory& history, ElementSystem& out);

}  // namespace inpact::solver::elements
