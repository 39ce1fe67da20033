#pragma once
/// Pressure-overclosure laws of penalty-type and softened contact: the contact pressure p as a
/// function of the overclosure h = −g (g the gap, positive = open), and its slope dp/dh.
/// Sources: [IG] "Contact Pressure-Overclosure Relationships" and "Contact Constraint
/// Enforcement Methods in Abaqus/Standard", as summarised in parser/KEYWORDS.md Part A
/// (*SURFACE BEHAVIOR) and Part C.
///
/// Each law is one class (a contact::PressureLaw) in contact/pressure_overclosure/:
///   linear_penalty.hpp     linear penalty: p = k (h + c0) for h > −c0, else 0
///   nonlinear_penalty.hpp  nonlinear penalty, s = h + c0: p = K_i s for 0 ≤ s ≤ s_e; stiffness
///                          rising linearly from K_i to K_f for s_e ≤ s ≤ s_d; slope K_f beyond;
///                          s_d = r_u L_char, s_e = r_l s_d, K_i = ratio K_f
///   exponential.hpp        EXPONENTIAL: p = p0/(e−1) (h/c0 + 1)(exp(h/c0 + 1) − 1) for h > −c0,
///                          else 0
///   linear_softened.hpp    LINEAR (softened): p = k h for h > 0, else 0
///   tabular.hpp            TABULAR: piecewise linear through (h_i, p_i); 0 below h_0; the last
///                          slope beyond the last point
///   tied.hpp               TIED (CalculiX): p = k h for every h, a bonded spring, tension
///                          included (h is measured from the initial gap, solver/contact_problem.cpp)
/// Augmented Lagrange adds a multiplier λ (a pressure) to the linear penalty law:
///   p = ⟨λ + k (h + c0)⟩.
/// The generic inverse (Newton with bisection) is PressureLaw::inverse, in pressure_law.cpp.
///
/// PressureOverclosure is the value the solver holds: it owns one immutable law and forwards to
/// it. A new law is one class in contact/pressure_overclosure/ (and its line in
/// contact/CMakeLists.txt), an enumerator in Kind with its case in from() below, and its keyword
/// in parser/kw_surface_interaction.cpp (with its model::PressureOverclosure value).
#include <memory>
#include <string>
#include <utility>

#include "contact/normal_behavior.hpp"
#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class PressureOverclosure {
 public:
  enum class Kind { LinearPenalty, NonlinearPenalty, Exponential, Linear, Tabular, Tied };

  PressureOverclosure() = default;

  /// The law of a resolved behaviour that is penalty-type or softened, for the pair's
  /// underlying element stiffness `ke` and characteristic length `l_char`. Throws
  /// std::invalid_argument for direct hard contact (it has no law: multipliers).
  static PressureOverclosure from(const ResolvedNormalBehavior& r, double ke, double l_char);

  /// p(h) and dp/dh; `lambda` is the augmented-Lagrange multiplier (0 otherwise).
  PressureValue eval(double h, double lambda = 0.0) const { return law_->eval(h, lambda); }
  /// The steepest slope the law reaches for overclosures up to `h_max` (exponential: at
  /// h_max; the others: their largest slope), compared with 1000 k_e by table 38.1.21.
  double max_slope(double h_max) const { return law_->max_slope(h_max); }
  /// Overclosure at which the law starts giving pressure (−c0; tabular: h_0; LINEAR: 0).
  double h_zero() const { return law_->h_zero(); }
  /// The inverse law: the overclosure h at which p(h; λ) = `p` (> 0) and the slope dp/dh there,
  /// for enforcement with Lagrange multipliers (table 38.1.21), where the pressure is the
  /// unknown and h(p) the constraint. Exact for the piecewise-linear laws, Newton with bisection
  /// safeguard (to 1e-14 relative) for the curved ones.
  PressureValue inverse(double p, double lambda = 0.0, double* h = nullptr) const {
    return law_->inverse(p, lambda, h);
  }

  Kind kind() const { return kind_; }
  double stiffness() const { return law_->stiffness(); }  ///< linear penalty k, nonlinear K_f, LINEAR slope

  std::string describe() const { return law_->describe(); }

 private:
  PressureOverclosure(Kind kind, std::shared_ptr<const PressureLaw> law) : kind_(kind), law_(std::move(law)) {}
  /// The default value: a linear penalty law with k = 0, c0 = 0.
  static std::shared_ptr<const PressureLaw> zero_law();

  Kind kind_ = Kind::LinearPenalty;
  std::shared_ptr<const PressureLaw> law_ = zero_law();  // never null; shared by copies (immutable)
};

}  // namespace inpact::contact
