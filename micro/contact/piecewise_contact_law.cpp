// The one contact-law class for every law whose F is a piecewise power law
// (seth2011, piecewise, table): the force kernel is compiled here once for all.
#include <utility>

#include "micro/contact/contact_law_impl.h"
#include "micro/contact/piecewise_power_law.h"

namespace softglass::micro {
namespace {

class PiecewiseContactLaw final : public ContactLawImpl<PiecewiseContactLaw> {
 public:
  PiecewiseContactLaw(std::string name, PiecewisePowerLaw law)
      : name_(std::move(name)), law_(std::move(law)) {}

  std::string name() const override { return name_; }

  void force_and_stiffness(double eps, double& force, double& stiffness) const {
    law_.evaluate(eps, force, stiffness);
  }

  double energy(double eps) const override { return law_.energy(eps); }

 private:
  std::string name_;
  PiecewisePowerLaw law_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_piecewise_contact_law(std::string name, PiecewisePowerLaw law) {
  return std::make_unique<PiecewiseContactLaw>(std::move(name), std::move(law));
}

}  // namespace softglass::micro
