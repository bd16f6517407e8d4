// `power-law`: the slip velocity a power of the wall stress in excess of a
// slip yield stress σ_s ≥ 0 (0 by default),
//
//     V_s = β (σ_w − σ_s)^p   for σ_w > σ_s,   V_s = 0 below,
//
// that is σ_w = σ_s + (V_s/β)^{1/p} for V_s > 0. With σ_s = 0 this is the law
// of the fixed-load EHD estimate (p = 2: Meeker, Bonnecaze & Cloitre, PRL 92,
// 198302 (2004)); p = 1 is Navier's linear slip with slip coefficient β (a
// Navier slip length b = β μ for a Newtonian bulk of viscosity μ). β is in
// m/s/Pa^p, σ_s in Pa. In (V_s, σ_w) it is a Herschel–Bulkley law with yield
// stress σ_s, consistency k = β^{−1/p} and index m = 1/p, and it is
// regularised as the bulk law is:
//
//     σ_ε(V) = σ_s V/√(V² + ε²) + k (V² + ε²)^{(m−1)/2} V,
//     σ_ε'(V) = σ_s ε²/(V² + ε²)^{3/2} + k (V² + ε²)^{(m−3)/2} (m V² + ε²).
//
// Why. For p > 1 (m < 1) the derivative k m V^{m−1} of the power term is
// infinite at V = 0 (and it vanishes there for p < 1), so Newton's matrix would
// be singular wherever a wall does not slip; σ_s makes σ_w jump at V = 0. Both
// forms are odd, smooth and strictly increasing, with σ_ε'(0) = σ_s/ε + k ε^{m−1}.
// Their error at fixed V ≠ 0 is second order,
//     σ_w(V) − σ_ε(V) ≈ [σ_s + (1 − m) k |V|^m] ε²/(2V²),
// as that of Bercovier–Engelman's regularisation of the bulk (regularised_law.h). Where the wall barely
// slides (|V| ~ ε) the stress is off by O(1) of itself, as the bulk's is in a
// plug; the flows converge like O(ε) then, and like O(ε²) for σ_s = 0 when
// every slip wall slides at |V| ≫ ε.
#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"
#include "macro/material/slip_law.h"

namespace softglass::macro {
namespace {

// "slip: 'coefficient' = -1 is not allowed; allowed: > 0 [m/s/Pa^p]"
void require_entry(bool condition, const char* entry, double value, const char* allowed) {
  require(std::isfinite(value) && condition,
          fmt::format("slip: '{}' = {} is not allowed; allowed: {}", entry, value, allowed));
}

class PowerLawSlip final : public SlipLaw {
 public:
  explicit PowerLawSlip(const SlipLawSpec& spec)
      : beta_(spec.coefficient),
        p_(spec.exponent),
        yield_(spec.yield_stress),
        consistency_(std::pow(beta_, -1.0 / p_)),
        index_(1.0 / p_) {}

  std::string name() const override { return "power-law"; }

  double stress(double velocity) const override {
    return yield_ + consistency_ * std::pow(velocity, index_);
  }

  double velocity(double stress) const override {
    return stress <= yield_ ? 0.0 : beta_ * std::pow(stress - yield_, p_);
  }

  WallStress regularised(double velocity, double velocity_scale) const override {
    const double e2 = velocity_scale * velocity_scale, s = velocity * velocity + e2;
    const double root = std::sqrt(s);
    const double power = consistency_ * std::pow(s, 0.5 * (index_ - 1.0));  // k s^{(m−1)/2}
    return {.value = (yield_ / root + power) * velocity,
            .derivative = yield_ * e2 / (s * root) + power * (index_ * velocity * velocity + e2) / s};
  }

 private:
  double beta_, p_, yield_;
  double consistency_, index_;  // k = β^{−1/p}, m = 1/p
};

std::unique_ptr<SlipLaw> make(const SlipLawSpec& spec) {
  require_entry(spec.coefficient > 0.0, "coefficient", spec.coefficient, "> 0 [m/s/Pa^p]");
  require_entry(spec.exponent > 0.0, "exponent", spec.exponent, "> 0");
  require_entry(spec.yield_stress >= 0.0, "yield stress", spec.yield_stress, ">= 0 [Pa]");
  require_entry(std::isfinite(std::pow(spec.coefficient, -1.0 / spec.exponent)), "coefficient",
                spec.coefficient, "a value whose beta^(-1/p) is finite");
  return std::make_unique<PowerLawSlip>(spec);
}

}  // namespace

SlipLawEntry power_law_slip_law() {
  return {"power-law", "V_s = beta (sigma_w - sigma_s)^p above sigma_s (0 by default)", {}, make};
}

}  // namespace softglass::macro
