#pragma once
/// The interface every pressure-overclosure law implements: the contact pressure p as a function
/// of the overclosure h = −g (g the gap, positive = open), its slope dp/dh, and its inverse.
/// One class per law in this folder; contact/pressure_overclosure.hpp maps a resolved
/// *SURFACE BEHAVIOR to one of them and is what the solver holds.
#include <string>

namespace inpact::contact {

struct PressureValue {
  double p = 0.0;   ///< pressure (≥ 0; negative only for the TIED law's tension)
  double dp = 0.0;  ///< dp/dh (0 where the law gives no pressure)
  bool active = false;  ///< h lies where the law acts (the stiffness enters the tangent)
};

class PressureLaw {
 public:
  virtual ~PressureLaw() = default;

  /// p(h) and dp/dh; `lambda` is the augmented-Lagrange multiplier (0 otherwise; only the
  /// linear penalty law uses it).
  virtual PressureValue eval(double h, double lambda) const = 0;
  /// The steepest slope the law reaches for overclosures up to `h_max`.
  virtual double max_slope(double h_max) const = 0;
  /// Overclosure at which the law starts giving pressure.
  virtual double h_zero() const = 0;
  /// The law's stiffness constant (linear penalty k, nonlinear K_f, LINEAR and TIED slope; 0 for
  /// the laws that have none).
  virtual double stiffness() const = 0;
  /// One line for `inpact check` and the .dat file.
  virtual std::string describe() const = 0;

  /// The overclosure h at which p(h; λ) = `p` (> 0), written to `h` when given, and the law's
  /// value there. This generic version brackets the root from lo = onset(λ) upwards (first width
  /// bracket_width(p, lo), doubled until p(hi) ≥ p) and runs Newton with a bisection safeguard
  /// to 1e-14 relative (one step per segment for the piecewise-linear laws); a law with a
  /// closed-form inverse may override it.
  virtual PressureValue inverse(double p, double lambda, double* h) const;

 protected:
  /// The lower end of inverse()'s bracket: where p(h; λ) starts being positive. h_zero() unless
  /// the multiplier moves it.
  virtual double onset(double lambda) const { return h_zero(); }
  /// The first width of inverse()'s bracket above `lo`: p over the slope at lo (the root itself
  /// for a linear law), at least |lo| and 1e-12. A law whose slope vanishes at its onset gives
  /// its own.
  virtual double bracket_width(double p, double lo) const;
};

}  // namespace inpact::contact
