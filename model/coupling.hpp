#pragma once
/// *COUPLING with *KINEMATIC or *DISTRIBUTING: the nodes of a surface coupled to a reference
/// node [K16 *COUPLING, *KINEMATIC, *DISTRIBUTING], [CCX *COUPLING].
///  - Kinematic: the chosen translations of each coupling node follow the rigid motion of the
///    reference node, u_i = u_R + (R(θ) − I) r_i (a rigid body over a subset of DOFs).
///  - Distributing: the reference node moves with the weighted average of the coupling nodes
///    (translation of their centroid, and the least-squares rotation about it), so a force or
///    moment at the reference node is spread over them by the weights, resultant exact.
/// Rotations are held as for a rigid body: in the translations of a rotation node.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

struct Coupling {
  enum class Kind : std::uint8_t { Unset, Kinematic, Distributing };
  /// *DISTRIBUTING, WEIGHTING METHOD: the weight w(ρ) at ρ = r / r0 (r from the reference node,
  /// r0 the influence radius, or the distance of the farthest coupling node).
  enum class Weighting : std::uint8_t { Uniform, Linear, Quadratic, Cubic };

  std::string name;     ///< CONSTRAINT NAME
  Kind kind = Kind::Unset;
  std::int32_t ref_node = -1;
  std::int32_t rot_node = -1;   ///< holds θ when the coupling has rotations (see needs_rotations())
  bool rot_node_added = false;  ///< always: inpact's own, reported as the reference node's UR/RM
  std::string surface;          ///< upper-case name; resolved by parser/couplings.cpp
  double influence_radius = 0;  ///< 0: every node of the surface
  /// ORIENTATION (upper-case name; empty: global): the local axes at each coupling node in which
  /// a kinematic coupling's DOFs 1–3 are meant.
  std::string orientation;
  SourceLoc orientation_loc;
  /// DOFs 1–6 the coupling constrains (data lines "first, last"; none: all of them).
  std::array<bool, 6> dofs{true, true, true, true, true, true};
  Weighting weighting = Weighting::Uniform;
  /// The coupling nodes: the surface's nodes within the influence radius, sorted, unique,
  /// without the reference node (node-based form: in the order of its lines).
  std::vector<std::int32_t> nodes;
  /// *DISTRIBUTING COUPLING (node-based, CalculiX's and Abaqus's older form): its data lines, a
  /// node label or node set (upper case) and a weight, resolved on the complete deck into
  /// `nodes` and `given_weights` (parallel to them).
  struct WeightedLine {
    std::string target;
    double weight = 0;
    SourceLoc loc;
  };
  std::vector<WeightedLine> weighted_lines;
  /// Empty: the weights come from the surface.
  std::vector<double> given_weights;
  bool node_based() const { return !weighted_lines.empty(); }
  /// The keyword messages name: the node-based form's own, or *COUPLING.
  const char* keyword() const { return node_based() ? "*DISTRIBUTING COUPLING" : "*COUPLING"; }
  SourceLoc loc;      ///< the *COUPLING (or *DISTRIBUTING COUPLING) line
  SourceLoc ref_loc;  ///< REF NODE='s value
  SourceLoc surface_loc;

  /// A rotation node is needed: kinematic couplings always (the coupling nodes turn with the
  /// reference node); distributing ones when they couple a rotation (2D: DOF 6).
  bool needs_rotations(int dim) const {
    if (kind == Kind::Kinematic) return true;
    return dim == 3 ? dofs[3] || dofs[4] || dofs[5] : dofs[5];
  }
};

}  // namespace inpact::model
