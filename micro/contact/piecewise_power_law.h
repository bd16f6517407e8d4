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
    double power_less_one;  // ε^{n−1}
    switch (kinds_[k]) {
      case Kind::three_halves:
        power_less_one = std::sqrt(eps);
        break;
      case Kind::two:
        power_less_one = eps;
        break;
      case Kind::three:
        power_less_one = eps * eps;
        break;
      default:
        power_less_one = std::pow(eps, b.exponent - 1.0);
    }
    force = b.prefactor * power_less_one * eps;
    stiffness = b.prefactor * b.exponent * power_less_one;
  }
  double energy(double eps) const;
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

  std::vector<Branch> branches_;
  std::vector<Kind> kinds_;  // fast paths for the common exponents
  std::vector<double> energy_at_start_;
};

/// The contact law `name` whose F is `law` (its force kernel is compiled once,
/// in piecewise_contact_law.cpp, for every law of this form).
std::unique_ptr<ContactLaw> make_piecewise_contact_law(std::string name, PiecewisePowerLaw law);

}  // namespace softglass::micro
