#include "shape_functions.hpp"

#include <stdexcept>

namespace inpact::solver::elements {
namespace {

// Corner signs of the 8-node brick in Abaqus order (Abaqus Theory Manual, "Solid isoparametric
// quadrilaterals and hexahedra"): nodes 1-4 on ζ = -1 counter-clockwise from (-1,-1), 5-8 on ζ = +1.
constexpr double kHexSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
// Midside nodes 9-20 of the 20-node brick: 9-12 on ζ = -1, 13-16 on ζ = +1, 17-20 on the
// vertical edges 1-5, 2-6, 3-7, 4-8.
constexpr double kHex20Mid[12][3] = {{0, -1, -1}, {1, 0, -1}, {0, 1, -1}, {-1, 0, -1},
                                     {0, -1, 1},  {1, 0, 1},  {0, 1, 1},  {-1, 0, 1},
                                     {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0}};
constexpr double kQuadSign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double kQuad8Mid[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};

void hex8(const std::array<double, 3>& x, ShapeValues& v) {
  for (int a = 0; a < 8; ++a) {
    const double* s = kHexSign[a];
    const double p0 = 1 + s[0] * x[0], p1 = 1 + s[1] * x[1], p2 = 1 + s[2] * x[2];
    v.N[a] = p0 * p1 * p2 / 8;
    v.dN[a] = {s[0] * p1 * p2 / 8, p0 * s[1] * p2 / 8, p0 * p1 * s[2] / 8};
  }
}

// Serendipity brick: corners N = (1+ξξa)(1+ηηa)(1+ζζa)(ξξa+ηηa+ζζa-2)/8; a midside node with
// ξa = 0 has N = (1-ξ²)(1+ηηa)(1+ζζa)/4 (and likewise for the other directions).
void hex20(const std::array<double, 3>& x, ShapeValues& v) {
  for (int a = 0; a < 8; ++a) {
    const double* s = kHexSign[a];
    const double p0 = 1 + s[0] * x[0], p1 = 1 + s[1] * x[1], p2 = 1 + s[2] * x[2];
    const double q = s[0] * x[0] + s[1] * x[1] + s[2] * x[2] - 2;
    v.N[a] = p0 * p1 * p2 * q / 8;
    v.dN[a] = {s[0] * p1 * p2 * (q + p0) / 8, s[1] * p0 * p2 * (q + p1) / 8, s[2] * p0 * p1 * (q + p2) / 8};
  }
  for (int m = 0; m < 12; ++m) {
    const double* s = kHex20Mid[m];
    double f[3], df[3];
    for (int j = 0; j < 3; ++j) {
      if (s[j] == 0) {
        f[j] = 1 - x[j] * x[j];
        df[j] = -2 * x[j];
      } else {
        f[j] = 1 + s[j] * x[j];
        df[j] = s[j];
      }
    }
    v.N[8 + m] = f[0] * f[1] * f[2] / 4;
    v.dN[8 + m] = {df[0] * f[1] * f[2] / 4, f[0] * df[1] * f[2] / 4, f[0] * f[1] * df[2] / 4};
  }
}

void quad4(const std::array<double, 3>& x, ShapeValues& v) {
  for (int a = 0; a < 4; ++a) {
    const double* s = kQuadSign[a];
    const double p0 = 1 + s[0] * x[0], p1 = 1 + s[1] * x[1];
    v.N[a] = p0 * p1 / 4;
    v.dN[a] = {s[0] * p1 / 4, p0 * s[1] / 4, 0};
  }
}

void quad8(const std::array<double, 3>& x, ShapeValues& v) {
  for (int a = 0; a < 4; ++a) {
    const double* s = kQuadSign[a];
    const double p0 = 1 + s[0] * x[0], p1 = 1 + s[1] * x[1];
    const double q = s[0] * x[0] + s[1] * x[1] - 1;
    v.N[a] = p0 * p1 * q / 4;
    v.dN[a] = {s[0] * p1 * (q + p0) / 4, s[1] * p0 * (q + p1) / 4, 0};
  }
  for (int m = 0; m < 4; ++m) {
    const double* s = kQuad8Mid[m];
    if (s[0] == 0) {
      const double p1 = 1 + s[1] * x[1];
      v.N[4 + m] = (1 - x[0] * x[0]) * p1 / 2;
      v.dN[4 + m] = {-x[0] * p1, (1 - x[0] * x[0]) * s[1] / 2, 0};
    } else {
      const double p0 = 1 + s[0] * x[0];
      v.N[4 + m] = p0 * (1 - x[1] * x[1]) / 2;
      v.dN[4 + m] = {s[0] * (1 - x[1] * x[1]) / 2, -p0 * x[1], 0};
    }
  }
}

void tri3(const std::array<double, 3>& x, ShapeValues& v) {
  v.N[0] = 1 - x[0] - x[1];
  v.N[1] = x[0];
  v.N[2] = x[1];
  v.dN[0] = {-1, -1, 0};
  v.dN[1] = {1, 0, 0};
  v.dN[2] = {0, 1, 0};
}

// u = (1-g-h)(1-2g-2h)u1 + g(2g-1)u2 + h(2h-1)u3 + 4g(1-g-h)u4 + 4gh u5 + 4h(1-g-h)u6.
void tri6(const std::array<double, 3>& x, ShapeValues& v) {
  const double g = x[0], h = x[1], l = 1 - g - h;
  v.N[0] = l * (2 * l - 1);
  v.N[1] = g * (2 * g - 1);
  v.N[2] = h * (2 * h - 1);
  v.N[3] = 4 * g * l;
  v.N[4] = 4 * g * h;
  v.N[5] = 4 * h * l;
  v.dN[0] = {1 - 4 * l, 1 - 4 * l, 0};
  v.dN[1] = {4 * g - 1, 0, 0};
  v.dN[2] = {0, 4 * h - 1, 0};
  v.dN[3] = {4 * (l - g), -4 * g, 0};
  v.dN[4] = {4 * h, 4 * g, 0};
  v.dN[5] = {-4 * h, 4 * (l - h), 0};
}

void tet4(const std::array<double, 3>& x, ShapeValues& v) {
  v.N[0] = 1 - x[0] - x[1] - x[2];
  v.N[1] = x[0];
  v.N[2] = x[1];
  v.N[3] = x[2];
  v.dN[0] = {-1, -1, -1};
  v.dN[1] = {1, 0, 0};
  v.dN[2] = {0, 1, 0};
  v.dN[3] = {0, 0, 1};
}

// Corners l(2l-1), g(2g-1), h(2h-1), r(2r-1); midsides 5: 4lg, 6: 4gh, 7: 4lh, 8: 4lr,
// 9: 4gr, 10: 4hr with l = 1-g-h-r.
void tet10(const std::array<double, 3>& x, ShapeValues& v) {
  const double g = x[0], h = x[1], r = x[2], l = 1 - g - h - r;
  v.N[0] = l * (2 * l - 1);
  v.N[1] = g * (2 * g - 1);
  v.N[2] = h * (2 * h - 1);
  v.N[3] = r * (2 * r - 1);
  v.N[4] = 4 * l * g;
  v.N[5] = 4 * g * h;
  v.N[6] = 4 * l * h;
  v.N[7] = 4 * l * r;
  v.N[8] = 4 * g * r;
  v.N[9] = 4 * h * r;
  const double dl = 1 - 4 * l;  // ∂[l(2l-1)]/∂g = -(4l-1)
  v.dN[0] = {dl, dl, dl};
  v.dN[1] = {4 * g - 1, 0, 0};
  v.dN[2] = {0, 4 * h - 1, 0};
  v.dN[3] = {0, 0, 4 * r - 1};
  v.dN[4] = {4 * (l - g), -4 * g, -4 * g};
  v.dN[5] = {4 * h, 4 * g, 0};
  v.dN[6] = {-4 * h, 4 * (l - h), -4 * h};
  v.dN[7] = {-4 * r, -4 * r, 4 * (l - r)};
  v.dN[8] = {4 * r, 0, 4 * g};
  v.dN[9] = {0, 4 * r, 4 * h};
}

// u = ½(1-g-h)(1-r)u1 + ½g(1-r)u2 + ½h(1-r)u3 + the same with (1+r) for nodes 4-6.
void wedge6(const std::array<double, 3>& x, ShapeValues& v) {
  const double g = x[0], h = x[1], r = x[2], l = 1 - g - h;
  for (int k = 0; k < 2; ++k) {
    const double s = k == 0 ? -1.0 : 1.0;
    const double z = (1 + s * r) / 2;
    v.N[3 * k + 0] = l * z;
    v.N[3 * k + 1] = g * z;
    v.N[3 * k + 2] = h * z;
    v.dN[3 * k + 0] = {-z, -z, s * l / 2};
    v.dN[3 * k + 1] = {z, 0, s * g / 2};
    v.dN[3 * k + 2] = {0, z, s * h / 2};
  }
}

void line2(const std::array<double, 3>& x, ShapeValues& v) {
  v.N[0] = (1 - x[0]) / 2;
  v.N[1] = (1 + x[0]) / 2;
  v.dN[0] = {-0.5, 0, 0};
  v.dN[1] = {0.5, 0, 0};
}

void line3(const std::array<double, 3>& x, ShapeValues& v) {
  const double s = x[0];
  v.N[0] = s * (s - 1) / 2;
  v.N[1] = s * (s + 1) / 2;
  v.N[2] = 1 - s * s;
  v.dN[0] = {s - 0.5, 0, 0};
  v.dN[1] = {s + 0.5, 0, 0};
  v.dN[2] = {-2 * s, 0, 0};
}

}  // namespace

int n_nodes(Shape s) {
  switch (s) {
    case Shape::Line2: return 2;
    case Shape::Line3: return 3;
    case Shape::Tri3: return 3;
    case Shape::Tri6: return 6;
    case Shape::Quad4: return 4;
    case Shape::Quad8: return 8;
    case Shape::Tet4: return 4;
    case Shape::Tet10: return 10;
    case Shape::Wedge6: return 6;
    case Shape::Hex8: return 8;
    case Shape::Hex20: return 20;
  }
  return 0;
}

int parametric_dim(Shape s) {
  switch (s) {
    case Shape::Line2:
    case Shape::Line3: return 1;
    case Shape::Tri3:
    case Shape::Tri6:
    case Shape::Quad4:
    case Shape::Quad8: return 2;
    default: return 3;
  }
}

Shape element_shape(const model::ElementTypeInfo& type) {
  if (model::is_shell(type)) {
    switch (type.n_nodes) {
      case 3: return Shape::Tri3;
      case 4: return Shape::Quad4;
      case 6: return Shape::Tri6;
      default: return Shape::Quad8;
    }
  }
  if (type.dim == 3) {
    switch (type.n_nodes) {
      case 4: return Shape::Tet4;
      case 10: return Shape::Tet10;
      case 6: return Shape::Wedge6;
      case 8: return Shape::Hex8;
      case 20: return Shape::Hex20;
      default: break;
    }
  } else {
    switch (type.n_nodes) {
      case 3: return Shape::Tri3;
      case 6: return Shape::Tri6;
      case 4: return Shape::Quad4;
      case 8: return Shape::Quad8;
      default: break;
    }
  }
  throw std::invalid_argument("element_shape: no interpolation for this element type");
}

Shape face_shape(int n_face_nodes, int n_corners) {
  if (n_corners == 2) return n_face_nodes == 2 ? Shape::Line2 : Shape::Line3;
  if (n_corners == 3) return n_face_nodes == 3 ? Shape::Tri3 : Shape::Tri6;
  return n_face_nodes == 4 ? Shape::Quad4 : Shape::Quad8;
}

ShapeValues evaluate_shape(Shape s, const std::array<double, 3>& xi) {
  ShapeValues v;
  v.n_nodes = n_nodes(s);
  v.dim = parametric_dim(s);
  switch (s) {
    case Shape::Line2: line2(xi, v); break;
    case Shape::Line3: line3(xi, v); break;
    case Shape::Tri3: tri3(xi, v); break;
    case Shape::Tri6: tri6(xi, v); break;
    case Shape::Quad4: quad4(xi, v); break;
    case Shape::Quad8: quad8(xi, v); break;
    case Shape::Tet4: tet4(xi, v); break;
    case Shape::Tet10: tet10(xi, v); break;
    case Shape::Wedge6: wedge6(xi, v); break;
    case Shape::Hex8: hex8(xi, v); break;
    case Shape::Hex20: hex20(xi, v); break;
  }
  return v;
}

std::array<double, 3> node_parametric_coords(Shape s, int a) {
  switch (s) {
    case Shape::Line2: return {a == 0 ? -1.0 : 1.0, 0, 0};
    case Shape::Line3: return {a == 0 ? -1.0 : a == 1 ? 1.0 : 0.0, 0, 0};
    case Shape::Tri3:
    case Shape::Tri6: {
      constexpr double p[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
      return {p[a][0], p[a][1], 0};
    }
    case Shape::Quad4:
    case Shape::Quad8:
      if (a < 4) return {kQuadSign[a][0], kQuadSign[a][1], 0};
      return {kQuad8Mid[a - 4][0], kQuad8Mid[a - 4][1], 0};
    case Shape::Tet4:
    case Shape::Tet10: {
      constexpr double p[10][3] = {{0, 0, 0},     {1, 0, 0},   {0, 1, 0},     {0, 0, 1},   {0.5, 0, 0},
                                   {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
      return {p[a][0], p[a][1], p[a][2]};
    }
    case Shape::Wedge6: {
      constexpr double p[6][3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
      return {p[a][0], p[a][1], p[a][2]};
    }
    case Shape::Hex8:
    case Shape::Hex20:
      if (a < 8) return {kHexSign[a][0], kHexSign[a][1], kHexSign[a][2]};
      return {kHex20Mid[a - 8][0], kHex20Mid[a - 8][1], kHex20Mid[a - 8][2]};
  }
  return {0, 0, 0};
}

}  // namespace inpact::solver::elements
