// Element loads: a uniform pressure on every face of every element type sums to −p·A·n
// (positive pressure pushes into the element, as in Abaqus), with the classical consistent
// distributions; body forces sum to b·V.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "solver/elements/face_loads.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using inpact::test::reference_coords;
using model::ElementFamily;

namespace {

// A rigid rotation of the reference element so no face is axis-aligned (3D only).
std::vector<Vec3> rotated(const std::vector<Vec3>& x) {
  const double c = std::cos(0.7), s = std::sin(0.7), c2 = std::cos(0.4), s2 = std::sin(0.4);
  std::vector<Vec3> y;
  for (const auto& p : x) {
    const Vec3 q = {c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]};
    y.push_back({q[0], c2 * q[1] - s2 * q[2], s2 * q[1] + c2 * q[2]});
  }
  return y;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Hand value of ∫ n_out dA for a flat face: the polygon vector area of the corners, negated
// because the Abaqus corner order turns into the solid. 2D: the edge rotated clockwise × thickness
// (CAX: × 2π r_mid, exact for a straight edge).
Vec3 outward_area_vector(const model::ElementTypeInfo& t, const std::vector<Vec3>& x, int face, double thickness) {
  const model::FaceDef& f = t.faces[face];
  if (t.dim == 2) {
    const Vec3& a = x[f.nodes[0]];
    const Vec3& b = x[f.nodes[1]];
    const double m = t.family == ElementFamily::Axisymmetric ? 2 * std::numbers::pi * (a[0] + b[0]) / 2 : thickness;
    return {(b[1] - a[1]) * m, -(b[0] - a[0]) * m, 0};
  }
  Vec3 v{};
  for (int i = 0; i < f.n_corners; ++i) {
    const Vec3 c = cross(x[f.nodes[i]], x[f.nodes[(i + 1) % f.n_corners]]);
    for (int k = 0; k < 3; ++k) v[k] -= 0.5 * c[k];
  }
  return v;
}

class EachType : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> names() {
  std::vector<std::string> n;
  for (const auto& t : model::element_types())
    if (model::is_continuum(t)) n.emplace_back(t.name);  // trusses, springs: test_line_elements.cpp
  return n;
}

}  // namespace

TEST_P(EachType, PressureOnEveryFaceSumsToMinusPTimesOutwardArea) {
  const auto& t = *model::find_element_type(GetParam());
  const auto x = t.dim == 3 ? rotated(reference_coords(t)) : reference_coords(t);
  const SectionData sec{0.7, 0.005};
  const double p = 2.5;
  Vec3 centroid{};
  for (const auto& c : x)
    for (int k = 0; k < 3; ++k) centroid[k] += c[k] / x.size();
  for (int f = 0; f < static_cast<int>(t.faces.size()); ++f) {
    const auto load = pressure_load(t, x, f, p, sec);
    const Vec3 na = outward_area_vector(t, x, f, sec.thickness);
    Vec3 sum{};
    for (int a = 0; a < t.n_nodes; ++a)
      for (int i = 0; i < t.dim; ++i) sum[i] += load[a * t.dim + i];
    for (int i = 0; i < t.dim; ++i) EXPECT_NEAR(sum[i], -p * na[i], 1e-12) << "S" << f + 1 << " component " << i;
    EXPECT_NEAR(face_area(t, x, f, sec), std::sqrt(na[0] * na[0] + na[1] * na[1] + na[2] * na[2]), 1e-12) << "S" << f + 1;
    // The hand normal itself points away from the element centre.
    Vec3 fc{};
    const auto& fd = t.faces[f];
    for (int i = 0; i < fd.n_corners; ++i)
      for (int k = 0; k < 3; ++k) fc[k] += x[fd.nodes[i]][k] / fd.n_corners;
    const Vec3 d = sub(fc, centroid);
    EXPECT_GT(d[0] * na[0] + d[1] * na[1] + d[2] * na[2], 0.0) << "S" << f + 1;
    // Nodes off the face carry nothing.
    for (int a = 0; a < t.n_nodes; ++a) {
      bool on_face = false;
      for (int i = 0; i < fd.n_nodes; ++i) on_face |= fd.nodes[i] == a;
      if (on_face) continue;
      for (int i = 0; i < t.dim; ++i) EXPECT_EQ(load[a * t.dim + i], 0.0);
    }
  }
}

TEST_P(EachType, BodyForceSumsToForceTimesVolume) {
  const auto& t = *model::find_element_type(GetParam());
  const auto x = reference_coords(t);
  const SectionData sec{0.7, 0.005};
  const Vec3 b = {1.5, -2.0, 0.5};
  const auto load = body_force_load(t, x, b, sec);
  // Reference volumes: cube 1, wedge ½, tet 1/6; square ×t, triangle ½×t; CAX: 2π r̄ A.
  double v = 0;
  const auto shape = element_shape(t);
  if (t.dim == 3) v = shape == Shape::Tet4 || shape == Shape::Tet10 ? 1.0 / 6 : shape == Shape::Wedge6 ? 0.5 : 1.0;
  else {
    const bool tri = shape == Shape::Tri3 || shape == Shape::Tri6;
    const double area = tri ? 0.5 : 1.0, rbar = tri ? 2 + 1.0 / 3 : 2.5;
    v = t.family == ElementFamily::Axisymmetric ? 2 * std::numbers::pi * rbar * area : sec.thickness * area;
  }
  for (int i = 0; i < t.dim; ++i) {
    double s = 0;
    for (int a = 0; a < t.n_nodes; ++a) s += load[a * t.dim + i];
    EXPECT_NEAR(s, b[i] * v, 1e-12) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, EachType, ::testing::ValuesIn(names()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

TEST(FaceLoads, ClassicalConsistentDistributions) {
  const SectionData sec;
  const double p = 1.0;
  // C3D8, unit face: a quarter of p·A to each corner.
  {
    const auto& t = *model::find_element_type("C3D8");
    const auto f = pressure_load(t, reference_coords(t), 1, p, sec);  // S2 = 5-8-7-6 at z = 1
    for (int a : {4, 5, 6, 7}) EXPECT_NEAR(f[a * 3 + 2], -0.25, 1e-14);
  }
  // C3D20: corners −1/12, midsides +1/3 of p·A (so corners pull outward under pressure).
  {
    const auto& t = *model::find_element_type("C3D20");
    const auto f = pressure_load(t, reference_coords(t), 0, p, sec);  // S1 at z = 0: force +z
    for (int a : {0, 1, 2, 3}) EXPECT_NEAR(f[a * 3 + 2], -1.0 / 12, 1e-14);
    for (int a : {8, 9, 10, 11}) EXPECT_NEAR(f[a * 3 + 2], 1.0 / 3, 1e-14);
  }
  // C3D10: zero at the corners, a third of p·A at each midside node (Abaqus Theory Manual,
  // "Triangular, tetrahedral, and wedge elements": why C3D10 is poor for contact).
  {
    const auto& t = *model::find_element_type("C3D10");
    const auto f = pressure_load(t, reference_coords(t), 0, p, sec);  // S1 = 1-2-3 at z = 0, A = ½
    for (int a : {0, 1, 2}) EXPECT_NEAR(f[a * 3 + 2], 0.0, 1e-14);
    for (int a : {4, 5, 6}) EXPECT_NEAR(f[a * 3 + 2], 0.5 / 3, 1e-14);
  }
  // CPE8 edge: 1/6, 2/3, 1/6.
  {
    const auto& t = *model::find_element_type("CPE8");
    const auto f = pressure_load(t, reference_coords(t), 0, p, sec);  // S1 = 1-2 (5) at y = 0
    EXPECT_NEAR(f[0 * 2 + 1], 1.0 / 6, 1e-14);
    EXPECT_NEAR(f[1 * 2 + 1], 1.0 / 6, 1e-14);
    EXPECT_NEAR(f[4 * 2 + 1], 2.0 / 3, 1e-14);
  }
  // CAX4 edge at z = 0 from r = 2 to 3: ring force p·π(3² − 2²), split by ∫N_a 2πr dr.
  {
    const auto& t = *model::find_element_type("CAX4");
    const auto f = pressure_load(t, reference_coords(t), 0, p, sec);
    const double two_pi = 2 * std::numbers::pi;
    EXPECT_NEAR(f[0 * 2 + 1], two_pi * (2.0 / 2 + 1.0 / 6), 1e-12);  // ∫(3−r) r dr over [2,3]
    EXPECT_NEAR(f[1 * 2 + 1], two_pi * (2.0 / 2 + 1.0 / 3), 1e-12);  // ∫(r−2) r dr
  }
}

TEST(FaceLoads, BodyForceOfTheQuadraticTetrahedron) {
  // Corner nodes −V/20, midside nodes V/5 of the total (the consistent load of C3D10).
  const auto& t = *model::find_element_type("C3D10");
  const auto f = body_force_load(t, reference_coords(t), {0, 0, 6.0}, SectionData{});
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(f[a * 3 + 2], -6.0 / 6 / 20, 1e-14);
  for (int a = 4; a < 10; ++a) EXPECT_NEAR(f[a * 3 + 2], 6.0 / 6 / 5, 1e-14);
}

// Tractions on shell edges (EDNOR, EDSHR, EDT): on a flat shell turned in space, each sums to q
// times the edge's length along the in-plane inward normal, the edge direction (node order) and
// the negative shell normal; a straight quadratic edge takes the classical 1/6, 2/3, 1/6.
TEST(FaceLoads, ShellEdgeTractionsSumToQTimesLengthInTheirDirections) {
  for (const char* name : {"S3", "S4", "S4R", "S6", "S8", "S8R"}) {
    const auto& type = *model::find_element_type(name);
    const std::vector<Vec3> x = rotated(reference_coords(type));
    const Vec3 normal = [&] {
      const Vec3 c = cross(sub(x[1], x[0]), sub(x[2], x[0]));
      const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      return Vec3{c[0] / l, c[1] / l, c[2] / l};
    }();
    Vec3 centroid{0, 0, 0};
    for (std::size_t a = 0; a < type.edges.size(); ++a)
      for (int i = 0; i < 3; ++i) centroid[i] += x[a][i] / static_cast<double>(type.edges.size());
    for (int edge = 0; edge < static_cast<int>(type.edges.size()); ++edge) {
      const model::FaceDef& ed = type.edges[static_cast<std::size_t>(edge)];
      const Vec3 chord = sub(x[ed.nodes[1]], x[ed.nodes[0]]);
      const double length = std::sqrt(chord[0] * chord[0] + chord[1] * chord[1] + chord[2] * chord[2]);
      const Vec3 t{chord[0] / length, chord[1] / length, chord[2] / length};
      Vec3 inward = cross(normal, t);  // in the plane, into the element (checked against the centroid)
      const Vec3 to_centre = sub(centroid, x[ed.nodes[0]]);
      ASSERT_GT(inward[0] * to_centre[0] + inward[1] * to_centre[1] + inward[2] * to_centre[2], 0) << name;
      const double q = 7.0;
      struct Case {
        model::EdgeTraction traction;
        Vec3 direction;
      };
      for (const Case& c : {Case{model::EdgeTraction::Normal, inward}, Case{model::EdgeTraction::Shear, t},
                            Case{model::EdgeTraction::Transverse, {-normal[0], -normal[1], -normal[2]}}}) {
        const auto f = edge_traction_load(type, x, edge, c.traction, q);
        Vec3 sum{0, 0, 0};
        for (int a = 0; a < type.n_nodes; ++a) {
          const bool on_edge = std::find(ed.nodes, ed.nodes + ed.n_nodes, a) != ed.nodes + ed.n_nodes;
          for (int i = 0; i < 3; ++i) {
            sum[i] += f[static_cast<std::size_t>(a) * 3 + i];
            if (!on_edge) {
              EXPECT_EQ(f[static_cast<std::size_t>(a) * 3 + i], 0.0) << name << " node " << a;
            }
          }
        }
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(sum[i], q * length * c.direction[i], 1e-12 * q * length) << name << " edge " << edge;
        if (ed.n_nodes != 3) continue;
        for (int k = 0; k < 3; ++k)  // corner, corner, midside: 1/6, 1/6, 2/3 of q L
          for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(f[static_cast<std::size_t>(ed.nodes[k]) * 3 + i],
                        (k == 2 ? 2.0 / 3.0 : 1.0 / 6.0) * q * length * c.direction[i], 1e-12 * q * length)
                << name;
          }
      }
    }
  }
}
