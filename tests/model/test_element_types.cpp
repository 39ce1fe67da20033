// Face tables: the outward normal derived from each face's corner order (see FaceDef) must point
// out of the element on the reference shape, so surfaces and pressure loads get the right sign.
#include <array>

#include <gtest/gtest.h>

#include "model/element_types.hpp"

using namespace inpact::model;

namespace {
using V = std::array<double, 3>;
V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Corner coordinates of the reference elements, Abaqus node order.
const std::vector<V> kHex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<V> kTet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<V> kWedge = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
const std::vector<V> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<V> kTri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

void expect_outward(const ElementTypeInfo& t, const std::vector<V>& corners) {
  V centroid{0, 0, 0};
  for (auto& c : corners)
    for (int i = 0; i < 3; ++i) centroid[i] += c[i] / corners.size();
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const FaceDef& face = t.faces[f];
    V fc{0, 0, 0};
    for (int i = 0; i < face.n_corners; ++i)
      for (int k = 0; k < 3; ++k) fc[k] += corners[face.nodes[i]][k] / face.n_corners;
    V normal;
    if (t.dim == 3) {
      // Abaqus's corner order turns into the solid: the outward normal is its negative.
      normal = cross(sub(corners[face.nodes[face.n_corners - 1]], corners[face.nodes[0]]),
                     sub(corners[face.nodes[1]], corners[face.nodes[0]]));
    } else {  // edge direction rotated clockwise
      V d = sub(corners[face.nodes[1]], corners[face.nodes[0]]);
      normal = {d[1], -d[0], 0};
    }
    EXPECT_GT(dot(normal, sub(fc, centroid)), 0.0) << t.name << " S" << f + 1;
  }
}
}  // namespace

TEST(ElementTypes, EveryFaceNormalPointsOutward) {
  for (const auto& t : element_types()) {
    if (!is_continuum(t)) continue;  // trusses and springs have no faces
    if (t.dim == 3 && t.faces.size() == 6) expect_outward(t, kHex);
    else if (t.dim == 3 && t.faces.size() == 4) expect_outward(t, kTet);
    else if (t.dim == 3) expect_outward(t, kWedge);
    else if (t.faces.size() == 4) expect_outward(t, kQuad);
    else expect_outward(t, kTri);
  }
}

TEST(ElementTypes, MidsideNodesOfQuadraticFacesLieBetweenTheirCorners) {
  // C3D20 S1 = 1-2-3-4 with 9-10-11-12: node 9 is between 1 and 2, and so on.
  const ElementTypeInfo* t = find_element_type("C3D20");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->faces[0].n_nodes, 8);
  EXPECT_EQ(t->faces[0].nodes[4], 8);   // node 9, 0-based
  EXPECT_EQ(t->faces[2].nodes[5], 12);  // S3 = 1-5-6-2 with 17-13-18-9: second midside is 13
  const ElementTypeInfo* q = find_element_type("CAX8R");
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(q->faces[3].nodes[2], 7);  // S4 = 4-1 with 8
  // S8R's SPOS (S2) runs 1-4-3-2, so its midsides run 8-7-6-5: the one between 1 and 4 is 8.
  const ElementTypeInfo* shell = find_element_type("S8R");
  ASSERT_NE(shell, nullptr);
  EXPECT_EQ(shell->faces[1].nodes[4], 7);
  EXPECT_EQ(find_element_type("S9R5"), nullptr);
}
