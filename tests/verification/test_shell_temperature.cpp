// A temperature through a shell's thickness (*TEMPERATURE's third field, the gradient ∂T/∂n):
// the thermal strain α (ΔT + z g) at z from the reference surface. A free 10 × 1 strip (S4 and
// S8R, t = 0.1, α = 1e-5, E = 2e5, ν = 0.3) held at one corner only bends without stress into
// w = −α g (x² + y²)/2 and stretches by α ΔT; a fully held one carries σ = −E α (ΔT + z g)/(1 − ν)
// at its section points. Both exact: to 1e-7 of the largest displacement (the round-off of a
// thin strip held at one corner) and 1e-9 of the stress.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_model.hpp"
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double kAlpha = 1e-5, kE = 2e5, kNu = 0.3, kT = 0.1;

/// The strip of ten elements along x, width 1, with `hold` (*BOUNDARY lines) and the temperature
/// line `temperature` (node set ALL) after an initial 0.
std::string strip(const std::string& type, const std::string& hold, const std::string& temperature, double offset) {
  const bool quadratic = type == "S8R";
  std::string d = "*NODE, NSET=ALL\n";
  // Corner nodes 1..11 (y = 0) and 101..111 (y = 1); S8R's midside nodes 201.. (y = 0), 301..
  // (y = 1) at the half x, and 401..411 at y = 0.5.
  for (int i = 0; i <= 10; ++i) {
    d += fmt::format("{}, {}, 0., 0.\n{}, {}, 1., 0.\n", i + 1, i, i + 101, i);
    if (quadratic) {
      d += fmt::format("{}, {}, 0.5, 0.\n", i + 401, i);
      if (i < 10) d += fmt::format("{}, {}, 0., 0.\n{}, {}, 1., 0.\n", i + 201, i + 0.5, i + 301, i + 0.5);
    }
  }
  d += fmt::format("*ELEMENT, TYPE={}, ELSET=STRIP\n", type);
  for (int i = 0; i < 10; ++i)
    d += quadratic ? fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, i + 1, i + 2, i + 102, i + 101, i + 201,
                                 i + 402, i + 301, i + 401)
                   : fmt::format("{}, {}, {}, {}, {}\n", i + 1, i + 1, i + 2, i + 102, i + 101);
  d += fmt::format("*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n*EXPANSION\n{}\n", kE, kNu, kAlpha);
  d += fmt::format("*SHELL SECTION, ELSET=STRIP, MATERIAL=M, OFFSET={}\n{}\n", offset, kT);
  d += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 0.\n*BOUNDARY\n" + hold;
  d += "*STEP\n*STATIC\n*TEMPERATURE\nALL, " + temperature + "\n*NODE PRINT, NSET=ALL\nU\n*EL PRINT\nS\n*OUTPUT, FIELD\n"
       "*NODE OUTPUT\nU\n*ELEMENT OUTPUT\nS\n*END STEP\n";
  return d;
}

std::unique_ptr<Run> run_text(const std::string& text) {
  const test::DeckDir dir;
  return run_deck(dir.write("deck.inp", text));
}

// Held at node 1 alone, ΔT = 50 on the reference surface and g = 100: u = α ΔT x, v = α ΔT y and
// w = −α g (x² + y²)/2 (the hotter +n side lengthens, so the strip curves toward −n), no stress.
// The reference surface at SPOS (OFFSET=0.5) gives the same (ΔT is given there).
TEST(ShellTemperature, AFreeStripBendsWithoutStress) {
  for (const std::string type : {"S4", "S8R"})
    for (double offset : {0.0, 0.5}) {
      const auto r = run_text(strip(type, "1, ENCASTRE\n", "50., 100.", offset));
      ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
      const solver::Frame& f = *r->capture.of_step(1).back();
      const auto& nodes = r->model().mesh.nodes;
      for (const std::int32_t row : nset(r->model(), "ALL")) {  // not the rotation nodes
        const auto n = static_cast<std::size_t>(row);
        const double x = nodes.coords[n][0], y = nodes.coords[n][1];
        const double w = -kAlpha * 100 * (x * x + y * y) / 2;
        EXPECT_NEAR(nodal(f, "U", n, 0), kAlpha * 50 * x, 1e-7 * 0.05) << type << " node " << nodes.labels[n];
        EXPECT_NEAR(nodal(f, "U", n, 1), kAlpha * 50 * y, 1e-7 * 0.05) << type << " node " << nodes.labels[n];
        EXPECT_NEAR(nodal(f, "U", n, 2), w, 1e-7 * 0.05) << type << " node " << nodes.labels[n];
      }
      const double stress_scale = kE * kAlpha * 100 * kT;
      for (double s : field(f, "S")->values) EXPECT_NEAR(s, 0.0, 1e-9 * stress_scale) << type;
    }
}

// A later *TEMPERATURE line without the gradient sets it to 0: the strip straightens again and
// keeps its stretch.
// The same after OP=NEW, which drops the earlier definitions first.
TEST(ShellTemperature, ALineWithoutTheGradientSetsItToZero) {
  for (const std::string keyword : {"*TEMPERATURE", "*TEMPERATURE, OP=NEW"}) {
    const auto r = run_text(strip("S4", "1, ENCASTRE\n", "50., 100.", 0.0) + "*STEP\n*STATIC\n" + keyword +
                            "\nALL, 50.\n*END STEP\n");
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::Frame& f = *r->capture.of_step(2).back();
    for (const std::int32_t row : nset(r->model(), "ALL")) {
      const auto n = static_cast<std::size_t>(row);
      EXPECT_NEAR(nodal(f, "U", n, 0), kAlpha * 50 * r->model().mesh.nodes.coords[n][0], 1e-7 * 0.05) << keyword;
      EXPECT_NEAR(nodal(f, "U", n, 2), 0.0, 1e-7 * 0.05) << keyword;
    }
  }
}

// A gradient at a node no shell uses would be ignored: a warning names the line and the node.
TEST(ShellTemperature, AGradientOffTheShellsIsAWarning) {
  const test::DeckDir dir;
  const auto r = dir.read(test::one_cube_deck() + "*STEP\n*STATIC\n*TEMPERATURE\n1, 10., 5.\n*END STEP\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  ASSERT_EQ(am.warnings.size(), 1u);
  EXPECT_NE(am.warnings[0].find("the temperature gradient at node 1 is ignored: no shell element uses the node"),
            std::string::npos)
      << am.warnings[0];
}

// Every node held: S11 = S22 = −E α (ΔT + z g)/(1 − ν) at SNEG (z = −t/2) and SPOS (z = t/2).
TEST(ShellTemperature, AHeldStripCarriesTheThermalStressThroughItsThickness) {
  for (const std::string type : {"S4", "S8R"}) {
    const auto r = run_text(strip(type, "ALL, ENCASTRE\n", "50., 100.", 0.0));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::FieldData& s = *field(*r->capture.of_step(1).back(), "S");
    const std::size_t n = s.component_labels.size();
    for (std::size_t i = 0; i < s.elements.size(); ++i) {
      ASSERT_TRUE(s.section_point[i] == 1 || s.section_point[i] == 5) << s.section_point[i];  // SNEG, SPOS
      const double z = s.section_point[i] == 1 ? -kT / 2 : kT / 2;
      const double expected = -kE * kAlpha * (50 + z * 100) / (1 - kNu);
      EXPECT_NEAR(s.values[i * n + 0], expected, 1e-9 * std::abs(expected)) << type << " ip " << s.ip[i];
      EXPECT_NEAR(s.values[i * n + 1], expected, 1e-9 * std::abs(expected)) << type << " ip " << s.ip[i];
    }
  }
}

// The held strip of a material whose E and α depend on temperature (E = 2e5 − 1e3 T, α = 1e-5 +
// 1e-7 T from rows at 0 and 100, reference temperature 0): S11 = −E(T) ε_th/(1 − ν) with ε_th =
// α(T) T − α(Tᴵ) Tᴵ at each section point's own T = 50 + 100 z, from an initial 0 and from an
// initial 20 + 40 z (the gradient of *INITIAL CONDITIONS), to 1e-9. A COMPOSITE of two layers of
// the material reads them alike (its SNEG and SPOS are section points 1 and 6).
TEST(ShellTemperature, TemperatureTablesAreReadAtEachSectionPoint) {
  const std::string constant = fmt::format("*ELASTIC\n{}, {}\n*EXPANSION\n{}\n", kE, kNu, kAlpha);
  const std::string tables = "*ELASTIC\n2e5, 0.3, 0.\n1e5, 0.3, 100.\n*EXPANSION\n1e-5, 0.\n2e-5, 100.\n";
  const auto E = [](double T) { return 2e5 - 1e3 * T; };
  const auto alpha = [](double T) { return 1e-5 + 1e-7 * T; };
  const std::string single = fmt::format("*SHELL SECTION, ELSET=STRIP, MATERIAL=M, OFFSET={}\n{}\n", 0.0, kT);
  const std::string layered = "*SHELL SECTION, ELSET=STRIP, COMPOSITE\n0.05, 3, M\n0.05, 3, M\n";
  for (const std::string type : {"S4", "S8R"})
    for (const auto& [t0, g0, composite] : {std::tuple{0.0, 0.0, false}, std::tuple{20.0, 40.0, false},
                                            std::tuple{0.0, 0.0, true}, std::tuple{20.0, 40.0, true}}) {
      std::string deck = strip(type, "ALL, ENCASTRE\n", "50., 100.", 0.0);
      deck.replace(deck.find(constant), constant.size(), tables);
      if (composite) deck.replace(deck.find(single), single.size(), layered);
      const std::string initial = "TYPE=TEMPERATURE\nALL, 0.\n";
      deck.replace(deck.find(initial), initial.size(), fmt::format("TYPE=TEMPERATURE\nALL, {}, {}\n", t0, g0));
      const auto r = run_text(deck);
      ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
      const solver::FieldData& s = *field(*r->capture.of_step(1).back(), "S");
      const std::size_t n = s.component_labels.size();
      ASSERT_FALSE(s.elements.empty()) << type;
      for (std::size_t i = 0; i < s.elements.size(); ++i) {
        ASSERT_TRUE(s.section_point[i] == 1 || s.section_point[i] == (composite ? 6 : 5)) << s.section_point[i];
        const double z = s.section_point[i] == 1 ? -kT / 2 : kT / 2;
        const double T = 50 + 100 * z, Ti = t0 + g0 * z;
        const double expected = -E(T) * (alpha(T) * T - alpha(Ti) * Ti) / (1 - kNu);
        EXPECT_NEAR(s.values[i * n], expected, 1e-9 * std::abs(expected)) << type << " T0 " << t0 << " z " << z << (composite ? " composite" : "");
      }
    }
}

// *ELEMENT OUTPUT with a section-point line reports those points, numbered from SNEG (1) to SPOS
// (5) through the default five: the same closed form at z = t (k − 3)/4, and at each in-plane
// point exactly the points asked for, in order. *EL PRINT keeps Abaqus's default, SNEG and SPOS.
TEST(ShellTemperature, SectionPointsAskedForAreReportedThroughTheThickness) {
  for (const std::string type : {"S4", "S8R"}) {
    std::string deck = strip(type, "ALL, ENCASTRE\n", "50., 100.", 0.0);
    const std::string asked = "*ELEMENT OUTPUT\nS\n";
    deck.replace(deck.find(asked), asked.size(),
                 "*ELEMENT OUTPUT\n2, 3, 4\nS\n*ELEMENT OUTPUT, ELSET=STRIP\n5, 7\nS\n");
    const auto r = run_text(deck);
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::FieldData& s = *field(*r->capture.of_step(1).back(), "S");
    const std::size_t n = s.component_labels.size(), in_plane = 4;  // 2 × 2 in-plane points
    ASSERT_EQ(s.elements.size(), 10 * in_plane * 4) << type;  // points 2, 3, 4 and 5 of each
    for (std::size_t i = 0; i < s.elements.size(); ++i) {
      EXPECT_EQ(s.section_point[i], static_cast<std::int32_t>(2 + i % 4)) << type << " location " << i;
      EXPECT_EQ(s.ip[i], static_cast<std::int32_t>(i / 4 % in_plane + 1)) << type << " location " << i;
      const double z = kT * (s.section_point[i] - 3) / 4;
      const double expected = -kE * kAlpha * (50 + z * 100) / (1 - kNu);
      EXPECT_NEAR(s.values[i * n + 0], expected, 1e-9 * std::abs(expected)) << type << " sp " << s.section_point[i];
    }
    // A point no section has (7 of 5) is said once, not silently dropped.
    EXPECT_EQ(std::count_if(r->capture.messages.begin(), r->capture.messages.end(),
                            [](const std::string& m) {
                              return m.find("element output at section point 7 of element set STRIP (none of its "
                                            "shell or beam sections has it)") != std::string::npos;
                            }),
              1);
    // The .dat table: SNEG and SPOS at each in-plane point, S11 of the closed form.
    const solver::PrintTable* table = nullptr;
    for (const auto& t : r->capture.prints.back().tables)
      if (t.at_section_points && t.element_type == type) table = &t;
    ASSERT_TRUE(table) << type;
    ASSERT_EQ(table->section_point.size(), 10 * in_plane * 2) << type;
    for (std::size_t row = 0; row < table->section_point.size(); ++row) {
      const std::int32_t sp = table->section_point[row];
      ASSERT_TRUE(sp == 1 || sp == 5) << sp;
      const double expected = -kE * kAlpha * (50 + (sp == 1 ? -kT / 2 : kT / 2) * 100) / (1 - kNu);
      EXPECT_NEAR(table->values[row * table->columns.size()], expected, 1e-9 * std::abs(expected)) << type;
    }
  }
}

// A section point is looked for in the request's element set: two held S4, element 1 (set A) of
// seven section points, element 2 (set B) of five; point 7 asked of B is said to be missing,
// asked of A it is reported.
TEST(ShellTemperature, ASectionPointIsLookedForInTheRequestsSet) {
  const std::string deck =
      "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n4, 0., 1., 0.\n5, 1., 1., 0.\n6, 2., 1., 0.\n"
      "*ELEMENT, TYPE=S4, ELSET=A\n1, 1, 2, 5, 4\n*ELEMENT, TYPE=S4, ELSET=B\n2, 2, 3, 6, 5\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*SHELL SECTION, ELSET=A, MATERIAL=M\n0.1, 7\n"
      "*SHELL SECTION, ELSET=B, MATERIAL=M\n0.1, 5\n*BOUNDARY\nALL, 1, 6\n*STEP\n*STATIC\n*OUTPUT, FIELD\n"
      "*ELEMENT OUTPUT, ELSET=A\n7\nS\n*ELEMENT OUTPUT, ELSET=B\n7\nS\n*END STEP\n";
  const auto r = run_text(deck);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto said = [&](const std::string& set) {
    return std::count_if(r->capture.messages.begin(), r->capture.messages.end(), [&](const std::string& m) {
      return m.find("element output at section point 7 of element set " + set) != std::string::npos;
    });
  };
  EXPECT_EQ(said("B"), 1);
  EXPECT_EQ(said("A"), 0);
  const solver::FieldData& s = *field(r->capture.last(), "S");
  ASSERT_FALSE(s.elements.empty());
  for (std::size_t i = 0; i < s.elements.size(); ++i) {
    EXPECT_EQ(s.elements[i], 1) << "location " << i;
    EXPECT_EQ(s.section_point[i], 7) << "location " << i;
  }
}

// What a run computes from its points' volumes (here *STATIC, STABILIZE's damping, sized by the
// strain energy ALLSE) does not depend on which section points an output request asks for: the
// same bits either way.
TEST(ShellTemperature, SectionPointsAskedForDoNotChangeAStabilisedRun) {
  std::vector<double> u[2];
  for (int asked = 0; asked < 2; ++asked) {
    // A cantilever (held at x = 0) bent by a tip load: its S is zero at the midsurface, so ALLSE
    // would change if the middle point counted.
    std::string deck = strip("S4", "1, ENCASTRE\n101, ENCASTRE\n", "0., 0.", 0.0);
    deck.replace(deck.find("*STEP\n*STATIC\n"), 14, "*STEP\n*STATIC, STABILIZE\n0.25, 1.\n*CLOAD\n11, 3, 1e-3\n111, 3, 1e-3\n");
    if (asked) deck.replace(deck.find("*ELEMENT OUTPUT\nS\n"), 18, "*ELEMENT OUTPUT\n2, 3, 4\nS\n");
    const auto r = run_text(deck);
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::FieldData* f = field(*r->capture.of_step(1).back(), "U");
    ASSERT_TRUE(f);
    u[asked] = f->values;
  }
  EXPECT_EQ(u[0], u[1]);
}

}  // namespace
}  // namespace inpact::verification
