#include "elastic_stiffness.hpp"

#include <cmath>

namespace inpact::model {

namespace {

double& at(Stiffness& d, int i, int j) { return d[static_cast<std::size_t>(i * 6 + j)]; }

Stiffness isotropic(double e, double nu) {
  Stiffness d{};
  const double mu = e / (2 * (1 + nu)), lambda = e * nu / ((1 + nu) * (1 - 2 * nu));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) at(d, i, j) = lambda;
    at(d, i, i) = lambda + 2 * mu;
    at(d, i + 3, i + 3) = mu;
  }
  return d;
}

/// The inverse of the normal block of the orthotropic compliance, by cofactors.
Stiffness engineering_constants(const std::vector<double>& c) {
  const double e1 = c[0], e2 = c[1], e3 = c[2], n12 = c[3], n13 = c[4], n23 = c[5];
  const double s[3][3] = {{1 / e1, -n12 / e1, -n13 / e1}, {-n12 / e1, 1 / e2, -n23 / e2}, {-n13 / e1, -n23 / e2, 1 / e3}};
  const double det = s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) - s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
                     s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
  Stiffness d{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      at(d, i, j) = (s[i1][j1] * s[i2][j2] - s[i1][j2] * s[i2][j1]) / det;  // adj(S)ᵢⱼ = cof(S)ⱼᵢ
    }
  at(d, 3, 3) = c[6];
  at(d, 4, 4) = c[7];
  at(d, 5, 5) = c[8];
  return d;
}

Stiffness orthotropic(const std::vector<double>& c) {
  Stiffness d{};
  at(d, 0, 0) = c[0];
  at(d, 0, 1) = at(d, 1, 0) = c[1];
  at(d, 1, 1) = c[2];
  at(d, 0, 2) = at(d, 2, 0) = c[3];
  at(d, 1, 2) = at(d, 2, 1) = c[4];
  at(d, 2, 2) = c[5];
  at(d, 3, 3) = c[6];
  at(d, 4, 4) = c[7];
  at(d, 5, 5) = c[8];
  return d;
}

// Column j of the upper triangle holds rows 0..j: D(0,0); D(0,1), D(1,1); D(0,2), D(1,2), D(2,2); …
Stiffness anisotropic(const std::vector<double>& c) {
  Stiffness d{};
  std::size_t k = 0;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i <= j; ++i) at(d, i, j) = at(d, j, i) = c[k++];
  return d;
}

Stiffness lamina(const std::vector<double>& c) {
  const double e1 = c[0], e2 = c[1], n12 = c[2];
  const double n21 = n12 * e2 / e1, q = 1 / (1 - n12 * n21);
  Stiffness d{};
  at(d, 0, 0) = e1 * q;
  at(d, 1, 1) = e2 * q;
  at(d, 0, 1) = at(d, 1, 0) = n12 * e2 * q;
  at(d, 3, 3) = c[3];
  at(d, 4, 4) = c[4];
  at(d, 5, 5) = c[5];
  return d;
}

}  // namespace

std::size_t elastic_constant_count(Elastic::Type type) {
  switch (type) {
    case Elastic::Type::Isotropic: return 2;
    case Elastic::Type::EngineeringConstants:
    case Elastic::Type::Orthotropic: return 9;
    case Elastic::Type::Anisotropic: return 21;
    case Elastic::Type::Lamina: return 6;
  }
  return 0;
}

Stiffness material_stiffness(const Elastic& elastic) {
  switch (elastic.type) {
    case Elastic::Type::Isotropic: return isotropic(elastic.youngs_modulus, elastic.poissons_ratio);
    case Elastic::Type::EngineeringConstants: return engineering_constants(elastic.constants);
    case Elastic::Type::Orthotropic: return orthotropic(elastic.constants);
    case Elastic::Type::Anisotropic: return anisotropic(elastic.constants);
    case Elastic::Type::Lamina: return lamina(elastic.constants);
  }
  return {};
}

bool positive_definite(const Stiffness& d) {
  double l[6][6] = {};
  for (int j = 0; j < 6; ++j) {
    double diag = d[static_cast<std::size_t>(j * 6 + j)];
    for (int k = 0; k < j; ++k) diag -= l[j][k] * l[j][k];
    if (!(diag > 0)) return false;
    l[j][j] = std::sqrt(diag);
    for (int i = j + 1; i < 6; ++i) {
      double v = d[static_cast<std::size_t>(i * 6 + j)];
      for (int k = 0; k < j; ++k) v -= l[i][k] * l[j][k];
      l[i][j] = v / l[j][j];
    }
  }
  return true;
}

}  // namespace inpact::model
