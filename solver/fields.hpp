#pragma once
/// The fields whose convergence Abaqus checks apart ([AX] "Convergence criteria for nonlinear
/// problems": "separate checks for each field"): the displacements with their forces, and the
/// rotations of beams and shells with their moments. A moment and a force differ by a length,
/// so measured together the larger unit would set the tolerance of the other.
#include <array>
#include <cstddef>

namespace inpact::solver {

enum Field : std::size_t { kDisplacementField = 0, kRotationField = 1 };
inline constexpr std::size_t kFields = 2;

/// One value per field.
using PerField = std::array<double, kFields>;

}  // namespace inpact::solver
