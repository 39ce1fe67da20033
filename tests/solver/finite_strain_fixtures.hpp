#pragma once
// What the finite-strain material tests share: a material point evaluated at a deformation
// gradient (the element's Green–Lagrange strain from F, NLGEOM), its initial state, and the
// stretch √C of a Green–Lagrange strain (to perturb E while keeping a rotation apart), and a
// state with plastic history.
#include <vector>

#include <Eigen/Dense>

#include "solver/elements/material.hpp"

namespace inpact::test::finite_strain {

using solver::elements::Mat6;
using solver::elements::Material;
using solver::elements::Vec6;

struct Eval {
  Vec6 stress;  ///< S
  Mat6 tangent;
  std::vector<double> trial;
};

inline Vec6 green_lagrange(const Eigen::Matrix3d& F) {
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  return (Vec6() << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(0, 2), 2 * E(1, 2)).finished();
}

inline Eval evaluate(const Material& m, const std::vector<double>& committed, const Eigen::Matrix3d& F) {
  Eval e;
  e.trial.assign(committed.size(), -1.0);
  const Vec6 strain = green_lagrange(F);
  Mat6 scratch;
  e.tangent = m.update({F, strain, 0.0, nullptr, true}, {committed, e.trial}, e.stress, scratch);
  return e;
}

inline std::vector<double> initial(const Material& m) {
  std::vector<double> s(m.state_size());
  m.initial_state(s);
  return s;
}

/// √C of C = I + 2E (E in Voigt form, engineering shear).
inline Eigen::Matrix3d stretch_of(const Vec6& E) {
  Eigen::Matrix3d C;
  C << 1 + 2 * E(0), E(3), E(4), E(3), 1 + 2 * E(1), E(5), E(4), E(5), 1 + 2 * E(2);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).operatorSqrt();
}

/// A committed state with plastic history: one plastic increment in shear and tension.
inline std::vector<double> plastic_history(const Material& m) {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 1.02, F(0, 1) = 0.03, F(1, 1) = 0.995, F(2, 0) = 0.004;
  return evaluate(m, initial(m), F).trial;
}

}  // namespace inpact::test::finite_strain
