#pragma once
/// The gap of one surface-to-surface integration point between smoothed surfaces and its exact
/// gradient (surface_to_surface.hpp, geometric_correction.hpp).
///
/// The point x̃_q is the slave facet's point at ξ_q moved onto the slave's idealised surface; the
/// master point x̃_m(ξ) and normal ñ(ξ) are the master's idealised ones where the ray along ñ
/// through x̃_q meets them: F(ξ, g; u) = x̃_m(ξ) + g ñ(ξ) − x̃_q = 0, g the point's gap. With
/// J = ∂F/∂(ξ, g) (columns x̃_m,α + g ñ_,α and ñ),
///   J (dξ, dg) = dx̃_q − ∂x̃_m/∂u − g ∂ñ/∂u,   so dg = ρ·(dx̃_q − ∂x̃_m/∂u − g ∂ñ/∂u),
/// ρ the last row of J⁻¹. The corrections' derivatives (their rotation with the facet,
/// CorrectionDerivatives) and the point's slide over the master (dξ) are in it: the gap the
/// iteration computes is what this differentiates.
/// Where the ray misses the master facet (ξ on the domain's boundary, held there):
///   dg = ñ·(dx̃_q − ∂x̃_m/∂u) + (x̃_q − x̃_m)·∂ñ/∂u at fixed ξ.
/// A master facet no correction covers: the faceted gap's [n; −N_a n] with the slave point's own
/// derivatives.
#include <array>
#include <span>
#include <vector>

#include "contact/facet.hpp"
#include "contact/geometric_correction.hpp"
#include "contact/projection.hpp"

namespace inpact::contact {

/// One smoothed point: its slave facet and rule point, its master facet and projection.
struct SmoothedPoint {
  const Facet* slave_facet = nullptr;
  std::array<double, 2> slave_xi{0, 0};
  const Facet* master_facet = nullptr;
  const Projection* projection = nullptr;  ///< the corrected projection (ξ, x̃_m, ñ, g)
  Vec3 x{};                                ///< x̃_q
  bool master_corrected = false;
};

/// ∂g/∂u over [slave facet nodes; master facet nodes] (facet orders, `dim` components each) into
/// `out` (resized).
void smoothed_gap_gradient(const SurfaceCorrections& slave, const SurfaceCorrections& master, const SmoothedPoint& pt,
                           std::span<const Vec3> x, int dim, std::vector<double>& out);

/// ∂(ln da)/∂u over the slave facet's nodes (`dim` components each) of a point's area element
/// da = w |a_1| (× thickness or 2π r) or w |a_2 × a_1|, at ξ of facet `f`, into `out` (resized).
void area_element_log_gradient(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x, int dim,
                               bool axisymmetric, std::vector<double>& out);

}  // namespace inpact::contact
