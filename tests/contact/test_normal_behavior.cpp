// The normal behaviour Abaqus would use: default method per formulation, penalty stiffness,
// the Lagrange-multiplier switch at 1000 k_e and the augmented-Lagrange tolerance, checked by
// hand; and the mesh scales k_e and the characteristic length on a unit cube.
#include <cmath>

#include <gtest/gtest.h>

#include "contact/normal_behavior.hpp"
#include "model/element_types.hpp"

using namespace inpact;
using contact::resolve_normal_behavior;
using model::ContactDiscretization;
using model::EnforcementMethod;

namespace {

constexpr auto kNts = ContactDiscretization::NodeToSurface;
constexpr auto kSts = ContactDiscretization::SurfaceToSurface;

model::SurfaceInteraction with_behavior(model::SurfaceBehavior b) {
  model::SurfaceInteraction i;
  i.name = "I";
  i.behavior = std::move(b);
  return i;
}

model::SurfaceBehavior method(EnforcementMethod m) {
  model::SurfaceBehavior b;
  b.method = m;
  return b;
}

/// Corner coordinates of an a × b × c brick in C3D8 node order.
std::vector<std::array<double, 3>> brick(double a, double b, double c) {
  return {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
}

/// A model of one element of `type` on `coords`, with section and material E, ν.
model::Model one_element(const char* type, const std::vector<std::array<double, 3>>& coords, double e, double nu) {
  model::Model m;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    m.mesh.nodes.labels.push_back(static_cast<std::int64_t>(i + 1));
    m.mesh.nodes.coords.push_back(coords[i]);
    m.mesh.nodes.instance.push_back(0);
    m.mesh.elements.conn.push_back(static_cast<std::int32_t>(i));
  }
  m.mesh.elements.type.push_back(model::element_type_index(*model::find_element_type(type)));
  m.mesh.elements.labels.push_back(1);
  m.mesh.elements.instance.push_back(0);
  m.mesh.elements.offsets.push_back(static_cast<std::int64_t>(coords.size()));
  m.mesh.elements.loc.push_back({});
  m.mesh.elsets["E"].rows = {0};
  m.mesh.sections.push_back({"E", "M", 1.0, "", {}});
  m.materials["M"].elastic = model::Elastic{e, nu, {}};
  return m;
}

/// The surface made of face `face` (0 = S1) of element row 0.
model::Surface element_surface(std::uint8_t face) {
  model::Surface s;
  s.faces = {{0, face}};
  return s;
}

}  // namespace

TEST(NormalBehavior, DefaultMethodFollowsTheFormulation) {
  // KEYWORDS.md Part C (d): no *SURFACE BEHAVIOR at all.
  EXPECT_EQ(resolve_normal_behavior(nullptr, kNts, false, false).method, EnforcementMethod::Direct);
  EXPECT_EQ(resolve_normal_behavior(nullptr, kSts, false, false).method, EnforcementMethod::PenaltyLinear);
  EXPECT_EQ(resolve_normal_behavior(nullptr, kSts, true, false).method, EnforcementMethod::Direct);
  EXPECT_EQ(resolve_normal_behavior(nullptr, kNts, true, false).method, EnforcementMethod::Direct);
  EXPECT_EQ(resolve_normal_behavior(nullptr, kSts, false, true).method, EnforcementMethod::PenaltyLinear);
  EXPECT_EQ(resolve_normal_behavior(nullptr, kSts, true, true).method, EnforcementMethod::PenaltyLinear);
  EXPECT_EQ(resolve_normal_behavior(nullptr, kNts, false, false, {nullptr, true}).method,
            EnforcementMethod::AugmentedLagrange);
  EXPECT_TRUE(resolve_normal_behavior(nullptr, kNts, false, false).method_is_default);
}

TEST(NormalBehavior, ExplicitMethodIsHonouredAndSoftenedLawsAreDirect) {
  for (auto m : {EnforcementMethod::Direct, EnforcementMethod::PenaltyLinear, EnforcementMethod::PenaltyNonlinear,
                 EnforcementMethod::AugmentedLagrange}) {
    const auto i = with_behavior(method(m));
    const auto r = resolve_normal_behavior(&i, kSts, false, true);
    EXPECT_EQ(r.method, m);
    EXPECT_FALSE(r.method_is_default);
  }
  model::SurfaceBehavior soft;
  soft.pressure_overclosure = model::PressureOverclosure::Linear;
  soft.linear_slope = 1e5;
  const auto i = with_behavior(soft);
  EXPECT_EQ(resolve_normal_behavior(&i, kSts, false, false).method, EnforcementMethod::Direct);
}

TEST(NormalBehavior, PenaltyStiffnessRules) {
  const double ke = 2.0;
  EXPECT_DOUBLE_EQ(penalty_stiffness(resolve_normal_behavior(nullptr, kSts, false, false), ke), 20.0);  // 10 k_e
  EXPECT_DOUBLE_EQ(penalty_stiffness(resolve_normal_behavior(nullptr, kNts, false, false), ke), 0.0);   // direct
  const auto nl = with_behavior(method(EnforcementMethod::PenaltyNonlinear));
  const auto r_nl = resolve_normal_behavior(&nl, kSts, false, false);
  EXPECT_DOUBLE_EQ(penalty_stiffness(r_nl, ke), 200.0);  // K_f = 100 k_e
  EXPECT_DOUBLE_EQ(r_nl.initial_final_ratio, 0.01);      // so K_i = k_e
  EXPECT_DOUBLE_EQ(r_nl.upper_quadratic_limit, 0.03);
  EXPECT_DOUBLE_EQ(r_nl.lower_quadratic_ratio, 1.0 / 3.0);

  auto al = method(EnforcementMethod::AugmentedLagrange);
  al.stiffness_scale_factor = 0.5;
  const auto i_al = with_behavior(al);
  model::ContactControls cc;
  cc.stiffness_scale_factor = 0.5;
  const auto r_al = resolve_normal_behavior(&i_al, kNts, false, false, {&cc});
  EXPECT_DOUBLE_EQ(r_al.scale_factor, 0.25);
  EXPECT_DOUBLE_EQ(penalty_stiffness(r_al, ke), 1000.0 * 2.0 * 0.25);

  auto given = method(EnforcementMethod::PenaltyLinear);
  given.penalty_stiffness = 1e6;
  given.stiffness_scale_factor = 3.0;
  const auto i_given = with_behavior(given);
  EXPECT_DOUBLE_EQ(penalty_stiffness(resolve_normal_behavior(&i_given, kSts, false, false), ke), 3e6);
}

TEST(NormalBehavior, LagrangeMultipliersSwitchOnAbove1000Ke) {
  const double ke = 1.0e3;
  // Direct hard contact: always. Default penalty (10 k_e) and augmented Lagrange (1000 k_e): no.
  EXPECT_TRUE(uses_lagrange_multipliers(resolve_normal_behavior(nullptr, kNts, false, false), ke));
  EXPECT_FALSE(uses_lagrange_multipliers(resolve_normal_behavior(nullptr, kSts, false, false), ke));
  const auto al = with_behavior(method(EnforcementMethod::AugmentedLagrange));
  EXPECT_FALSE(uses_lagrange_multipliers(resolve_normal_behavior(&al, kNts, false, false), ke));

  auto at = method(EnforcementMethod::PenaltyLinear);
  at.penalty_stiffness = 1000.0 * ke;  // exactly 1000 k_e: still no (k ≤ 1000 k_e)
  const auto i_at = with_behavior(at);
  EXPECT_FALSE(uses_lagrange_multipliers(resolve_normal_behavior(&i_at, kSts, false, false), ke));
  // Round-off above 1000 k_e (100 × 10 k_e computed in floating point) does not switch; a
  // real excess of one part in a billion does.
  auto rounding = at;
  rounding.penalty_stiffness = std::nextafter(1000.0 * ke, 2e6);
  const auto i_rounding = with_behavior(rounding);
  EXPECT_FALSE(uses_lagrange_multipliers(resolve_normal_behavior(&i_rounding, kSts, false, false), ke));
  auto above = at;
  above.penalty_stiffness = 1000.0 * ke * (1.0 + 1e-9);
  const auto i_above = with_behavior(above);
  EXPECT_TRUE(uses_lagrange_multipliers(resolve_normal_behavior(&i_above, kSts, false, false), ke));

  // Softened laws: by the local slope.
  model::SurfaceBehavior soft;
  soft.pressure_overclosure = model::PressureOverclosure::Tabular;
  const auto i_soft = with_behavior(soft);
  const auto r_soft = resolve_normal_behavior(&i_soft, kNts, false, false);
  EXPECT_FALSE(uses_lagrange_multipliers(r_soft, ke, 1000.0 * ke));
  EXPECT_TRUE(uses_lagrange_multipliers(r_soft, ke, 1001.0 * ke));
}

TEST(NormalBehavior, AugmentedLagrangePenetrationTolerance) {
  auto al = method(EnforcementMethod::AugmentedLagrange);
  const auto i = with_behavior(al);
  // 0.1 % of the characteristic length; 5 % for finite-sliding surface-to-surface.
  EXPECT_DOUBLE_EQ(*penetration_tolerance(resolve_normal_behavior(&i, kNts, false, false), 2.0), 0.002);
  EXPECT_DOUBLE_EQ(*penetration_tolerance(resolve_normal_behavior(&i, kSts, false, false), 2.0), 0.1);
  EXPECT_DOUBLE_EQ(*penetration_tolerance(resolve_normal_behavior(&i, kSts, true, false), 2.0), 0.002);
  // f_k = 0.25 < 1: the default is scaled by 1/√0.25 = 2.
  al.stiffness_scale_factor = 0.25;
  const auto soft = with_behavior(al);
  EXPECT_DOUBLE_EQ(*penetration_tolerance(resolve_normal_behavior(&soft, kNts, false, false), 2.0), 0.004);
  // A given tolerance is never scaled; absolute wins over the length.
  model::ContactControls rel;
  rel.relative_penetration_tolerance = 0.01;
  EXPECT_DOUBLE_EQ(*penetration_tolerance(resolve_normal_behavior(&soft, kNts, false, false, {&rel}), 2.0), 0.02);
  model::ContactControls abs;
  abs.absolute_penetration_tolerance = 1e-4;
  EXPECT_DOUBLE_EQ(*penetration_tolerance(resolve_normal_behavior(&soft, kSts, false, false, {&abs}), 2.0), 1e-4);
  // Other methods have none.
  EXPECT_FALSE(penetration_tolerance(resolve_normal_behavior(nullptr, kSts, false, false), 2.0));
}

TEST(NormalBehavior, UnitCubeScales) {
  // One C3D8 unit cube, E = 210000, ν = 0.3. Face S2 (z = 1): A = 1, V = 1, h = V/A = 1.
  // M = E(1-ν)/((1+ν)(1-2ν)) = 210000 · 0.7 / (1.3 · 0.4) = 282692.307..., k_e = M / h.
  const model::Model m = one_element("C3D8", brick(1, 1, 1), 210000.0, 0.3);
  auto s = contact::surface_scales(m, element_surface(1));  // S2
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->element_stiffness, 210000.0 * 0.7 / (1.3 * 0.4), 1e-9);
  EXPECT_DOUBLE_EQ(s->characteristic_length, 1.0);
  EXPECT_EQ(s->n_facets, 1u);
  model::Surface nodal;
  nodal.kind = model::Surface::Kind::Node;
  nodal.nodes = {4};
  EXPECT_FALSE(contact::surface_scales(m, nodal));
}

TEST(NormalBehavior, StretchedBrickUsesItsThicknessNormalToTheFace) {
  // A 2 × 3 × 0.5 brick, ν = 0 (M = E): face S2 (z = 0.5) has A = 6, h = V/A = 0.5, facet √6;
  // face S3 (y = 0) has A = 2 × 0.5 = 1, h = 3.
  const model::Model m = one_element("C3D8", brick(2, 3, 0.5), 1000.0, 0.0);
  auto top = contact::surface_scales(m, element_surface(1));
  ASSERT_TRUE(top);
  EXPECT_DOUBLE_EQ(top->element_stiffness, 1000.0 / 0.5);
  EXPECT_DOUBLE_EQ(top->characteristic_length, std::sqrt(6.0));
  auto side = contact::surface_scales(m, element_surface(2));
  ASSERT_TRUE(side);
  EXPECT_DOUBLE_EQ(side->element_stiffness, 1000.0 / 3.0);
}

TEST(NormalBehavior, PlaneStressEdgeScales) {
  // CPS4 2 × 1, ν = 0.25: edge S1 (y = 0) has length 2, element area 2, h = 1; M = E/(1-ν²).
  const model::Model m = one_element("CPS4", {{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}}, 100.0, 0.25);
  auto s = contact::surface_scales(m, element_surface(0));
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->element_stiffness, 100.0 / (1.0 - 0.0625));
  EXPECT_DOUBLE_EQ(s->characteristic_length, 2.0);
}


TEST(NormalBehavior, TwoMaterialsTakeTheSofterModulusOverTheSlavesThickness) {
  // Unit cube, ν = 0: M = E. A stiff slave (E = 1e6, k_e = 1e6) against a soft master
  // (M = 1, k_e = 4 on a brick of thickness 1/4): the slave's h with the master's M, 1 · 1/1.
  const model::Model stiff = one_element("C3D8", brick(1, 1, 1), 1e6, 0.0);
  const model::Model soft = one_element("C3D8", brick(1, 1, 0.25), 1.0, 0.0);
  const auto s = contact::surface_scales(stiff, element_surface(1));
  const auto m = contact::surface_scales(soft, element_surface(1));
  ASSERT_TRUE(s && m);
  EXPECT_DOUBLE_EQ(s->modulus, 1e6);
  EXPECT_DOUBLE_EQ(m->element_stiffness, 4.0);
  EXPECT_DOUBLE_EQ(contact::softer_element_stiffness(*s, *m), 1.0);
  // The soft side keeps its own: its modulus is already the softer.
  EXPECT_DOUBLE_EQ(contact::softer_element_stiffness(*m, *s), 4.0);
}

// A directional *ELASTIC scales the face by the mean of its direct stiffnesses: engineering
// constants with every ν = 0 have D11 = E1, D22 = E2, D33 = E3.
TEST(NormalBehavior, AnOrthotropicMaterialTakesTheMeanDirectStiffness) {
  model::Model m = one_element("C3D8", brick(1, 1, 1), 0.0, 0.0);
  model::Elastic& e = *m.materials["M"].elastic;
  e.type = model::Elastic::Type::EngineeringConstants;
  e.constants = {300.0, 200.0, 100.0, 0.0, 0.0, 0.0, 50.0, 50.0, 50.0};
  auto s = contact::surface_scales(m, element_surface(1));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->element_stiffness, 200.0, 1e-12);
}

// A COMPOSITE shell takes its thickest layer's material, over the whole section's thickness:
// the same as a shell of that material alone.
TEST(NormalBehavior, ACompositeShellTakesItsThickestLayer) {
  const std::vector<std::array<double, 3>> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  model::Model single = one_element("S4", square, 100.0, 0.3);
  single.mesh.sections.clear();
  model::ShellSection sec;
  sec.elset = "E";
  sec.material = "M";
  sec.thickness = 0.3;
  single.mesh.shell_sections.push_back(sec);
  model::Model layered = single;
  layered.materials["SOFT"].elastic = model::Elastic{1.0, 0.3, {}};
  model::ShellSection& composite = layered.mesh.shell_sections[0];
  composite.material.clear();
  composite.layers = {{0.1, 3, "SOFT", "", 0.0, "", {}, {}}, {0.2, 3, "M", "", 0.0, "", {}, {}}};
  auto a = contact::surface_scales(single, element_surface(1));
  auto b = contact::surface_scales(layered, element_surface(1));
  ASSERT_TRUE(a && b);
  EXPECT_GT(b->element_stiffness, 0.0);
  EXPECT_DOUBLE_EQ(b->element_stiffness, a->element_stiffness);
}
