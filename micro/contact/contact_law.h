// Elastic contact laws: the interface every law implements.
//
// Two spheres overlapping by h = R_α + R_β − r have deformation ε = h/R_c with
// R_c = R_α R_β/(R_α + R_β). A law gives the repulsive force in reduced form,
//
//     f = E* R_c² F(ε) n⊥ ,       pair energy  E* R_c³ W(ε),   W(ε) = ∫₀^ε F,
//
// so the paper's law is F(ε) = (4/3) C ε^n. The pair stiffness along the normal
// is df/dh = E* R_c F'(ε). The EHD drag needs only F as well (see
// model/ehd_drag.h).
//
// A new law is one new file — a class deriving from ContactLawImpl (see
// contact_law_impl.h) that defines F, F′ and W, and a function returning its
// registry entry (name, summary, coefficients, factory) — plus one line in
// registered_laws.h. ContactLawImpl compiles the force kernel with the law's F
// inlined, so the law costs no call per contact. A law's coefficients are
// parameter-file entries of subsection `contact law` named "<law> <coefficient>"
// (e.g. `set power exponent = 2`); their defaults and ranges come from the entry.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/registry.h"

namespace softglass::micro {

struct ForceKernelInput;  // forces/contact_forces.h
struct ContactField;

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;

  virtual std::string name() const = 0;

  /// F(ε) and F'(ε) for deformations ε > 0.
  virtual void evaluate(std::span<const double> deformation, std::span<double> force,
                        std::span<double> stiffness) const = 0;

  /// W(ε) = ∫₀^ε F(e) de.
  virtual double energy(double deformation) const = 0;

  /// Every contact force of a configuration (forces/contact_forces.h).
  virtual void compute_forces(const ForceKernelInput& input, ContactField& out) const = 0;

  double force(double deformation) const;
  double stiffness(double deformation) const;
};

struct ContactLawSpec {
  std::string name = "seth2011";
  ComponentValues coefficients{};  // by the law's names; unset ones take their defaults
  std::string table_text{};        // `table`: the file's contents (as stored in a result file)

  /// `table`: the contents of the file named by coefficient "file", unless
  /// table_text holds them; empty for other laws. InputError if unreadable.
  std::string table() const;
};

using ContactLawEntry = ComponentEntry<ContactLaw, ContactLawSpec>;

/// Every contact law (registered_laws.h).
const Registry<ContactLawEntry>& contact_laws();

/// The law named in `spec` with its coefficients completed by their defaults
/// and checked; InputError for an unknown name, a bad coefficient or table.
std::unique_ptr<ContactLaw> make_contact_law(const ContactLawSpec& spec);

/// `spec` with every coefficient of its law present (defaults filled in).
ContactLawSpec completed(const ContactLawSpec& spec);

}  // namespace softglass::micro
