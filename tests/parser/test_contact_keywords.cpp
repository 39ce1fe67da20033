// The contact keywords into the model database: defaults, CalculiX and Abaqus/CAE spellings, and
// each class of bad data reported at its file:line:col.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;
using model::EnforcementMethod;
using model::PressureOverclosure;

namespace {

/// The one-cube deck with two surfaces (lines 16-19); `extra` starts on line 20.
std::string contact_deck(const std::string& extra) {
  return one_cube_deck("*SURFACE, NAME=TOP\n1, S2\n*SURFACE, NAME=BOTTOM\n1, S1\n" + extra);
}

const std::string kStep = "*STEP\n*STATIC\n";
const std::string kEndStep = "*END STEP\n";

}  // namespace

TEST(ContactKeywords, SurfaceInteractionAloneIsFrictionlessHardContact) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=Int-1\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& i = r.model.interactions.at("INT-1");
  EXPECT_EQ(i.name, "Int-1");
  EXPECT_FALSE(i.behavior);
  EXPECT_FALSE(i.friction);
  EXPECT_DOUBLE_EQ(i.out_of_plane_thickness, 1.0);
  EXPECT_FALSE(i.tracking_thickness);
}

TEST(ContactKeywords, SurfaceInteractionDataLineIsTheOutOfPlaneThickness) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I, TRACKING THICKNESS=0.5\n2.5\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_DOUBLE_EQ(r.model.interactions.at("I").out_of_plane_thickness, 2.5);
  EXPECT_DOUBLE_EQ(*r.model.interactions.at("I").tracking_thickness, 0.5);
}

TEST(ContactKeywords, SurfaceBehaviorDefaultsToHardContactWithTheFormulationsMethod) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& b = *r.model.interactions.at("I").behavior;
  EXPECT_EQ(b.pressure_overclosure, PressureOverclosure::Hard);
  EXPECT_EQ(b.method, EnforcementMethod::Default);
  EXPECT_FALSE(b.no_separation);
  EXPECT_FALSE(b.penalty_stiffness);
  EXPECT_DOUBLE_EQ(b.clearance_at_zero_pressure, 0.0);
  EXPECT_DOUBLE_EQ(b.stiffness_scale_factor, 1.0);
}

TEST(ContactKeywords, PenaltyAndAugmentedLagrangeDataLines) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=P\n*SURFACE BEHAVIOR, PENALTY\n1e6, 0.01, 0.5\n"
                                 "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n, , 2.\n"
                                 "*SURFACE INTERACTION, NAME=N\n*SURFACE BEHAVIOR, PENALTY=NONLINEAR\n, , , 0.04, 0.02, 0.5\n"
                                 "*SURFACE INTERACTION, NAME=D\n*SURFACE BEHAVIOR, DIRECT, NO SEPARATION\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& p = *r.model.interactions.at("P").behavior;
  EXPECT_EQ(p.method, EnforcementMethod::PenaltyLinear);
  EXPECT_DOUBLE_EQ(*p.penalty_stiffness, 1e6);
  EXPECT_DOUBLE_EQ(p.clearance_at_zero_pressure, 0.01);
  EXPECT_DOUBLE_EQ(p.stiffness_scale_factor, 0.5);
  const auto& a = *r.model.interactions.at("A").behavior;
  EXPECT_EQ(a.method, EnforcementMethod::AugmentedLagrange);
  EXPECT_FALSE(a.penalty_stiffness);  // blank: the default 1000 k_e
  EXPECT_DOUBLE_EQ(a.stiffness_scale_factor, 2.0);
  const auto& n = *r.model.interactions.at("N").behavior;
  EXPECT_EQ(n.method, EnforcementMethod::PenaltyNonlinear);
  EXPECT_DOUBLE_EQ(*n.upper_quadratic_limit_scale_factor, 0.04);
  EXPECT_DOUBLE_EQ(*n.initial_final_stiffness_ratio, 0.02);
  EXPECT_DOUBLE_EQ(*n.lower_quadratic_limit_ratio, 0.5);
  const auto& d = *r.model.interactions.at("D").behavior;
  EXPECT_EQ(d.method, EnforcementMethod::Direct);
  EXPECT_TRUE(d.no_separation);
}

TEST(ContactKeywords, SoftenedLaws) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=E\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.001, 20.\n"
                                 "*SURFACE INTERACTION, NAME=L\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LIN\n1e5\n"
                                 "*SURFACE INTERACTION, NAME=T\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n"
                                 "0., -0.001\n10., 0.\n100., 0.001\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& e = *r.model.interactions.at("E").behavior;
  EXPECT_EQ(e.pressure_overclosure, PressureOverclosure::Exponential);
  EXPECT_DOUBLE_EQ(e.exponential_c0, 0.001);
  EXPECT_DOUBLE_EQ(e.exponential_p0, 20.0);
  const auto& l = *r.model.interactions.at("L").behavior;  // LIN: an abbreviation of LINEAR
  EXPECT_EQ(l.pressure_overclosure, PressureOverclosure::Linear);
  EXPECT_DOUBLE_EQ(*l.linear_slope, 1e5);
  EXPECT_FALSE(l.linear_sigma_inf);
  const auto& t = *r.model.interactions.at("T").behavior;
  ASSERT_EQ(t.table.size(), 3u);
  EXPECT_DOUBLE_EQ(t.table[2][0], 100.0);
  EXPECT_DOUBLE_EQ(t.table[2][1], 0.001);
}

TEST(ContactKeywords, FrictionDefaultsAndOptions) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=F\n*FRICTION\n0.3\n"
                                 "*SURFACE INTERACTION, NAME=S\n*FRICTION, SLIP TOLERANCE=0.01\n0.1,\n"
                                 "*SURFACE INTERACTION, NAME=E\n*FRICTION, ELASTIC SLIP=1e-4\n0.1\n"
                                 "*SURFACE INTERACTION, NAME=L\n*FRICTION, LAGRANGE\n0.5\n"
                                 "*SURFACE INTERACTION, NAME=R\n*FRICTION, ROUGH\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& f = *r.model.interactions.at("F").friction;
  EXPECT_DOUBLE_EQ(f.mu, 0.3);
  EXPECT_FALSE(f.rough);
  EXPECT_FALSE(f.lagrange);
  EXPECT_FALSE(f.slip_tolerance);  // unset: 0.005 of the characteristic length, resolved by contact/
  EXPECT_FALSE(f.stick_slope);
  EXPECT_DOUBLE_EQ(*r.model.interactions.at("S").friction->slip_tolerance, 0.01);
  EXPECT_DOUBLE_EQ(*r.model.interactions.at("E").friction->elastic_slip, 1e-4);
  EXPECT_TRUE(r.model.interactions.at("L").friction->lagrange);
  EXPECT_TRUE(r.model.interactions.at("R").friction->rough);
}

TEST(ContactKeywords, ContactPairDefaultsToFiniteSlidingNodeToSurface) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*CONTACT PAIR, INTERACTION=I\nTOP, BOTTOM\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.contact_pairs.size(), 1u);
  const auto& p = r.model.contact_pairs[0];
  EXPECT_EQ(p.slave, "TOP");
  EXPECT_EQ(p.master, "BOTTOM");
  EXPECT_EQ(p.interaction, "I");
  EXPECT_EQ(p.type, model::ContactDiscretization::NodeToSurface);
  EXPECT_FALSE(p.small_sliding);
  EXPECT_FALSE(p.adjust_distance);
  EXPECT_TRUE(p.adjust_nset.empty());
  EXPECT_FALSE(p.tied);
  EXPECT_DOUBLE_EQ(p.extension_zone, 0.1);
  EXPECT_DOUBLE_EQ(p.smooth, 0.2);
  EXPECT_FALSE(p.hcrit);
  EXPECT_EQ(p.loc.line, 22u);
  EXPECT_EQ(p.loc.col, 1u);
}

TEST(ContactKeywords, ContactPairOptionsAndSelfContact) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*NSET, NSET=ADJ\n5, 6\n*SURFACE INTERACTION, NAME=I\n"
                                 "*CONTACT PAIR, INTERACTION=I, SMALL SLIDING, ADJUST=0.01, TIED\nTOP, BOTTOM\n"
                                 "*CONTACT PAIR, INTERACTION=I, ADJUST=ADJ, TYPE=SURFACE TO SURFACE, HCRIT=0.2\nBOTTOM, TOP\n"
                                 "*CONTACT PAIR, INTERACTION=I, ADJUST=YES, POSITION TOLERANCE=0.05\nTOP,\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.contact_pairs.size(), 3u);
  const auto& a = r.model.contact_pairs[0];
  EXPECT_TRUE(a.small_sliding);
  EXPECT_TRUE(a.tied);
  EXPECT_DOUBLE_EQ(*a.adjust_distance, 0.01);
  const auto& b = r.model.contact_pairs[1];
  EXPECT_EQ(b.type, model::ContactDiscretization::SurfaceToSurface);
  EXPECT_EQ(b.adjust_nset, "ADJ");
  EXPECT_DOUBLE_EQ(*b.hcrit, 0.2);
  const auto& c = r.model.contact_pairs[2];
  EXPECT_EQ(c.slave, "TOP");
  EXPECT_EQ(c.master, "TOP");  // `surf,` is self-contact
  EXPECT_DOUBLE_EQ(*c.adjust_distance, 0.05);
}

TEST(ContactKeywords, GeneralContactWithAssignmentsAndSmoothing) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=FRICTION1\n*FRICTION\n0.1\n"
                                 "*CONTACT\n*CONTACT INCLUSIONS, ALL EXTERIOR\n*CONTACT EXCLUSIONS\nTOP, BOTTOM\n"
                                 "*CONTACT PROPERTY ASSIGNMENT\n , , FRICTION1\nTOP, BOTTOM, FRICTION1\n"
                                 "*SURFACE PROPERTY ASSIGNMENT, PROPERTY=GEOMETRICCORRECTION\n"
                                 "TOP, CIRCUMFERENTIAL, 0., 0., 0., 0., 0., 1.\nBOTTOM, SPHERICAL, 1., 2., 3.\n"
                                 "TOP, TOROIDAL, 0., 0., 0., 1., 0., 0., 5.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& gc = r.model.general_contact;
  EXPECT_TRUE(gc.defined);
  ASSERT_EQ(gc.inclusions.size(), 1u);
  EXPECT_TRUE(gc.inclusions[0].first.empty());
  EXPECT_TRUE(gc.inclusions[0].second.empty());
  ASSERT_EQ(gc.exclusions.size(), 1u);
  EXPECT_EQ(gc.exclusions[0].second, "BOTTOM");
  ASSERT_EQ(gc.property_assignments.size(), 2u);
  EXPECT_TRUE(gc.property_assignments[0].first.empty());
  EXPECT_EQ(gc.property_assignments[0].interaction, "FRICTION1");
  ASSERT_EQ(gc.geometric_corrections.size(), 3u);
  using Kind = model::GeometricCorrection::Kind;
  EXPECT_EQ(gc.geometric_corrections[0].kind, Kind::Circumferential);
  EXPECT_DOUBLE_EQ(gc.geometric_corrections[0].b[2], 1.0);
  EXPECT_EQ(gc.geometric_corrections[1].kind, Kind::Spherical);
  EXPECT_DOUBLE_EQ(gc.geometric_corrections[1].a[1], 2.0);
  EXPECT_EQ(gc.geometric_corrections[2].kind, Kind::Toroidal);
  EXPECT_DOUBLE_EQ(gc.geometric_corrections[2].radius, 5.0);
}

TEST(ContactKeywords, SurfaceSmoothingNamedByASurfaceToSurfacePair) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE SMOOTHING, NAME=SM\nTOP, SPHERICAL, 0, 0, 0\n*SURFACE INTERACTION, NAME=I\n"
                                 "*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE, GEOMETRIC CORRECTION=SM\nTOP, BOTTOM\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.surface_smoothings.at("SM").corrections.size(), 1u);
  EXPECT_EQ(r.model.contact_pairs[0].geometric_correction, "SM");
}

TEST(ContactKeywords, ClearanceValueAndTableWithEitherSpelling) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*CONTACT PAIR, INTERACTION=I, SMALL SLIDING\nTOP, BOTTOM\n"
                                 "*CLEARANCE, SLAVE=TOP, MASTER=BOTTOM, VALUE=-0.001\n"
                                 "*CLEARANCE, SECONDARY=TOP, MAIN=BOTTOM, TABULAR\n5, 0.002\nALL, 0.001\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.clearances.size(), 2u);
  EXPECT_DOUBLE_EQ(*r.model.clearances[0].value, -0.001);
  EXPECT_EQ(r.model.clearances[1].slave, "TOP");
  EXPECT_EQ(r.model.clearances[1].master, "BOTTOM");
  EXPECT_EQ(r.model.clearances[1].node_values.size(), 9u);  // node 5 and the 8 of ALL
}

TEST(ContactKeywords, AbaqusCaeFragment) {
  DeckDir dir;
  auto r = dir.read(contact_deck("**\n** INTERACTION PROPERTIES\n**\n*Surface Interaction, name=IntProp-1\n1.,\n"
                                 "*Friction\n0.2,\n*Surface Behavior, pressure-overclosure=HARD\n"
                                 "**\n** INTERACTIONS\n**\n*Contact Pair, interaction=IntProp-1, type=SURFACE TO SURFACE\n"
                                 "Top, Bottom\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& i = r.model.interactions.at("INTPROP-1");
  ASSERT_TRUE(i.friction);
  EXPECT_DOUBLE_EQ(i.friction->mu, 0.2);
  ASSERT_TRUE(i.behavior);
  EXPECT_EQ(i.behavior->pressure_overclosure, PressureOverclosure::Hard);
  EXPECT_EQ(i.behavior->method, EnforcementMethod::Default);
  ASSERT_EQ(r.model.contact_pairs.size(), 1u);
  EXPECT_EQ(r.model.contact_pairs[0].type, model::ContactDiscretization::SurfaceToSurface);
  EXPECT_EQ(r.model.contact_pairs[0].interaction, "INTPROP-1");
}

TEST(ContactKeywords, CalculixFragment) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION,NAME=SI1\n*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=LINEAR\n"
                                 "1.E7,1.E-3,1.E-3\n*FRICTION\n0.2,5000.\n"
                                 "*SURFACE INTERACTION,NAME=SI2\n*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TIED\n1.E7\n"
                                 "*FRICTION\n0.,5000.\n"
                                 "*CONTACT PAIR,INTERACTION=SI1,TYPE=NODE TO SURFACE\nTOP,BOTTOM\n"
                                 "*CONTACT PAIR,INTERACTION=SI2,TYPE=SURFACE TO SURFACE\nBOTTOM,TOP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& b = *r.model.interactions.at("SI1").behavior;
  EXPECT_DOUBLE_EQ(*b.linear_slope, 1e7);
  EXPECT_DOUBLE_EQ(*b.linear_sigma_inf, 1e-3);
  EXPECT_DOUBLE_EQ(*b.linear_c0, 1e-3);
  // Read, but not honoured: a warning says so (inpact's LINEAR has no tension branch).
  EXPECT_TRUE(has_diagnostic(r, "are read but not used"));
  EXPECT_DOUBLE_EQ(*r.model.interactions.at("SI1").friction->stick_slope, 5000.0);
  const auto& t = *r.model.interactions.at("SI2").behavior;
  EXPECT_EQ(t.pressure_overclosure, PressureOverclosure::Tied);
  EXPECT_DOUBLE_EQ(*t.tied_slope, 1e7);
  EXPECT_EQ(r.model.contact_pairs.size(), 2u);
}

// ---- errors, each at its file:line:col (extra starts on line 20) ----

TEST(ContactKeywordErrors, NegativePenaltyStiffness) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PENALTY\n1., 0., 1.\n 2., -1e6\n"
                                 "*SURFACE INTERACTION, NAME=J\n*SURFACE BEHAVIOR, PENALTY\n-1e6\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:2: error: *SURFACE BEHAVIOR: expected one data line")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:26:1: error: *SURFACE BEHAVIOR: the penalty stiffness must be positive, found -1000000"))
      << r.report();
}

TEST(ContactKeywordErrors, ZeroLengthSmoothingAxis) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*CONTACT\n*SURFACE PROPERTY ASSIGNMENT, PROPERTY=GEOMETRIC CORRECTION\n"
                                 "TOP, CIRCUMFERENTIAL, 1., 2., 3., 1., 2., 3.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:35: error: *SURFACE PROPERTY ASSIGNMENT: the axis has zero length")) << r.report();
}

TEST(ContactKeywordErrors, ToroidalRadiusMustBePositive) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE SMOOTHING, NAME=S\nTOP, TOROIDAL, 0., 0., 0., 0., 0., 1., 0.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:40: error: *SURFACE SMOOTHING: the distance R of the arc centre from the axis "
                                "must be positive, found 0"))
      << r.report();
}

TEST(ContactKeywordErrors, SoftenedLinearWithoutASlope) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
                                 "*SURFACE INTERACTION, NAME=J\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n, 3.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:41: error: *SURFACE BEHAVIOR: LINEAR needs its slope on a data line")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:1: error: *SURFACE BEHAVIOR: slope of the pressure-overclosure line is missing"))
      << r.report();
}

TEST(ContactKeywordErrors, ExponentialNeedsC0AndP0) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n"
                                 "*SURFACE INTERACTION, NAME=J\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.001\n"
                                 "*SURFACE INTERACTION, NAME=K\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.001, \n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:41: error: *SURFACE BEHAVIOR: EXPONENTIAL needs a data line: c0, p0")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:1: error: *SURFACE BEHAVIOR: data line has 1 field, expected 2 to 3")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:27:1: error: *SURFACE BEHAVIOR: data line has 1 field, expected 2 to 3")) << r.report();
}

TEST(ContactKeywordErrors, TabularPressureMustRiseWithOverclosure) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n"
                                 "0., 0.\n100., 0.001\n 50., 0.002\n100., 0.002\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:2: error: *SURFACE BEHAVIOR: pressures must increase with overclosure: 50 follows 100"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:25:7: error: *SURFACE BEHAVIOR: overclosures must increase from line to line"))
      << r.report();
}

TEST(ContactKeywordErrors, NegativeFrictionCoefficient) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*FRICTION\n  -0.1\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:3: error: *FRICTION: the friction coefficient must not be negative, found -0.1"))
      << r.report();
}

TEST(ContactKeywordErrors, MethodsAndLawsThatDoNotGoTogether) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PENALTY, DIRECT\n"
                                 "*SURFACE INTERACTION, NAME=J\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR, PENALTY\n1e5\n"
                                 "*SURFACE INTERACTION, NAME=K\n*SURFACE BEHAVIOR, NO SEPARATION, PRESSURE-OVERCLOSURE=HARD\n"
                                 "*SURFACE INTERACTION, NAME=L\n*SURFACE BEHAVIOR\n1e5\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:29: error: *SURFACE BEHAVIOR: AUGMENTED LAGRANGE, DIRECT and PENALTY are mutually exclusive"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:49: error: *SURFACE BEHAVIOR: PENALTY applies to hard contact only")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:26:20: error: *SURFACE BEHAVIOR: NO SEPARATION cannot be combined with PRESSURE-OVERCLOSURE"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:29:1: error: *SURFACE BEHAVIOR: hard contact takes a data line only with PENALTY"))
      << r.report();
}

TEST(ContactKeywordErrors, UnsupportedOptionsSaySo) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I, USER\n"
                                 "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=SCALE FACTOR\n"
                                 "*FRICTION, ANISOTROPIC\n0.1, 0.2\n"
                                 "*CONTACT PAIR, INTERACTION=I, TYPE=MASSLESS\nTOP, BOTTOM\n"
                                 "*SURFACE INTERACTION, NAME=J\n*FRICTION\n0.1, , 10.\n0.2, , 20.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:31: error: *SURFACE INTERACTION: USER is not supported by inpact yet")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:41: error: *SURFACE BEHAVIOR: PRESSURE-OVERCLOSURE=SCALE FACTOR applies to "
                                "Abaqus/Explicit general contact only"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:12: error: *FRICTION: ANISOTROPIC is not supported by inpact yet")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:36: error: *CONTACT PAIR: TYPE=MASSLESS (CalculiX's contact of explicit "
                                "dynamics) is not supported"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:29:1: error: *FRICTION: rate-, pressure- or temperature-dependent friction")) << r.report();
}

TEST(ContactKeywords, CalculixMortarRunsAsSurfaceToSurfaceWithAWarning) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*CONTACT PAIR, INTERACTION=I, TYPE=MORTAR\nTOP, BOTTOM\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.contact_pairs.at(0).type, model::ContactDiscretization::SurfaceToSurface);
  EXPECT_TRUE(has_diagnostic(r, "warning: *CONTACT PAIR: TYPE=MORTAR (CalculiX's mortar contact) runs as inpact's "
                                "SURFACE TO SURFACE"))
      << r.report();
}

TEST(ContactKeywordErrors, SubOptionsNeedTheirParent) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*FRICTION\n0.1\n*CONTACT INCLUSIONS, ALL EXTERIOR\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:1: error: *FRICTION: must follow *SURFACE INTERACTION")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *CONTACT INCLUSIONS: must follow *CONTACT")) << r.report();
}

TEST(ContactKeywordErrors, UndefinedReferencesAreFoundWhenTheDeckIsComplete) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*CONTACT PAIR, INTERACTION=NOPE, ADJUST=NOSET\nTOP, BOTOM\n"
                                 "*CLEARANCE, SLAVE=BOTTOM, MASTER=TOP, VALUE=0.1\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:1: error: *CONTACT PAIR: surface 'BOTOM' is not defined (did you mean 'BOTTOM'?)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:28: error: *CONTACT PAIR: surface interaction 'NOPE' is not defined"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:41: error: *CONTACT PAIR: node set 'NOSET' is not defined")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *CLEARANCE: no *CONTACT PAIR has slave 'BOTTOM' and master 'TOP'"))
      << r.report();
}

// An undefined name is reported where the deck writes it: INTERACTION= (and GEOMETRIC
// CORRECTION=) on the *CONTACT PAIR keyword line, not the pair's data line; the third field of a
// *CONTACT PROPERTY ASSIGNMENT data line. Line 20 is the keyword line, NOPE starts at column 28.
TEST(ContactKeywordErrors, AnUndefinedNameIsReportedWhereItIsWritten) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*CONTACT PAIR, INTERACTION=NOPE\nTOP, BOTTOM\n"
                                 "*SURFACE INTERACTION, NAME=I\n"
                                 "*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE, GEOMETRIC CORRECTION=NOSM\n"
                                 "TOP, BOTTOM\n"
                                 "*CONTACT\n*CONTACT INCLUSIONS, ALL EXTERIOR\n*CONTACT PROPERTY ASSIGNMENT\n, , NOPE2\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:28: error: *CONTACT PAIR: surface interaction 'NOPE' is not defined"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:77: error: *CONTACT PAIR: surface smoothing 'NOSM' is not defined"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:28:5: error: *CONTACT PROPERTY ASSIGNMENT: surface interaction 'NOPE2' is not "
                                "defined"))
      << r.report();
}

TEST(ContactKeywordErrors, ContactControlsBelongInAStep) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*CONTACT CONTROLS, STIFFNESS SCALE FACTOR=0.5\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:1: error: *CONTACT CONTROLS: not allowed in the model data")) << r.report();
}

// ---- step level ----

TEST(ContactKeywords, ContactControlsAndPairsInAStep) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n" + kStep +
                                 "*CONTACT CONTROLS, STIFFNESS SCALE FACTOR=0.25, RELATIVE PENETRATION TOLERANCE=0.01\n"
                                 "*CONTACT CONTROLS, SECONDARY=TOP, MAIN=BOTTOM, ABSOLUTE PENETRATION TOLERANCE=1e-4\n"
                                 "*CONTACT CONTROLS, STIFFNESS SCALE FACTOR=USER ADAPTIVE, RESET\n"
                                 "*CONTACT PAIR, INTERACTION=I\nTOP, BOTTOM\n" +
                                 kEndStep));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps.size(), 1u);
  const auto& s = r.model.steps[0];
  ASSERT_EQ(s.contact_controls.size(), 3u);
  EXPECT_DOUBLE_EQ(*s.contact_controls[0].stiffness_scale_factor, 0.25);
  EXPECT_DOUBLE_EQ(*s.contact_controls[0].relative_penetration_tolerance, 0.01);
  EXPECT_TRUE(s.contact_controls[0].slave.empty());
  EXPECT_EQ(s.contact_controls[1].slave, "TOP");
  EXPECT_EQ(s.contact_controls[1].master, "BOTTOM");
  EXPECT_DOUBLE_EQ(*s.contact_controls[1].absolute_penetration_tolerance, 1e-4);
  EXPECT_TRUE(s.contact_controls[2].user_adaptive_stiffness);
  EXPECT_TRUE(s.contact_controls[2].reset);
  EXPECT_EQ(s.contact_pairs.size(), 1u);
  EXPECT_TRUE(r.model.contact_pairs.empty());
}

TEST(ContactKeywordErrors, ContactControlsChecks) {
  DeckDir dir;
  auto r = dir.read(contact_deck(kStep +
                                 "*CONTACT CONTROLS, ABSOLUTE PENETRATION TOLERANCE=1e-4, RELATIVE PENETRATION TOLERANCE=0.01\n"
                                 "*CONTACT CONTROLS, SLAVE=TOP\n*CONTACT CONTROLS, STABILIZE=USER ADAPTIVE\n*CONTACT\n" + kEndStep));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:88: error: *CONTACT CONTROLS: ABSOLUTE and RELATIVE PENETRATION TOLERANCE are "
                                "mutually exclusive"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:1: error: *CONTACT CONTROLS: SLAVE= and MASTER=")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:30: error: *CONTACT CONTROLS: STABILIZE=USER ADAPTIVE (a factor varying over the iterations) "
                                "is not supported yet")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:25:1: error: *CONTACT: general contact in a step")) << r.report();
}

// *CONTACT STABILIZATION (parameters, surface lines) and *CONTACT CONTROLS, STABILIZE (factor,
// TANGENT FRACTION, its data line) as the model keeps them; defaults where nothing is given.
TEST(ContactKeywords, ContactStabilizationForms) {
  DeckDir dir;
  auto r = dir.read(contact_deck("*AMPLITUDE, NAME=A\n0, 1, 1, 0\n" + kStep +
                                 "*CONTACT STABILIZATION\n"
                                 "*CONTACT STABILIZATION, AMPLITUDE=A, RANGE=0.2, REDUCTION PER INCREMENT=0.5, "
                                 "SCALE FACTOR=3, TANGENT FRACTION=0.25\nTOP, BOTTOM\n, \n"
                                 "*CONTACT STABILIZATION, RESET\n"
                                 "*CONTACT CONTROLS, SLAVE=TOP, MASTER=BOTTOM, STABILIZE=2, TANGENT FRACTION=0.5\n"
                                 "0.7, 0.1, 0.3\n"
                                 "*CONTACT CONTROLS, STABILIZE\n" +
                                 kEndStep));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.steps.at(0);
  ASSERT_EQ(s.contact_stabilizations.size(), 3u);
  const auto& plain = s.contact_stabilizations[0];
  EXPECT_TRUE(plain.amplitude.empty());
  EXPECT_FALSE(plain.range);
  EXPECT_DOUBLE_EQ(plain.reduction_per_increment, 0.1);
  EXPECT_DOUBLE_EQ(plain.scale_factor, 1.0);
  EXPECT_DOUBLE_EQ(plain.tangent_fraction, 0.0);
  EXPECT_TRUE(plain.surfaces.empty());
  const auto& full = s.contact_stabilizations[1];
  EXPECT_EQ(full.amplitude, "A");
  EXPECT_DOUBLE_EQ(*full.range, 0.2);
  EXPECT_DOUBLE_EQ(full.reduction_per_increment, 0.5);
  EXPECT_DOUBLE_EQ(full.scale_factor, 3.0);
  EXPECT_DOUBLE_EQ(full.tangent_fraction, 0.25);
  ASSERT_EQ(full.surfaces.size(), 2u);
  EXPECT_EQ(full.surfaces[0], (std::pair<std::string, std::string>{"TOP", "BOTTOM"}));
  EXPECT_EQ(full.surfaces[1], (std::pair<std::string, std::string>{"", ""}));
  EXPECT_TRUE(s.contact_stabilizations[2].reset);
  ASSERT_EQ(s.contact_controls.size(), 2u);
  const auto& pair = s.contact_controls[0];
  EXPECT_DOUBLE_EQ(*pair.stabilize, 2.0);
  EXPECT_DOUBLE_EQ(*pair.tangent_fraction, 0.5);
  EXPECT_DOUBLE_EQ(*pair.stabilize_coefficient, 0.7);
  EXPECT_DOUBLE_EQ(*pair.stabilize_end_factor, 0.1);
  EXPECT_DOUBLE_EQ(*pair.stabilize_range, 0.3);
  EXPECT_DOUBLE_EQ(*s.contact_controls[1].stabilize, 1.0);
  EXPECT_FALSE(s.contact_controls[1].tangent_fraction);
}
