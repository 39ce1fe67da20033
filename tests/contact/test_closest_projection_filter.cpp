// closest_projection() projects only the candidates its distance bounds cannot rule out
// (contact/closest_projection.cpp). It must give, to the bit, what projecting every candidate
// and comparing them in the order given does: checked against that reference (the rule of
// projection.hpp written out) on curved meshes of every facet shape, at random points near and
// far, on nodes and edge midpoints (ties between facets), with the candidates in random order.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "contact/projection.hpp"
#include "contact/vec3.hpp"

using namespace inpact;
using contact::Facet;
using contact::FacetShape;
using contact::Projection;
using contact::Vec3;

namespace {

/// Every candidate projected; the closest (ties within tol: interior, edge, vertex, then the lowest
/// index) in candidate order; n̄ over the candidates sharing its point.
Projection reference(std::span<const Facet> facets, std::span<const std::int32_t> candidates, std::span<const Vec3> x,
                     const Vec3& xs) {
  std::vector<Projection> all;
  double size = 0.0;
  for (std::int32_t c : candidates) {
    const Facet& f = facets[static_cast<std::size_t>(c)];
    all.push_back(contact::project_to_facet(f, x, xs, c));
    for (int a = 1; a < f.n_nodes; ++a)
      size = std::max(size, contact::norm(contact::sub(x[static_cast<std::size_t>(f.nodes[a])], x[static_cast<std::size_t>(f.nodes[0])])));
  }
  const double tol = 1e-8 * size;
  auto better = [&](const Projection& a, const Projection& b) {
    if (a.distance < b.distance - tol) return true;
    if (a.distance > b.distance + tol) return false;
    if (a.region != b.region) return a.region < b.region;
    return a.facet < b.facet;
  };
  std::size_t ib = 0;
  for (std::size_t i = 1; i < all.size(); ++i)
    if (better(all[i], all[ib])) ib = i;
  Projection best = all[ib];
  Vec3 nbar{};
  for (const Projection& q : all)
    if (std::abs(q.distance - best.distance) <= tol && contact::norm(contact::sub(q.x_master, best.x_master)) <= tol)
      nbar = contact::add(nbar, q.facet_normal);
  const double len = contact::norm(nbar);
  const int dim = contact::facet_param_dim(facets[static_cast<std::size_t>(best.facet)].shape) == 1 ? 2 : 3;
  const Vec3 r = contact::sub(xs, best.x_master);
  if (best.distance <= tol) {
    if (len > 0) best.normal = contact::scale(1.0 / len, nbar);
    best.gap = contact::dot(r, best.normal);
  } else if (best.region != contact::ProjectionRegion::Interior) {
    const double s = contact::dot(r, nbar) < 0 ? -1.0 : 1.0;
    best.normal = contact::scale(s / best.distance, r);
    best.gap = s * best.distance;
  }
  contact::tangent_basis(best.normal, dim, best.t1, best.t2);
  return best;
}

bool same_bits(const Projection& a, const Projection& b) {
  auto eq = [](const auto& u, const auto& v) { return std::memcmp(&u, &v, sizeof(u)) == 0; };
  return a.facet == b.facet && eq(a.xi, b.xi) && a.region == b.region && eq(a.x_master, b.x_master) &&
         eq(a.distance, b.distance) && eq(a.gap, b.gap) && eq(a.normal, b.normal) &&
         eq(a.facet_normal, b.facet_normal) && eq(a.t1, b.t1) && eq(a.t2, b.t2) && a.converged == b.converged;
}

/// A curved mesh of n × n cells (2D: n edges) of `shape` on a grid of half-cell points: nodes
/// shared between neighbours, so that edges and vertices are ties.
struct Mesh {
  std::vector<Vec3> x;
  std::vector<Facet> facets;
};

Vec3 surface(double u, double v, bool plane) {
  if (plane) return {u, 0.3 * std::sin(2.0 * u), 0.0};
  return {u + 0.05 * v * v, v, 0.25 * std::sin(1.5 * u) * std::cos(v) + 0.1 * u * v};
}

Mesh make_mesh(FacetShape shape, int n) {
  const bool plane = contact::facet_param_dim(shape) == 1;
  const int m = 2 * n + 1;
  Mesh mesh;
  for (int j = 0; j < (plane ? 1 : m); ++j)
    for (int i = 0; i < m; ++i) mesh.x.push_back(surface(0.5 * i, 0.5 * j, plane));
  auto node = [&](int i, int j) { return static_cast<std::int32_t>(j * m + i); };
  auto add = [&](std::initializer_list<std::int32_t> rows) {
    Facet f;
    f.shape = shape;
    f.n_nodes = static_cast<std::uint8_t>(rows.size());
    std::copy(rows.begin(), rows.end(), f.nodes.begin());
    mesh.facets.push_back(f);
  };
  for (int c = 0; c < n; ++c) {
    const int i = 2 * c;
    if (shape == FacetShape::Line2) add({node(i, 0), node(i + 2, 0)});
    if (shape == FacetShape::Line3) add({node(i, 0), node(i + 2, 0), node(i + 1, 0)});
    if (plane) continue;
    for (int r = 0; r < n; ++r) {
      const int j = 2 * r;
      const auto c00 = node(i, j), c10 = node(i + 2, j), c11 = node(i + 2, j + 2), c01 = node(i, j + 2);
      if (shape == FacetShape::Quad4) add({c00, c10, c11, c01});
      if (shape == FacetShape::Quad8)
        add({c00, c10, c11, c01, node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 2), node(i, j + 1)});
      if (shape == FacetShape::Tri3) {
        add({c00, c10, c11});
        add({c00, c11, c01});
      }
      if (shape == FacetShape::Tri6) {
        add({c00, c10, c11, node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 1)});
        add({c00, c11, c01, node(i + 1, j + 1), node(i + 1, j + 2), node(i, j + 1)});
      }
    }
  }
  return mesh;
}

}  // namespace

TEST(ClosestProjectionFilter, ChoosesWhatProjectingEveryCandidateChoosesToTheBit) {
  std::mt19937 rng(7);
  for (FacetShape shape : {FacetShape::Line2, FacetShape::Line3, FacetShape::Tri3, FacetShape::Tri6,
                           FacetShape::Quad4, FacetShape::Quad8}) {
    const Mesh mesh = make_mesh(shape, 4);
    const bool plane = contact::facet_param_dim(shape) == 1;
    std::vector<std::int32_t> candidates(mesh.facets.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) candidates[i] = static_cast<std::int32_t>(i);
    std::vector<Vec3> points = mesh.x;  // every node (vertex and edge ties)
    std::uniform_real_distribution<double> along(-0.5, 4.5), height(-0.6, 0.6);
    for (int k = 0; k < 400; ++k) {
      Vec3 p = surface(along(rng), plane ? 0.0 : along(rng), plane);
      p[plane ? 1 : 2] += (k % 4 == 0 ? 1e-12 : 1.0) * height(rng);  // on the surface to round-off, too
      points.push_back(p);
    }
    int n_points = 0;
    for (const Vec3& p : points) {
      std::shuffle(candidates.begin(), candidates.end(), rng);
      const Projection a = contact::closest_projection(mesh.facets, candidates, mesh.x, p);
      const Projection b = reference(mesh.facets, candidates, mesh.x, p);
      EXPECT_TRUE(same_bits(a, b)) << "shape " << int(shape) << " point " << n_points << ": facet " << a.facet
                                   << " vs " << b.facet << ", gap " << a.gap << " vs " << b.gap;
      ++n_points;
    }
  }
}

TEST(GapGradient, IsLinearizeGapsGradientToTheBit) {
  std::mt19937 rng(11);
  for (FacetShape shape : {FacetShape::Line2, FacetShape::Line3, FacetShape::Tri6, FacetShape::Quad4, FacetShape::Quad8}) {
    const Mesh mesh = make_mesh(shape, 2);
    const bool plane = contact::facet_param_dim(shape) == 1;
    std::uniform_real_distribution<double> along(0.0, 2.0), height(-0.3, 0.3);
    for (int k = 0; k < 50; ++k) {
      Vec3 p = surface(along(rng), plane ? 0.0 : along(rng), plane);
      p[plane ? 1 : 2] += height(rng);
      const auto f = static_cast<std::int32_t>(k % static_cast<int>(mesh.facets.size()));
      const Projection pr = contact::project_to_facet(mesh.facets[static_cast<std::size_t>(f)], mesh.x, p, f);
      const int dim = plane ? 2 : 3;
      const auto full = contact::linearize_gap(mesh.facets[static_cast<std::size_t>(f)], mesh.x, p, pr, dim, 99);
      const auto grad = contact::gap_gradient(mesh.facets[static_cast<std::size_t>(f)], pr, dim, 99);
      EXPECT_EQ(grad.n_dof, full.n_dof);
      EXPECT_EQ(grad.nodes, full.nodes);
      EXPECT_EQ(grad.gradient, full.gradient);  // (exact ==: the same operations)
    }
  }
}

TEST(ProjectionHint, AStartNearTheLastPointConvergesToTheSamePointToRoundOff) {
  std::mt19937 rng(5);
  for (FacetShape shape : {FacetShape::Tri6, FacetShape::Quad4, FacetShape::Quad8}) {
    const Mesh mesh = make_mesh(shape, 3);
    std::vector<std::int32_t> candidates(mesh.facets.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) candidates[i] = static_cast<std::int32_t>(i);
    std::uniform_real_distribution<double> along(0.2, 2.8), height(-0.3, 0.3), nudge(-0.01, 0.01);
    for (int k = 0; k < 100; ++k) {
      Vec3 p = surface(along(rng), along(rng), false);
      p[2] += height(rng);
      const Projection cold = contact::closest_projection(mesh.facets, candidates, mesh.x, p);
      if (cold.region != contact::ProjectionRegion::Interior) continue;
      // The last iteration's ξ: the point has moved a little since.
      const contact::ProjectionHint hint{cold.facet, {cold.xi[0] + nudge(rng), cold.xi[1] + nudge(rng)}};
      const Projection warm = contact::closest_projection(mesh.facets, candidates, mesh.x, p, &hint);
      EXPECT_EQ(warm.facet, cold.facet);
      EXPECT_NEAR(warm.xi[0], cold.xi[0], 1e-12);
      EXPECT_NEAR(warm.xi[1], cold.xi[1], 1e-12);
      EXPECT_NEAR(warm.gap, cold.gap, 1e-13);
    }
  }
}

// A surface-to-surface point keeps its last closest facet without a search while no other facet
// can have come within the search's tolerance of it (SurfaceToSurfacePair::reproject): the
// margin closest_projection() reports, less how far the point and the facets moved, must then
// exceed the distance to the kept facet, and sole_projection() must give the search's numbers to
// the bit. Checked on curved meshes of every face shape, with the point and the nodes moved.
TEST(SoleProjection, IsTheSearchsResultWhenNoOtherFacetCanHaveComeClose) {
  std::mt19937 rng(17);
  for (FacetShape shape : {FacetShape::Tri3, FacetShape::Tri6, FacetShape::Quad4, FacetShape::Quad8}) {
    const Mesh mesh = make_mesh(shape, 4);
    std::vector<std::int32_t> candidates(mesh.facets.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) candidates[i] = static_cast<std::int32_t>(i);
    std::uniform_real_distribution<double> along(0.2, 3.8), height(-0.4, 0.4), step(-0.02, 0.02);
    int kept = 0, checked = 0;
    for (int k = 0; k < 300; ++k) {
      Vec3 p = surface(along(rng), along(rng), false);
      p[2] += height(rng);
      contact::ClosestMargin margin;
      const Projection then = contact::closest_projection(mesh.facets, candidates, mesh.x, p, nullptr, {}, &margin);
      // The point and every node move by up to 0.035 (the nodes less).
      const Vec3 moved_p = contact::add(p, {step(rng), step(rng), step(rng)});
      std::vector<Vec3> x = mesh.x;
      double node_motion = 0.0;
      for (Vec3& xi : x) {
        const Vec3 d{0.3 * step(rng), 0.3 * step(rng), 0.3 * step(rng)};
        xi = contact::add(xi, d);
        node_motion = std::max(node_motion, contact::norm(d));
      }
      const double facet_motion = (contact::facet_is_quadratic(shape) ? 3.0 : 1.0) * node_motion;
      double size = 0.0, magnitude = 0.0;
      for (const Facet& f : mesh.facets) size = std::max(size, contact::facet_box(f, x).size2);
      for (const Vec3& xi : x)
        for (double c : xi) magnitude = std::max(magnitude, std::abs(c));
      for (double c : moved_p) magnitude = std::max(magnitude, std::abs(c));
      const double tol = 1e-8 * std::sqrt(size), slack = tol + 1e-12 * magnitude;
      const double others = margin.others - margin.slack - contact::norm(contact::sub(moved_p, p)) - facet_motion - slack;
      const contact::ProjectionHint hint{then.facet, then.xi};
      const Projection now = contact::closest_projection(mesh.facets, candidates, x, moved_p, &hint);
      ++checked;
      Projection raw;
      const Projection sole = contact::sole_projection(mesh.facets, then.facet, x, moved_p, &hint, tol, &raw);
      // Ruled out or not, the kept facet's projection stands in for the search's own.
      const Projection reused = contact::closest_projection(mesh.facets, candidates, x, moved_p, &hint, {}, nullptr, &raw);
      EXPECT_TRUE(same_bits(reused, now)) << "shape " << int(shape) << " point " << k;
      Projection marked = raw;  // (stands in for the facet's projection wherever the search makes it)
      marked.x_master[0] += 1e-3;
      const Projection with_mark =
          contact::closest_projection(mesh.facets, candidates, x, moved_p, &hint, {}, nullptr, &marked);
      if (now.facet == raw.facet) {
        EXPECT_EQ(with_mark.x_master[0], marked.x_master[0]) << "point " << k;
      }
      if (!(sole.distance > tol && others > sole.distance + tol)) continue;
      ++kept;
      EXPECT_TRUE(same_bits(sole, now)) << "shape " << int(shape) << " point " << k << ": facet " << sole.facet
                                        << " vs " << now.facet << ", gap " << sole.gap << " vs " << now.gap;
    }
    EXPECT_GT(kept, checked / 10) << "shape " << int(shape);  // (the test is not vacuous)
  }
}
