#include "hourglass.hpp"

namespace inpact::solver::elements {
namespace {

// Parametric corner signs in Abaqus node order.
constexpr double kHex[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr double kQuad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

}  // namespace

Eigen::MatrixXd hourglass_shape_vectors(int dim, const Eigen::MatrixXd& x, const Eigen::MatrixXd& b) {
  const int n = dim == 3 ? 8 : 4;
  const int n_modes = dim == 3 ? 4 : 1;
  Eigen::MatrixXd h(n_modes, n);
  for (int a = 0; a < n; ++a) {
    if (dim == 3) {
      const double* s = kHex[a];
      h(0, a) = s[0] * s[1];
      h(1, a) = s[0] * s[2];
      h(2, a) = s[1] * s[2];
      h(3, a) = s[0] * s[1] * s[2];
    } else {
      h(0, a) = kQuad[a][0] * kQuad[a][1];
    }
  }
  // γ = (h − (h·x_i) b_iᵀ) / n: hx(α, i) = h_α · x_i.
  const Eigen::MatrixXd hx = h * x;  // n_modes × dim
  return (h - hx * b.transpose()) / n;
}

Eigen::MatrixXd hourglass_stiffness(int dim, const Eigen::MatrixXd& x, const Eigen::MatrixXd& b, double volume,
                                    double shear_modulus, double scale) {
  const Eigen::MatrixXd gamma = hourglass_shape_vectors(dim, x, b);
  const int n = static_cast<int>(x.rows());
  const double k = scale * shear_modulus * volume * b.squaredNorm();
  const Eigen::MatrixXd kg = k * gamma.transpose() * gamma;  // n × n
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n * dim, n * dim);
  for (int a = 0; a < n; ++a)
    for (int c = 0; c < n; ++c)
      for (int i = 0; i < dim; ++i) K(a * dim + i, c * dim + i) = kg(a, c);
  return K;
}

}  // namespace inpact::solver::elements
