#include "transform.hpp"

#include <algorithm>
#include <cmath>

namespace inpact::model {

namespace {

using V = std::array<double, 3>;

V cross(const V& a, const V& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// v made a unit vector; false when it is (numerically) zero against `scale`.
bool normalize(V& v, double scale) {
  const double l = std::sqrt(dot(v, v));
  if (!(l > 1e-12 * scale)) return false;
  for (double& c : v) c /= l;
  return true;
}

}  // namespace

bool local_axes(const NodalTransform& t, const std::array<double, 3>& x, std::array<std::array<double, 3>, 3>& e) {
  const double scale = std::max({std::sqrt(dot(t.a, t.a)), std::sqrt(dot(t.b, t.b)), std::sqrt(dot(x, x)), 1.0});
  if (t.type == NodalTransform::Type::Rectangular) {
    V e1 = t.a;
    if (!normalize(e1, scale)) return false;
    V e2{t.b[0] - dot(t.b, e1) * e1[0], t.b[1] - dot(t.b, e1) * e1[1], t.b[2] - dot(t.b, e1) * e1[2]};
    if (!normalize(e2, scale)) return false;
    e = {e1, e2, cross(e1, e2)};
    return true;
  }
  V e3{t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
  if (!normalize(e3, scale)) return false;
  const V w{x[0] - t.a[0], x[1] - t.a[1], x[2] - t.a[2]};
  const double along = dot(w, e3);
  V e1{w[0] - along * e3[0], w[1] - along * e3[1], w[2] - along * e3[2]};
  if (!normalize(e1, scale)) return false;
  e = {e1, cross(e3, e1), e3};
  return true;
}

}  // namespace inpact::model
