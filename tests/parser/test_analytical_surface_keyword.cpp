// *SURFACE, TYPE=SEGMENTS | CYLINDER | REVOLUTION and *RIGID BODY, ANALYTICAL SURFACE= (parser/
// kw_analytical_surface.cpp, kw_rigid_body.cpp): the profile and local axes read, and the deck
// errors with their line and column.
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

/// The one-cube deck with a free node 50 above it, then `body` and an empty step.
std::string cube(const std::string& body) {
  return test::one_cube_deck("*NODE\n50, 0.5, 0.5, 2.\n" + body + "*STEP\n*STATIC\n*END STEP\n");
}

}  // namespace

TEST(AnalyticalSurfaceKeyword, CylinderAxesProfileAndItsRigidBodyAreRead) {
  DeckDir dir;
  auto r = dir.read(cube("*SURFACE, TYPE=CYLINDER, NAME=ROLL, FILLET RADIUS=0.1\n"
                         "0., 0., 2., 2., 0., 2.\n"
                         "0., 5., 3.\n"
                         "START, 1., 0.\n"
                         "LINE, 0.5, 0.\n"
                         "CIRCL, -0.5, 0., 0., 0.5\n"
                         "*RIGID BODY, REF NODE=50, ANALYTICAL SURFACE=ROLL\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.analytical_surfaces.size(), 1u);
  const auto& s = r.model.analytical_surfaces[0];
  EXPECT_EQ(s.type, model::AnalyticalSurface::Type::Cylinder);
  EXPECT_EQ(s.fillet_radius, 0.1);
  EXPECT_EQ(s.origin, (std::array<double, 3>{0, 0, 2}));
  EXPECT_EQ(s.axes[0], (std::array<double, 3>{1, 0, 0}));
  // c − a = (0, 5, 1) made normal to x, then unit: the generator; y = z × x.
  EXPECT_NEAR(s.axes[2][1], 5.0 / std::sqrt(26.0), 1e-15);
  EXPECT_NEAR(s.axes[1][2], -5.0 / std::sqrt(26.0), 1e-15);
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_EQ(s.segments[1].kind, model::ProfileSegment::Kind::Arc);
  EXPECT_EQ(s.segments[1].center, (std::array<double, 2>{0.0, 0.5}));
  const auto& surf = r.model.mesh.surfaces.at("ROLL");
  EXPECT_EQ(surf.kind, model::Surface::Kind::Analytical);
  ASSERT_EQ(r.model.rigid_bodies.size(), 1u);
  EXPECT_EQ(r.model.rigid_bodies[0].analytical_surface, 0);
  EXPECT_TRUE(r.model.rigid_bodies[0].nodes.empty());
  EXPECT_TRUE(r.model.rigid_bodies[0].rot_node_added);
}

TEST(AnalyticalSurfaceKeyword, RevolutionWithoutItsAxisLineTakesTheGlobalAxes) {
  DeckDir dir;
  auto r = dir.read(cube("*SURFACE, TYPE=REVOLUTION, NAME=BALL\nSTART, 1., 0.\nCIRCL, 0., -1., 0., 0.\n"
                         "*RIGID BODY, REF NODE=50, ANALYTICAL SURFACE=BALL\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.analytical_surfaces[0].axes[2], (std::array<double, 3>{0, 0, 1}));
  EXPECT_EQ(r.model.analytical_surfaces[0].start, (std::array<double, 2>{1.0, 0.0}));
}

TEST(AnalyticalSurfaceKeyword, DeckErrorsNameTheLine) {
  DeckDir dir;
  auto parab = dir.read(cube("*SURFACE, TYPE=SEGMENTS, NAME=P\nSTART, 1., 0.\nPARAB, 0., 1., -1., 0.\n"));
  EXPECT_TRUE(has_diagnostic(parab, "deck.inp:20:1: error: *SURFACE: PARAB segments are not supported yet")) << parab.report();
  auto no_start = dir.read(cube("*SURFACE, TYPE=SEGMENTS, NAME=P\nLINE, 1., 0.\nLINE, 2., 0.\n"));
  EXPECT_TRUE(has_diagnostic(no_start, "deck.inp:19:1: error: *SURFACE: the profile must begin with START")) << no_start.report();
  auto not_analytical = dir.read(cube("*SURFACE, NAME=TOP\nCUBE, S2\n*RIGID BODY, REF NODE=50, ANALYTICAL SURFACE=TOP\n"));
  EXPECT_TRUE(has_diagnostic(not_analytical, "error: *RIGID BODY: 'TOP' is not an analytical surface")) << not_analytical.report();
  auto fillet = dir.read(cube("*SURFACE, NAME=TOP, FILLET RADIUS=1.\nCUBE, S2\n"));
  EXPECT_TRUE(has_diagnostic(fillet, "error: *SURFACE: FILLET RADIUS belongs to an analytical surface")) << fillet.report();
  auto twice = dir.read(cube("*SURFACE, TYPE=SEGMENTS, NAME=P\nSTART, 1., 0.\nLINE, 2., 0.\n"
                             "*RIGID BODY, REF NODE=50, ANALYTICAL SURFACE=P\n*RIGID BODY, REF NODE=5, ANALYTICAL SURFACE=P\n"));
  EXPECT_TRUE(has_diagnostic(twice, "error: *RIGID BODY: surface 'P' is carried by another *RIGID BODY already")) << twice.report();
}

// Abaqus/CAE writes an analytical rigid part as an instance holding its reference point, its
// surface and its *RIGID BODY; the names resolve inside the instance, and the instance's
// translation moves the profile with the reference node.
TEST(AnalyticalSurfaceKeyword, ARigidBodyInsideAnInstanceAsAbaqusCaeWritesIt) {
  DeckDir dir;
  auto r = dir.read("*Part, name=block\n*Node\n1, 0., 0.\n2, 1., 0.\n3, 1., 1.\n4, 0., 1.\n"
                    "*Element, type=CPE4\n1, 1, 2, 3, 4\n*Elset, elset=all\n1\n"
                    "*Solid Section, elset=all, material=steel\n,\n*End Part\n"
                    "*Part, name=indenter\n*End Part\n"
                    "*Assembly, name=Assembly\n*Instance, name=block-1, part=block\n*End Instance\n"
                    "*Instance, name=indenter-1, part=indenter\n0., 1., 0.\n*Node\n1, 0.5, 2.\n"
                    "*Nset, nset=indenter-1-RefPt_, internal\n1,\n"
                    "*Surface, type=SEGMENTS, name=RigidSurface_, internal\nSTART, 2., 1.5\nLINE, -1., 1.5\n"
                    "*Rigid Body, ref node=indenter-1-RefPt_, analytical surface=RigidSurface_\n*End Instance\n"
                    "*End Assembly\n*Material, name=steel\n*Elastic\n210000., 0.3\n"
                    "*Step\n*Static\n*End Step\n");
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.rigid_bodies.size(), 1u);
  const auto& body = r.model.rigid_bodies[0];
  EXPECT_EQ(body.analytical_surface, 0);
  EXPECT_TRUE(r.model.mesh.surfaces.count("INDENTER-1.RIGIDSURFACE_"));
  // The reference node is the indenter's own (after the block's four), moved to (0.5, 3).
  EXPECT_EQ(body.ref_node, 4);
  EXPECT_EQ(r.model.mesh.nodes.coords[4], (std::array<double, 3>{0.5, 3.0, 0.0}));
  const auto& a = r.model.analytical_surfaces[0];
  EXPECT_EQ(a.start, (std::array<double, 2>{2.0, 2.5}));
  EXPECT_EQ(a.segments[0].end, (std::array<double, 2>{-1.0, 2.5}));
}
