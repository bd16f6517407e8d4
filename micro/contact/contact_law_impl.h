// ContactLawImpl: the base of every contact law. A law `L` derives from
// ContactLawImpl<L> and defines
//     std::string name() const;
//     void force_and_stiffness(double eps, double& F, double& dF) const;  // inline
//     double energy(double eps) const;
// and this base turns F into the ContactLaw interface, compiling the contact
// force kernel (forces/contact_kernel.h) once per law with F inlined.
#pragma once

#include "micro/contact/contact_kernel.h"
#include "micro/contact/contact_law.h"

namespace softglass::micro {

template <class Law>
class ContactLawImpl : public ContactLaw {
 public:
  void evaluate(std::span<const double> eps, std::span<double> force,
                std::span<double> stiffness) const final {
    for (std::size_t k = 0; k < eps.size(); ++k)
      law().force_and_stiffness(eps[k], force[k], stiffness[k]);
  }

  void compute_forces(const ForceKernelInput& input, ContactField& out) const final {
    run_contact_kernel(law(), input, out);
  }

 private:
  const Law& law() const { return static_cast<const Law&>(*this); }
};

}  // namespace softglass::micro
