// F(ε) = a_k ε^{n_k} on consecutive intervals (ε_k, ε_{k+1}], continuous in ε.
//
// The `seth2011` and `piecewise` laws (the paper's form (4/3) C ε^n with
// deformation-dependent n and C) and the `table` law (log–log interpolation
// of user data, which is exactly a piecewise power law) share this evaluator
// and one contact-law class (make_piecewise_contact_law). The energy
// W(ε) = ∫₀^ε F is exact: a sum of closed-form branch integrals.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace softglass::micro {

class ContactLaw;

class PiecewisePowerLaw {
 public:
  struct Branch {
    double start;      // ε_k; the first branch starts at 0
    double prefactor;  // a_k
    double exponent;   // n_k > 0
  };

  /// Branches must start at 0, increase, and join continuously (checked to 1e-9).
  explicit PiecewisePowerLaw(std::vector<Branch> branches);

  /// F = (4/3) C ε^{n_0} up to the first breakpoint, then exponent n_k on the
  /// k-th interval, each prefactor set by continuity: the paper's form with
  /// deformation-dependent (n, C). Needs one exponent more than breakpoints,
  /// breakpoints positive and increasing, exponents positive; InputError
  /// otherwise, its message starting with `what`.
  static PiecewisePowerLaw continuous(const std::string& what, double first_c,
                                      const std::vector<double>& breakpoints,
                                      const std::vector<double>& exponents);

  void evaluate(double eps, double& force, double& stiffness) const {
    const std::size_t k = branch_of(eps);
    const Branch& b = branches_[k];
    const double p = power_less_one(k, eps);
    force = b.prefactor * p * eps;
    stiffness = b.prefactor * b.exponent * p;
  }
  /// ∫₀^ε F: on branch k, a ε^{n+1}/(n+1) plus the branch's constant.
  double energy(double eps) const {
    const std::size_t k = branch_of(eps);
    return energy_offset_[k] + energy_factor_[k] * power_less_one(k, eps) * eps * eps;
  }
  const std::vector<Branch>& branches() const { return branches_; }

 private:
  enum class Kind { three_halves, two, three, general };
  /// Index of the branch holding ε, intervals closed on the right (a joint
  /// belongs to the branch below it, as in "ε ≤ 0.1: Hertz"): a scan for the few
  /// branches of an analytic law, bisection for long tables.
  std::size_t branch_of(double eps) const {
    const std::size_t count = branches_.size();
    if (count <= 8) {
      std::size_t k = count - 1;
      while (k > 0 && eps <= branches_[k].start) --k;
      return k;
    }
    return bisect(eps);
  }
  std::size_t bisect(double eps) const;
  /// ε^{n−1} on branch k; the common exponents without std::pow (the force
  /// kernel's energy and force both go through here).
  double power_less_one(std::size_t k, double eps) const {
    switch (kinds_[k]) {
      case Kind::three_halves:
        return std::sqrt(eps);
      case Kind::two:
        return eps;
      case Kind::three:
        return eps * eps;
      default:
        return std::pow(eps, branches_[k].exponent - 1.0);
    }
  }

  std::vector<Branch> branches_;
  std::vector<Kind> kinds_;  // fast paths for the common exponents
  std::vector<double> energy_factor_;  // a_k/(n_k + 1)
  std::vector<double> energy_offset_;  // energy at the branch's start − a_k start^{n_k+1}/(n_k+1)
};

/// The contact law `name` whose F is `law` (its force kernel is compiled once,
/// in piecewise_contact_law.cpp, for every law of this form).
std::unique_ptr<ContactLaw> make_piecewise_contact_law(std::string name, PiecewisePowerLaw law);

}  // namespace softglass::micro
