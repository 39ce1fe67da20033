#include "element_types.hpp"

#include <array>
#include <cstddef>

namespace inpact::model {
namespace {

// Face tables as the Abaqus manual numbers them (1-based there, 0-based here):
// corners in the order that points the normal out of the element, then midside nodes.
constexpr FaceDef face(std::initializer_list<int> corners, std::initializer_list<int> mids = {}) {
  FaceDef f;
  for (int n : corners) f.nodes[f.n_nodes++] = static_cast<std::uint8_t>(n - 1);
  f.n_corners = f.n_nodes;
  for (int n : mids) f.nodes[f.n_nodes++] = static_cast<std::uint8_t>(n - 1);
  return f;
}

constexpr std::array<FaceDef, 6> kHex8 = {face({1, 2, 3, 4}), face({5, 8, 7, 6}), face({1, 5, 6, 2}),
                                          face({2, 6, 7, 3}), face({3, 7, 8, 4}), face({4, 8, 5, 1})};
constexpr std::array<FaceDef, 6> kHex20 = {
    face({1, 2, 3, 4}, {9, 10, 11, 12}),  face({5, 8, 7, 6}, {16, 15, 14, 13}),
    face({1, 5, 6, 2}, {17, 13, 18, 9}),  face({2, 6, 7, 3}, {18, 14, 19, 10}),
    face({3, 7, 8, 4}, {19, 15, 20, 11}), face({4, 8, 5, 1}, {20, 16, 17, 12})};
constexpr std::array<FaceDef, 4> kTet4 = {face({1, 2, 3}), face({1, 4, 2}), face({2, 4, 3}),
                                          face({3, 4, 1})};
constexpr std::array<FaceDef, 4> kTet10 = {face({1, 2, 3}, {5, 6, 7}), face({1, 4, 2}, {8, 9, 5}),
                                           face({2, 4, 3}, {9, 10, 6}), face({3, 4, 1}, {10, 8, 7})};
constexpr std::array<FaceDef, 5> kWedge6 = {face({1, 2, 3}), face({4, 6, 5}), face({1, 4, 5, 2}),
                                            face({2, 5, 6, 3}), face({3, 6, 4, 1})};
constexpr std::array<FaceDef, 4> kQuad4 = {face({1, 2}), face({2, 3}), face({3, 4}), face({4, 1})};
constexpr std::array<FaceDef, 4> kQuad8 = {face({1, 2}, {5}), face({2, 3}, {6}), face({3, 4}, {7}),
                                           face({4, 1}, {8})};
constexpr std::array<FaceDef, 3> kTri3 = {face({1, 2}), face({2, 3}), face({3, 1})};
// Rigid elements (R3D3, R3D4, R2D2, RAX2): the element is its own surface, S1 = SNEG and
// S2 = SPOS. Abaqus's positive normal follows the node order by the right-hand rule (2D: the
// direction 1 → 2 turned counter-clockwise), so SPOS lists the nodes reversed in the solids'
// convention above (its normal out of the face) and SNEG as given.
constexpr std::array<FaceDef, 2> kRigidTri = {face({1, 2, 3}), face({1, 3, 2})};
constexpr std::array<FaceDef, 2> kRigidQuad = {face({1, 2, 3, 4}), face({1, 4, 3, 2})};
// Shells have the two sides of the rigid elements: S1 = SNEG (the node order), S2 = SPOS.
constexpr std::array<FaceDef, 2> kShellQuad8 = {face({1, 2, 3, 4}, {5, 6, 7, 8}), face({1, 4, 3, 2}, {8, 7, 6, 5})};
constexpr std::array<FaceDef, 2> kShellTri6 = {face({1, 2, 3}, {4, 5, 6}), face({1, 3, 2}, {6, 5, 4})};
// A shell's edges run from corner n to corner n + 1 (the midside node between them last).
constexpr std::array<FaceDef, 3> kShellTri3Edges = {face({1, 2}), face({2, 3}), face({3, 1})};
constexpr std::array<FaceDef, 4> kShellQuad4Edges = {face({1, 2}), face({2, 3}), face({3, 4}), face({4, 1})};
constexpr std::array<FaceDef, 3> kShellTri6Edges = {face({1, 2}, {4}), face({2, 3}, {5}), face({3, 1}, {6})};
constexpr std::array<FaceDef, 4> kShellQuad8Edges = {face({1, 2}, {5}), face({2, 3}, {6}), face({3, 4}, {7}),
                                                     face({4, 1}, {8})};
constexpr std::array<FaceDef, 2> kRigidLine = {face({1, 2}), face({2, 1})};
constexpr std::array<FaceDef, 3> kTri6 = {face({1, 2}, {4}), face({2, 3}, {5}), face({3, 1}, {6})};

using F = ElementFamily;
using I = Integration;

constexpr ElementTypeInfo kTypes[] = {
    {"C3D8", F::Solid3D, I::Full, 3, 8, 1, kHex8, false},
    {"C3D8R", F::Solid3D, I::Reduced, 3, 8, 1, kHex8, false},
    {"C3D8I", F::Solid3D, I::IncompatibleModes, 3, 8, 1, kHex8, false},
    {"C3D20", F::Solid3D, I::Full, 3, 20, 2, kHex20, false},
    {"C3D20R", F::Solid3D, I::Reduced, 3, 20, 2, kHex20, false},
    {"C3D4", F::Solid3D, I::Full, 3, 4, 1, kTet4, false},
    {"C3D10", F::Solid3D, I::Full, 3, 10, 2, kTet10, false},
    {"C3D6", F::Solid3D, I::Full, 3, 6, 1, kWedge6, false},
    {"CPE4", F::PlaneStrain, I::Full, 2, 4, 1, kQuad4, false},
    {"CPE4R", F::PlaneStrain, I::Reduced, 2, 4, 1, kQuad4, false},
    {"CPE4I", F::PlaneStrain, I::IncompatibleModes, 2, 4, 1, kQuad4, false},
    {"CPE8", F::PlaneStrain, I::Full, 2, 8, 2, kQuad8, false},
    {"CPE8R", F::PlaneStrain, I::Reduced, 2, 8, 2, kQuad8, false},
    {"CPE3", F::PlaneStrain, I::Full, 2, 3, 1, kTri3, false},
    {"CPE6", F::PlaneStrain, I::Full, 2, 6, 2, kTri6, false},
    {"CPS4", F::PlaneStress, I::Full, 2, 4, 1, kQuad4, false},
    {"CPS4R", F::PlaneStress, I::Reduced, 2, 4, 1, kQuad4, false},
    {"CPS4I", F::PlaneStress, I::IncompatibleModes, 2, 4, 1, kQuad4, false},
    {"CPS8", F::PlaneStress, I::Full, 2, 8, 2, kQuad8, false},
    {"CPS8R", F::PlaneStress, I::Reduced, 2, 8, 2, kQuad8, false},
    {"CPS3", F::PlaneStress, I::Full, 2, 3, 1, kTri3, false},
    {"CPS6", F::PlaneStress, I::Full, 2, 6, 2, kTri6, false},
    {"CAX4", F::Axisymmetric, I::Full, 2, 4, 1, kQuad4, false},
    {"CAX4R", F::Axisymmetric, I::Reduced, 2, 4, 1, kQuad4, false},
    {"CAX4I", F::Axisymmetric, I::IncompatibleModes, 2, 4, 1, kQuad4, false},
    {"CAX8", F::Axisymmetric, I::Full, 2, 8, 2, kQuad8, false},
    {"CAX8R", F::Axisymmetric, I::Reduced, 2, 8, 2, kQuad8, false},
    {"CAX3", F::Axisymmetric, I::Full, 2, 3, 1, kTri3, false},
    {"CAX6", F::Axisymmetric, I::Full, 2, 6, 2, kTri6, false},
    // Hybrid (mixed displacement–pressure) forms, after the others so the indices above stay.
    {"C3D8H", F::Solid3D, I::Full, 3, 8, 1, kHex8, true},
    {"C3D20H", F::Solid3D, I::Full, 3, 20, 2, kHex20, true},
    {"C3D20RH", F::Solid3D, I::Reduced, 3, 20, 2, kHex20, true},
    {"C3D4H", F::Solid3D, I::Full, 3, 4, 1, kTet4, true},
    {"C3D10H", F::Solid3D, I::Full, 3, 10, 2, kTet10, true},
    {"CPE4H", F::PlaneStrain, I::Full, 2, 4, 1, kQuad4, true},
    {"CPE8H", F::PlaneStrain, I::Full, 2, 8, 2, kQuad8, true},
    {"CPE8RH", F::PlaneStrain, I::Reduced, 2, 8, 2, kQuad8, true},
    {"CAX4H", F::Axisymmetric, I::Full, 2, 4, 1, kQuad4, true},
    {"CAX8H", F::Axisymmetric, I::Full, 2, 8, 2, kQuad8, true},
    {"CAX8RH", F::Axisymmetric, I::Reduced, 2, 8, 2, kQuad8, true},
    // Line and point elements: no faces. T3D3's nodes are end, middle, end (Abaqus's order).
    {"T2D2", F::Truss, I::Full, 2, 2, 1, {}},
    {"T3D2", F::Truss, I::Full, 3, 2, 1, {}},
    {"T3D3", F::Truss, I::Full, 3, 3, 2, {}},
    {"SPRINGA", F::Spring, I::Full, 0, 2, 1, {}},
    {"SPRING1", F::Spring, I::Full, 0, 1, 1, {}},
    {"SPRING2", F::Spring, I::Full, 0, 2, 1, {}},
    // Beams in space: B32's nodes are end, middle, end; B32R is CalculiX's name for the same
    // reduced-integration element (Abaqus's B32 integrates at two points already).
    {"B31", F::Beam, I::Reduced, 3, 2, 1, {}},
    {"B32", F::Beam, I::Reduced, 3, 3, 2, {}},
    {"B32R", F::Beam, I::Reduced, 3, 3, 2, {}},
    {"B33", F::Beam, I::Full, 3, 2, 3, {}},  // Euler–Bernoulli, cubic (Hermite) deflection
    {"R3D3", F::Rigid, I::Full, 3, 3, 1, kRigidTri},
    {"R3D4", F::Rigid, I::Full, 3, 4, 1, kRigidQuad},
    {"R2D2", F::Rigid, I::Full, 2, 2, 1, kRigidLine},
    {"RAX2", F::Rigid, I::Full, 2, 2, 1, kRigidLine},
    // Conventional shells (shell_elements.hpp). S8 is CalculiX's full-integration S8R, S6 its
    // six-node triangle.
    {"S3", F::Shell, I::Full, 3, 3, 1, kRigidTri, false, kShellTri3Edges},
    {"S3R", F::Shell, I::Reduced, 3, 3, 1, kRigidTri, false, kShellTri3Edges},
    {"S4", F::Shell, I::Full, 3, 4, 1, kRigidQuad, false, kShellQuad4Edges},
    {"S4R", F::Shell, I::Reduced, 3, 4, 1, kRigidQuad, false, kShellQuad4Edges},
    {"S8R", F::Shell, I::Reduced, 3, 8, 2, kShellQuad8, false, kShellQuad8Edges},
    {"S8", F::Shell, I::Full, 3, 8, 2, kShellQuad8, false, kShellQuad8Edges},
    {"S6", F::Shell, I::Full, 3, 6, 2, kShellTri6, false, kShellTri6Edges},
};

}  // namespace

const ElementTypeInfo* find_element_type(std::string_view upper_name) {
  for (const auto& t : kTypes)
    if (t.name == upper_name) return &t;
  return nullptr;
}

std::span<const ElementTypeInfo> element_types() { return kTypes; }

const ElementTypeInfo& element_type(std::uint8_t index) { return kTypes[index]; }

std::uint8_t element_type_index(const ElementTypeInfo& info) {
  return static_cast<std::uint8_t>(&info - kTypes);
}

}  // namespace inpact::model
