// GAMG's near null space (solver/linear/rigid_body_modes.hpp): every mode is a motion the model
// resists with no force. On free models (no boundary condition) of shells, beams and solids,
// the internal force of a small displacement along each mode is under 1e-7 of that of a
// deformation of the same size (round-off on the beam and the solid; 3e-9 on the warped S4
// plate, whose source was not traced); with the rotation nodes moved like displacement nodes
// (PETSc's own modes) a rotation strains the model: over 1e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/dof_map.hpp"
#include "solver/linear/rigid_body_modes.hpp"
#include "solver/linear_solve.hpp"
#include "solver/step_conditions.hpp"

namespace inpact {
namespace {

using test::DeckDir;

const std::string kShell = R"(*NODE
1, 0, 0, 0
2, 1, 0, 0.1
3, 2, 0, 0
4, 0, 1, 0.2
5, 1, 1, 0
6, 2, 1.1, 0
*ELEMENT, TYPE=S4, ELSET=PLATE
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL
0.05
*STEP
*STATIC
*END STEP
)";

const std::string kBeam = R"(*NODE
1, 0, 0, 0
2, 1, 0.2, 0
3, 2, 0.1, 0.3
*ELEMENT, TYPE=B31, ELSET=BEAM
1, 1, 2
2, 2, 3
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT
0.1, 0.2
0., 0., -1.
*STEP
*STATIC
*END STEP
)";

const std::string kSolid = R"(*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1.2
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL
*STEP
*STATIC
*END STEP
)";

struct FreeModel {
  explicit FreeModel(const std::string& deck)
      : read(dir.read(deck)), am(solver::build_analysis_model(read.model)),
        conditions(am, read.model.steps[0], solver::initial_history(am), 0.0),
        dofs(solver::DofMap::build(am, conditions.prescribed())), assembler(am, dofs) {}
  DeckDir dir;
  parser::ReadResult read;
  solver::AnalysisModel am;
  solver::StepConditions conditions;
  solver::DofMap dofs;
  solver::Assembler assembler;

  /// |f_int(u)|, small strain.
  double force(const std::vector<double>& u) {
    std::vector<double> f(am.n_dof(), 0.0);
    assembler.assemble(u, {.tangent = false, .nlgeom = false, .delta_t = {}, .points = false}, f);
    double sum = 0.0;
    for (double v : f) sum += v * v;
    return std::sqrt(sum);
  }
  /// What the PETSc path is given (3 coordinates a node: these models are 3D).
  solver::EquationPoints points() const { return solver::equation_points(am, dofs); }
};

/// Every mode's force, against a deformation's (every unknown 1e-6 × its index) of the same norm.
void expect_force_free(const std::string& deck, bool with_rotation_nodes) {
  FreeModel m(deck);
  ASSERT_TRUE(m.read.ok()) << m.read.report();
  const solver::EquationPoints p = m.points();
  EXPECT_EQ(!p.rotation.empty(), with_rotation_nodes);
  const auto modes = solver::rigid_body_modes(m.am.dim, p.coordinates, p.rotation);
  ASSERT_EQ(modes.size(), 6u);
  for (std::size_t k = 0; k < modes.size(); ++k) {
    double size = 0.0;
    for (double v : modes[k]) size += v * v;
    std::vector<double> u(modes[k].size()), strained(modes[k].size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      u[i] = 1e-6 * modes[k][i] / std::sqrt(size);
      strained[i] = 1e-6 * std::sin(1.0 + static_cast<double>(i)) / std::sqrt(0.5 * static_cast<double>(u.size()));
    }
    EXPECT_LT(m.force(u), 1e-7 * m.force(strained)) << "mode " << k;
  }
  if (!with_rotation_nodes) return;
  // Rotation nodes moved like the others (PETSc's own modes): a rotation then strains the model.
  const auto as_displacements = solver::rigid_body_modes(m.am.dim, p.coordinates, {});
  for (std::size_t k = 3; k < 6; ++k) {
    double size = 0.0;
    for (double v : as_displacements[k]) size += v * v;
    std::vector<double> u(as_displacements[k].size()), strained(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      u[i] = 1e-6 * as_displacements[k][i] / std::sqrt(size);
      strained[i] = 1e-6 * std::sin(1.0 + static_cast<double>(i)) / std::sqrt(0.5 * static_cast<double>(u.size()));
    }
    EXPECT_GT(m.force(u), 1e-3 * m.force(strained)) << "mode " << k;
  }
}

TEST(RigidBodyModes, AFreeShellResistsNone) { expect_force_free(kShell, true); }
TEST(RigidBodyModes, AFreeBeamResistsNone) { expect_force_free(kBeam, true); }
TEST(RigidBodyModes, AFreeSolidResistsNone) { expect_force_free(kSolid, false); }

}  // namespace
}  // namespace inpact
