#pragma once
/// The stiffness of an *ELASTIC definition in its material axes. Plain arrays (the model has no
/// Eigen): the parser checks the constants with it (parser/elastic_stability.hpp), the solver
/// builds its material laws from it.
///
/// Voigt order 11, 22, 33, 12, 13, 23 with engineering shear strains, σ = D ε, as Abaqus
/// writes D (D1212 = G12).
#include <array>
#include <cstddef>

#include "material.hpp"

namespace inpact::model {

using Stiffness = std::array<double, 36>;  ///< 6 × 6, row-major

/// The number of constants one temperature of `type` has (E, ν: 2; engineering constants and
/// orthotropic: 9; anisotropic: 21; lamina: 6).
std::size_t elastic_constant_count(Elastic::Type type);

/// The 3D stiffness in the material axes. ISOTROPIC: λ + 2μ, λ, μ; ENGINEERING CONSTANTS: the
/// inverse of the compliance (S11 = 1/E1, S12 = −ν12/E1, S13 = −ν13/E1, S23 = −ν23/E2,
/// S44 = 1/G12, S55 = 1/G13, S66 = 1/G23); ORTHOTROPIC and ANISOTROPIC: the D's as given.
/// LAMINA has no 3D stiffness: the plane-stress one in the 11, 22, 12 rows and columns (E1/(1 −
/// ν12ν21) …), G13 and G23 for 13 and 23, and zero for 33.
Stiffness material_stiffness(const Elastic& elastic);

/// Whether the symmetric 6 × 6 matrix is positive definite (Cholesky).
bool positive_definite(const Stiffness& d);

}  // namespace inpact::model
