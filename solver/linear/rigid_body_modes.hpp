#pragma once
/// The rigid-body modes of a mesh's displacement unknowns, GAMG's near null space
/// (linear/petsc_solver.cpp). Rotation nodes (beams, shells, rigid bodies, couplings: their
/// components hold the rotation θ, θ3 alone in component 0 in 2D) are turned, not moved: a
/// translation moves every other node and leaves θ; a rotation ω turns the other nodes by
/// ω × x and sets θ = ω. (PETSc's MatNullSpaceCreateRigidBody takes every node for a
/// displacement one: a rotation of a shell model is then no mode of its matrix, and GAMG's
/// iterations grow with the mesh; bench/petsc_solver/README.md, shells.)
#include <span>
#include <vector>

namespace inpact::solver {

/// Mode k (translations first: dim of them, then the rotations: 3 in 3D, 1 in 2D) at node block
/// b is modes[k][b * dim + c]; the blocks' coordinates are coords[b * dim + c], rotation[b] says
/// whether block b is a rotation node (empty: none is). Not normalised.
inline std::vector<std::vector<double>> rigid_body_modes(int dim, std::span<const double> coords,
                                                         std::span<const char> rotation) {
  const std::size_t d = static_cast<std::size_t>(dim), n_blocks = coords.size() / d;
  const int n_modes = dim == 3 ? 6 : 3;
  std::vector<std::vector<double>> modes(static_cast<std::size_t>(n_modes), std::vector<double>(coords.size(), 0.0));
  for (std::size_t b = 0; b < n_blocks; ++b) {
    const bool turns = !rotation.empty() && rotation[b];
    const double* x = &coords[b * d];
    for (int k = 0; k < n_modes; ++k) {
      double* e = &modes[static_cast<std::size_t>(k)][b * d];
      if (k < dim) {  // a translation
        if (!turns) e[k] = 1.0;
      } else if (turns) {  // a rotation about axis k − dim (2D: about z, θ3 in component 0)
        e[dim == 3 ? k - 3 : 0] = 1.0;
      } else if (dim == 2) {
        e[0] = -x[1];
        e[1] = x[0];
      } else {
        const int j = k - 3;  // e_j × x
        e[(j + 1) % 3] = -x[(j + 2) % 3];
        e[(j + 2) % 3] = x[(j + 1) % 3];
      }
    }
  }
  return modes;
}

}  // namespace inpact::solver
