#include "incompatible_modes.hpp"

namespace inpact::solver::elements {

Eigen::MatrixX3d incompatible_mode_gradients(int dim, const double* xi, const Eigen::MatrixXd& J0_inv_t, double j0,
                                             double j) {
  Eigen::MatrixX3d g = Eigen::MatrixX3d::Zero(dim, 3);
  for (int k = 0; k < dim; ++k) {
    Eigen::VectorXd dm = Eigen::VectorXd::Zero(dim);  // ∂M_k/∂ξ = −2ξ_k e_k
    dm(k) = -2 * xi[k];
    const Eigen::VectorXd gk = (j0 / j) * (J0_inv_t * dm);
    for (int i = 0; i < dim; ++i) g(k, i) = gk(i);
  }
  return g;
}

}  // namespace inpact::solver::elements
