// The law an exact reference integrates: any shear law (shear_law.h), or a
// Herschel–Bulkley struct, which it wraps — the closed forms of the tests are
// written for those. Passed by value; it owns the wrapper it makes.
#pragma once

#include <memory>

#include "macro/material/herschel_bulkley.h"
#include "macro/material/shear_law.h"

namespace softglass::macro::exact {

class LawRef {
 public:
  LawRef(const ShearLaw& law) : law_(&law) {}  // NOLINT: implicit by design
  LawRef(const HerschelBulkley& law)            // NOLINT: implicit by design
      : owned_(shear_law(law)), law_(owned_.get()) {}

  const ShearLaw& operator*() const { return *law_; }
  const ShearLaw* operator->() const { return law_; }

 private:
  std::shared_ptr<const ShearLaw> owned_;
  const ShearLaw* law_;
};

}  // namespace softglass::macro::exact
