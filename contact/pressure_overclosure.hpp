#pragma once
/// Pressure-overclosure laws of penalty-type and softened contact: the contact pressure p as a
/// function of the overclosure h = −g (g the gap, positive = open), and its slope dp/dh.
/// Sources: [IG] "Contact Pressure-Overclosure Relationships" and "Contact Constraint
/// Enforcement Methods in Abaqus/Standard", as summarised in parser/KEYWORDS.md Part A
/// (*SURFACE BEHAVIOR) and Part C.
///
///   linear penalty     p = k (h + c0)                              for h > −c0, else 0
///   nonlinear penalty  s = h + c0:  p = K_i s                       for 0 ≤ s ≤ s_e
///                      stiffness rising linearly from K_i to K_f   for s_e ≤ s ≤ s_d
///                      slope K_f                                   for s > s_d
///                      s_d = r_u L_char, s_e = r_l s_d, K_i = ratio K_f
///   EXPONENTIAL        p = p0/(e−1) (h/c0 + 1)(exp(h/c0 + 1) − 1)  for h > −c0, else 0
///   LINEAR (softened)  p = k h                                      for h > 0, else 0
///   TABULAR            piecewise linear through (h_i, p_i); 0 below h_0; last slope beyond
///   TIED (CalculiX)    p = k h for every h: a bonded spring, tension included (h is measured
///                      from the initial gap, solver/contact_problem.cpp)
/// Augmented Lagrange adds a multiplier λ (a pressure) to the linear penalty law:
///   p = ⟨λ + k (h + c0)⟩.
#include <string>
#include <vector>

#include "contact/normal_behavior.hpp"

namespace inpact::contact {

struct PressureValue {
  double p = 0.0;   ///< pressure (≥ 0)
  double dp = 0.0;  ///< dp/dh (0 where the law gives no pressure)
  bool active = false;  ///< h lies where the law acts (the stiffness enters the tangent)
};

class PressureOverclosure {
 public:
  enum class Kind { LinearPenalty, NonlinearPenalty, Exponential, Linear, Tabular, Tied };

  /// The law of a resolved behaviour that is penalty-type or softened, for the pair's
  /// underlying element stiffness `ke` and characteristic length `l_char`. Throws
  /// std::invalid_argument for direct hard contact (it has no law: multipliers).
  static PressureOverclosure from(const ResolvedNormalBehavior& r, double ke, double l_char);

  /// p(h) and dp/dh; `lambda` is the augmented-Lagrange multiplier (0 otherwise).
  PressureValue eval(double h, double lambda = 0.0) const;
  /// The steepest slope the law reaches for overclosures up to `h_max` (exponential: at
  /// h_max; the others: their largest slope), compared with 1000 k_e by table 38.1.21.
  double max_slope(double h_max) const;
  /// Overclosure at which the law starts giving pressure (−c0; tabular: h_0; LINEAR: 0).
  double h_zero() const;
  /// The inverse law: the overclosure h at which p(h; λ) = `p` (> 0) and the slope dp/dh there,
  /// for enforcement with Lagrange multipliers (table 38.1.21), where the pressure is the
  /// unknown and h(p) the constraint. Exact for the piecewise-linear laws, Newton with bisection
  /// safeguard (to 1e-14 relative) for the curved ones.
  PressureValue inverse(double p, double lambda = 0.0, double* h = nullptr) const;

  Kind kind() const { return kind_; }
  double stiffness() const { return k_; }  ///< linear penalty k, nonlinear K_f, LINEAR slope

  std::string describe() const;

 private:
  Kind kind_ = Kind::LinearPenalty;
  double k_ = 0.0, c0_ = 0.0;
  double k_initial_ = 0.0, s_e_ = 0.0, s_d_ = 0.0;  // nonlinear penalty
  double p0_ = 0.0;                                 // exponential
  std::vector<double> h_, p_;                       // tabular
};

}  // namespace inpact::contact
