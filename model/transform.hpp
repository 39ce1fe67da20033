#pragma once
/// *TRANSFORM: a local coordinate system at nodes, in which their boundary conditions,
/// concentrated loads and equations are given and their printed output is written
/// [K16 *TRANSFORM], [CCX *TRANSFORM]. TYPE=R (rectangular): local x towards point a, local y
/// in the plane of a and b (both from the global origin). TYPE=C (cylindrical): a and b on the
/// axis, local 1 radial, 2 tangential, 3 along the axis from a to b — at each node's own
/// position. inpact gives each node whose DOFs the deck refers to a local node (its translations
/// are the local components), and eliminates the node's global translations into it,
/// u = Σ_k e_k u_local,k (solver/dof_map.cpp).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

struct NodalTransform {
  enum class Type : std::uint8_t { Rectangular, Cylindrical };
  Type type = Type::Rectangular;
  std::string nset;
  std::vector<std::int32_t> nodes;  ///< the NSET's rows
  std::array<double, 3> a{}, b{};
  SourceLoc loc;
};

/// A node in a *TRANSFORM whose DOFs the deck refers to, and the node inpact added for them.
struct TransformedNode {
  std::int32_t node = -1;
  std::int32_t local = -1;      ///< its translations are the node's local components
  std::int32_t transform = -1;  ///< index into Model::transforms
};

/// The local axes e_1, e_2, e_3 of `t` at point x (rows of the result). False for a cylindrical
/// system at a point on its axis, or degenerate points a, b.
bool local_axes(const NodalTransform& t, const std::array<double, 3>& x, std::array<std::array<double, 3>, 3>& e);

}  // namespace inpact::model
