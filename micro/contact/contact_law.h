// Elastic contact laws: the interface every law implements.
//
// Two spheres overlapping by h = R_α + R_β − r have deformation ε = h/R_c with
// R_c = R_α R_β/(R_α + R_β). A law gives the repulsive force in reduced form,
//
//     f = E* R_c² F(ε) n⊥ ,       pair energy  E* R_c³ W(ε),   W(ε) = ∫₀^ε F,
//
// so the paper's law is F(ε) = (4/3) C ε^n. The pair stiffness along the normal
// is df/dh = E* R_c F'(ε). The EHD drag needs only F as well (see
// forces/ehd_drag.h), so a new law is one new file implementing this interface
// plus one line in contact_law.cpp's registry.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace softglass::micro {

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;

  virtual std::string name() const = 0;

  /// F(ε) and F'(ε) for a batch of deformations ε > 0. Called once per particle
  /// with all its contacts, so the dispatch stays out of the innermost loop.
  virtual void evaluate(std::span<const double> deformation, std::span<double> force,
                        std::span<double> stiffness) const = 0;

  /// W(ε) = ∫₀^ε F(e) de.
  virtual double energy(double deformation) const = 0;

  double force(double deformation) const;
  double stiffness(double deformation) const;
};

struct ContactLawSpec {
  std::string name = "seth2011";
  std::filesystem::path table_file;  // for name = "table"
};

/// The law named in `spec`; InputError for an unknown name or a bad table.
std::unique_ptr<ContactLaw> make_contact_law(const ContactLawSpec& spec);

/// Names accepted by make_contact_law, for documentation and validation.
std::vector<std::string> contact_law_names();

}  // namespace softglass::micro
