#include "pressure_overclosure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace inpact::contact {

using Law = model::PressureOverclosure;
using model::EnforcementMethod;

PressureOverclosure PressureOverclosure::from(const ResolvedNormalBehavior& r, double ke, double l_char) {
  PressureOverclosure law;
  const model::SurfaceBehavior& b = r.deck;
  switch (r.law) {
    case Law::Hard:
      if (r.method == EnforcementMethod::PenaltyLinear || r.method == EnforcementMethod::AugmentedLagrange) {
        law.kind_ = Kind::LinearPenalty;
        law.k_ = penalty_stiffness(r, ke);
        law.c0_ = b.clearance_at_zero_pressure;
        return law;
      }
      if (r.method == EnforcementMethod::PenaltyNonlinear) {
        // KEYWORDS.md *SURFACE BEHAVIOR: d + c0 = r_u L_char, e + c0 = r_l (d + c0).
        law.kind_ = Kind::NonlinearPenalty;
        law.k_ = penalty_stiffness(r, ke);
        law.k_initial_ = r.initial_final_ratio * law.k_;
        law.c0_ = b.clearance_at_zero_pressure;
        law.s_d_ = r.upper_quadratic_limit * l_char;
        law.s_e_ = r.lower_quadratic_ratio * law.s_d_;
        return law;
      }
      throw std::invalid_argument("direct hard contact has no pressure-overclosure law");
    case Law::Exponential:
      law.kind_ = Kind::Exponential;
      law.c0_ = b.exponential_c0;
      law.p0_ = b.exponential_p0;
      return law;
    case Law::Linear:
      law.kind_ = Kind::Linear;
      law.k_ = b.linear_slope.value_or(0.0);
      return law;
    case Law::Tabular:
      law.kind_ = Kind::Tabular;
      for (const auto& [p, h] : b.table) {
        law.p_.push_back(p);
        law.h_.push_back(h);
      }
      return law;
    case Law::Tied:
      law.kind_ = Kind::Tied;
      law.k_ = b.tied_slope.value_or(0.0);
      return law;
  }
  throw std::invalid_argument("unknown pressure-overclosure law");
}

PressureValue PressureOverclosure::eval(double h, double lambda) const {
  PressureValue v;
  switch (kind_) {
    case Kind::LinearPenalty: {
      // p = ⟨λ + k (h + c0)⟩
      const double trial = lambda + k_ * (h + c0_);
      if (trial > 0.0 || (lambda == 0.0 && h + c0_ >= 0.0)) v = {std::max(trial, 0.0), k_, true};
      return v;
    }
    case Kind::NonlinearPenalty: {
      const double s = h + c0_;
      if (s < 0.0) return v;
      v.active = true;
      const double kf = k_, ki = k_initial_, span = s_d_ - s_e_;
      if (s <= s_e_) {
        v.p = ki * s;
        v.dp = ki;
      } else if (s <= s_d_) {
        v.p = ki * s + (kf - ki) * (s - s_e_) * (s - s_e_) / (2.0 * span);
        v.dp = ki + (kf - ki) * (s - s_e_) / span;
      } else {
        v.p = ki * s_d_ + 0.5 * (kf - ki) * span + kf * (s - s_d_);
        v.dp = kf;
      }
      return v;
    }
    case Kind::Exponential: {
      // p = p0/(e−1) · ŝ (exp(ŝ) − 1),  ŝ = h/c0 + 1
      if (h < -c0_) return v;
      const double s = h / c0_ + 1.0, a = p0_ / (std::numbers::e - 1.0);
      v.p = a * s * (std::exp(s) - 1.0);
      v.dp = a / c0_ * ((std::exp(s) - 1.0) + s * std::exp(s));
      v.active = true;
      return v;
    }
    case Kind::Linear:
      if (h < 0.0) return v;
      return {k_ * h, k_, true};
    case Kind::Tied:
      return {k_ * h, k_, true};
    case Kind::Tabular: {
      if (h_.empty() || h < h_.front()) return v;
      v.active = true;
      const std::size_t n = h_.size();
      if (n == 1) return {p_[0], 0.0, true};
      // Segment i: [h_i, h_{i+1}]; beyond the last point the last segment continues.
      std::size_t i = static_cast<std::size_t>(std::upper_bound(h_.begin(), h_.end(), h) - h_.begin());
      i = std::min(std::max<std::size_t>(i, 1), n - 1) - 1;
      const double slope = (p_[i + 1] - p_[i]) / (h_[i + 1] - h_[i]);
      v.p = std::max(p_[i] + slope * (h - h_[i]), 0.0);
      v.dp = slope;
      return v;
    }
  }
  return v;
}

double PressureOverclosure::max_slope(double h_max) const {
  switch (kind_) {
    case Kind::Exponential: return eval(std::max(h_max, -c0_)).dp;
    case Kind::Tabular: {
      double s = 0.0;
      for (std::size_t i = 0; i + 1 < h_.size(); ++i) s = std::max(s, (p_[i + 1] - p_[i]) / (h_[i + 1] - h_[i]));
      return s;
    }
    default: return k_;
  }
}

PressureValue PressureOverclosure::inverse(double p, double lambda, double* h_out) const {
  // Bracket [lo, hi] with p(lo) ≤ p ≤ p(hi), then safeguarded Newton on p(h) − p.
  double lo = h_zero();
  if (kind_ == Kind::LinearPenalty) lo = -c0_ - lambda / k_;  // where λ + k (h + c0) = 0
  double step = std::max({std::abs(lo), 1e-12, p / std::max(max_slope(lo), 1e-300)});
  double hi = lo + step;
  for (int i = 0; i < 200 && eval(hi, lambda).p < p; ++i) {
    step *= 2.0;
    hi = lo + step;
  }
  double h = hi;
  PressureValue v = eval(h, lambda);
  for (int it = 0; it < 200; ++it) {
    const double r = v.p - p;
    if (std::abs(r) <= 1e-14 * p) break;
    (r > 0 ? hi : lo) = h;
    double next = v.dp > 0 ? h - r / v.dp : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == h) break;
    h = next;
    v = eval(h, lambda);
  }
  if (h_out) *h_out = h;
  return v;
}

double PressureOverclosure::h_zero() const {
  switch (kind_) {
    case Kind::Linear: return 0.0;
    case Kind::Tabular: return h_.empty() ? 0.0 : h_.front();
    default: return -c0_;
  }
}

std::string PressureOverclosure::describe() const {
  switch (kind_) {
    case Kind::LinearPenalty: return fmt::format("linear penalty, k = {:.4g}, c0 = {:g}", k_, c0_);
    case Kind::NonlinearPenalty:
      return fmt::format("nonlinear penalty, K_i = {:.4g}, K_f = {:.4g}, quadratic for {:.3g} ≤ h + c0 ≤ {:.3g}",
                         k_initial_, k_, s_e_, s_d_);
    case Kind::Exponential: return fmt::format("exponential, c0 = {:g}, p0 = {:g}", c0_, p0_);
    case Kind::Linear: return fmt::format("linear softened, k = {:g}", k_);
    case Kind::Tabular: return fmt::format("tabular, {} points", h_.size());
    case Kind::Tied: return fmt::format("tied (CalculiX), k = {:.4g}, tension included", k_);
  }
  return {};
}

}  // namespace inpact::contact
