// Elastic contact laws: the interface every law implements.
//
// Two spheres overlapping by h = R_α + R_β − r have deformation ε = h/R_c with
// R_c = R_α R_β/(R_α + R_β). A law gives the repulsive force in reduced form,
//
//     f = E* R_c² F(ε) n⊥ ,       pair energy  E* R_c³ W(ε),   W(ε) = ∫₀^ε F,
//
// so the paper's law is F(ε) = (4/3) C ε^n. The pair stiffness along the normal
// is df/dh = E* R_c F'(ε). The EHD drag needs only F as well (see
// forces/ehd_drag.h).
//
// A new law is one new file — a class deriving from ContactLawImpl (see
// contact_law_impl.h) that defines F, F′ and W — plus one line in
// contact_law.cpp's registry. ContactLawImpl compiles the force kernel with the
// law's F inlined, so the law costs no call per contact.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

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
  std::filesystem::path table_file{};  // for name = "table": the file, or
  std::string table_text{};            // its contents (as stored in a result file)

  /// The table's contents, read from table_file unless table_text holds them;
  /// empty for other laws. InputError if the file cannot be read.
  std::string table() const;
};

/// The law named in `spec`; InputError for an unknown name or a bad table.
std::unique_ptr<ContactLaw> make_contact_law(const ContactLawSpec& spec);

/// Names accepted by make_contact_law, for documentation and validation.
std::vector<std::string> contact_law_names();

}  // namespace softglass::micro
