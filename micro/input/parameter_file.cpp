#include "micro/input/parameter_file.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "common/deal_ii_message.h"
#include "common/errors.h"
#include "common/parameter_input.h"
#include "micro/input/model_preset.h"
#include "micro/sweep/sweep_plan.h"

namespace softglass::micro {

namespace {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

/// What the file sets, before conversion to the engine's types.
struct Entries {
  MicroParameters p;
  std::string model_preset = kDefaultModelPreset;
  std::string coupling = "implicit";
  std::string film_velocity = "tangential";
  std::string stokes_reference = "affine";
  std::string packing_input, output_file = "micro.h5";
  // Every law's coefficients, by entry name "<law> <coefficient>" (the
  // registry's declarations); only the chosen law's are used.
  std::map<std::string, std::string> law_coefficients;
  unsigned long particles = 1000;
  unsigned long seed = 1;
  unsigned long stage_iterations = 2000;
  unsigned long max_relaxation_iterations = 500000;
};

// Declares an entry bound to `value`, its documentation ending with what the
// pattern allows, so that the template states every range.
template <class T>
void entry(ParameterHandler& prm, const std::string& name, T& value, const std::string& doc,
           const Patterns::PatternBase& pattern) {
  prm.add_parameter(name, value,
                    doc + " Allowed: " + pattern.description(Patterns::PatternBase::Text) + ".",
                    pattern);
}

// An entry's documentation: `intro`, then every registered component's name
// and summary.
template <class Entry>
std::string documented_choice(std::string intro, const Registry<Entry>& registry) {
  for (const Entry& e : registry.entries()) intro += " " + e.name + ": " + e.summary + ";";
  intro.back() = '.';
  return intro;
}

// A law's coefficients as entries "<law> <coefficient>", with their ranges.
void declare_coefficients(ParameterHandler& prm, const ContactLawEntry& law, Entries& e) {
  for (const ComponentParameter& c : law.parameters) {
    std::string& value = e.law_coefficients[law.name + " " + c.name];
    value = c.default_value;
    const std::string doc = fmt::format("For law = {}: {}", law.name, c.documentation);
    const auto bound = [](double x) {
      return std::isfinite(x) ? x : std::copysign(std::numeric_limits<double>::max(), x);
    };
    const Patterns::Double number(bound(c.lower), bound(c.upper));
    switch (c.kind) {
      case ComponentParameter::Kind::number:
        entry(prm, law.name + " " + c.name, value, doc, number);
        break;
      case ComponentParameter::Kind::numbers:
        entry(prm, law.name + " " + c.name, value, doc, Patterns::List(number, 0, 100, ","));
        break;
      case ComponentParameter::Kind::file:
        entry(prm, law.name + " " + c.name, value, doc, Patterns::Anything());
        break;
    }
  }
}

void declare_model(ParameterHandler& prm, Entries& e) {
  prm.enter_subsection("model");
  entry(prm, "preset", e.model_preset,
        "A whole reading of the paper's model (docs/fidelity.md); it sets entries of "
        "subsections 'contact law' and 'drag', and every entry this file sets itself wins:" +
            model_preset_documentation(),
        Patterns::Selection(model_preset_names()));
  prm.leave_subsection();
}

void declare_particles(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("particles");
  entry(prm, "number", e.particles, "Number of particles N.", Patterns::Integer(2, 50000000));
  entry(prm, "volume fraction", p.packing.volume_fraction,
        "phi = sum (4/3) pi R^3 / V; soft glasses live above random close packing "
        "(0.64). The paper studies 0.70 ... 0.90.",
        Patterns::Double(0.64, 0.95));
  entry(prm, "polydispersity", p.packing.radii.polydispersity,
        "Standard deviation / mean of the radius (the paper: 0.10).", Patterns::Double(0.0, 0.3));
  entry(prm, "distribution", p.packing.radii.shape,
        documented_choice("Shape of the radius distribution:", radius_shapes()),
        Patterns::Selection(radius_shapes().selection()));
  entry(prm, "truncation", p.packing.radii.truncation_sigmas,
        "Gaussian and lognormal radii are cut at this many standard deviations.",
        Patterns::Double(1.0, 5.0));
  entry(prm, "seed", e.seed, "Seed of every random number of the packing.", Patterns::Integer(0));
  prm.leave_subsection();
}

void declare_packing(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("packing");
  entry(prm, "input file", e.packing_input,
        "Reuse the relaxed packing of an earlier run file (HDF5) instead of making "
        "one; empty: make a packing. Relative to this parameter file.",
        Patterns::Anything());
  entry(prm, "initial volume fraction", p.packing.initial_volume_fraction,
        "Random placement happens at this volume fraction, before compression.",
        Patterns::Double(0.05, 0.95));
  entry(prm, "compression step", p.packing.compression_step,
        "Increase of phi between relaxations during compression.", Patterns::Double(1e-4, 0.1));
  entry(prm, "stage tolerance", p.packing.stage_tolerance,
        "Residual max|F|/<|f|> at which a compression stage stops.", Patterns::Double(1e-12, 1.0));
  entry(prm, "stage iterations", e.stage_iterations,
        "FIRE iterations allowed per compression stage (the compression rate).",
        Patterns::Integer(1));
  entry(prm, "force tolerance", p.packing.relaxation.force_tolerance,
        "Residual max|F|/<|f|> of the final relaxation to force balance.",
        Patterns::Double(1e-15, 1e-2));
  entry(prm, "max iterations", e.max_relaxation_iterations,
        "FIRE iterations allowed for the final relaxation.", Patterns::Integer(1));
  prm.leave_subsection();
}

void declare_contact_law(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("contact law");
  entry(prm, "law", p.contact_law.name,
        documented_choice("Elastic contact law f = E* R_c^2 F(eps), eps = h/R_c (docs/physics.md):",
                          contact_laws()),
        Patterns::Selection(contact_laws().selection()));
  for (const ContactLawEntry& law : contact_laws().entries()) declare_coefficients(prm, law, e);
  prm.leave_subsection();
}

void declare_shear(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("shear");
  entry(prm, "gamma dot tilde", p.shear_model.gamma_tilde,
        "Dimensionless shear rate gamma_dot eta_s / E* (the paper: 1e-9 ... 1e-4).",
        Patterns::Double(1e-14, 1e-1));
  entry(prm, "mobility factor", p.shear_model.mobility_factor,
        "f_r in the mobility M = f_r / (6 pi eta_s R) against the affine flow (the paper: 0.01; "
        "results unchanged below 0.1). Above 1 that friction is weaker than a free sphere's "
        "Stokes drag: the films carry the dissipation (docs/physics.md).",
        Patterns::Double(kMinMobilityFactor, kMaxMobilityFactor));
  entry(prm, "sample interval", p.protocol.sample_interval, "Strain between stress samples.",
        Patterns::Double(1e-6, 0.5));
  entry(prm, "check interval", p.protocol.check_interval, "Strain between steady-state checks.",
        Patterns::Double(1e-6, 1e6));
  entry(prm, "min strain", p.protocol.min_strain, "Never stop before this strain.",
        Patterns::Double(0.0, 1e6));
  entry(prm, "max strain", p.protocol.max_strain, "Stop (unconverged) at this strain.",
        Patterns::Double(0.0, 1e6));
  entry(prm, "min stationary strain", p.protocol.min_stationary_strain,
        "The averaged (stationary) window must span at least this strain.",
        Patterns::Double(0.0, 1e6));
  entry(prm, "snapshot interval", p.protocol.snapshot_interval,
        "Strain between configurations stored for structure analysis (0: none).",
        Patterns::Double(0.0, 1e6));
  entry(prm, "target relative error", p.protocol.target_relative_error,
        "Stop when the standard errors of sigma, N1 and N2 are below this fraction "
        "of their means.",
        Patterns::Double(1e-6, 1.0));
  prm.leave_subsection();
}

void declare_drag(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("drag");
  entry(prm, "ehd", p.shear_model.drag.enabled,
        "Include the elastohydrodynamic drag between sliding facets.", Patterns::Bool());
  entry(prm, "velocity", e.film_velocity,
        "Relative velocity the EHD drag acts on: tangential (the paper: sliding of the facets), "
        "full (also approach and separation, a declared extension) or nonaffine (sliding "
        "relative to the affine flow, a diagnostic); docs/physics.md.",
        Patterns::Selection(film_velocity_names()));
  entry(prm, "film rest thickness", p.shear_model.drag.rest_thickness,
        "Thickness h0 of a film at rest, in units of the mean radius R (a surfactant film: nm "
        "over R): the film drags linearly, eta_s u A/h0, below the sliding speed at which the "
        "EHD film would be thinner than h0 (a declared extension; docs/physics.md). 0: the "
        "paper's law at every speed.",
        Patterns::Double(0.0, 0.5));
  entry(prm, "stokes reference", e.stokes_reference,
        "What the Stokes friction 6 pi eta_s R / f_r acts against: affine (the paper: the motion "
        "relative to the imposed flow) or neighbours (relative to the contacting particles, as "
        "pair dashpots; docs/physics.md).",
        Patterns::Selection(stokes_reference_names()));
  entry(prm, "stokes reservoir share", p.shear_model.drag.stokes.reservoir_share,
        "For stokes reference = neighbours: share of the friction left against the affine flow "
        "(keeps particles without contacts moving with the solvent).",
        Patterns::Double(1e-6, 1.0));
  entry(prm, "coupling", e.coupling,
        "implicit: velocities solved with the drag at every step (Newton); lagged: "
        "drag from the previous velocities (for measuring that error only).",
        Patterns::Selection("implicit|lagged"));
  entry(prm, "tolerance", p.shear_model.drag.tolerance,
        "Velocity residual of the implicit solve, relative to max(1, max|v|).",
        Patterns::Double(1e-14, 1e-2));
  entry(prm, "max newton iterations", p.shear_model.drag.max_newton_iterations,
        "Newton iterations allowed per velocity solve.", Patterns::Integer(1, 10000));
  prm.leave_subsection();
}

void declare_integrator(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("integrator");
  entry(prm, "scheme", p.integrator.name,
        documented_choice(fmt::format("Time integrator (docs/integrators.md): auto: euler at "
                                      "gamma~ >= {:g} with drag/stokes reference = affine, "
                                      "bdf2 below and with neighbours;",
                                      kAutoImplicitBelow),
                          integrators()),
        Patterns::Selection("auto|" + integrators().selection()));
  entry(prm, "tolerance", p.integrator.tolerance,
        "Local position error allowed per step, in units of R; 0: the scheme's default "
        "(euler 1e-4, implicit 1e-3, bdf2 3e-3).",
        Patterns::Double(0.0, 0.1));
  entry(prm, "stability fraction", p.integrator.stability_fraction,
        "Fraction of the explicit stability limit 2/lambda used at most.",
        Patterns::Double(0.01, 0.99));
  entry(prm, "max step", p.integrator.max_step, "Largest step (strain).",
        Patterns::Double(1e-12, 1.0));
  entry(prm, "solver tolerance", p.integrator.solver_tolerance,
        "implicit: residual force of a step's nonlinear solve, relative to the mean contact "
        "force.",
        Patterns::Double(1e-15, 1e-3));
  prm.leave_subsection();
}

void declare_structure(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("structure");
  entry(prm, "bin width", p.structure.bin_width, "Radial bin width of g_lm(r), units of R.",
        Patterns::Double(1e-4, 0.5));
  entry(prm, "range", p.structure.range, "Largest pair distance analysed, units of R.",
        Patterns::Double(2.0, 10.0));
  entry(prm, "slab half-width", p.structure.slab,
        "g(r, theta) in the flow-gradient plane counts pairs with |dz| below this, units of R.",
        Patterns::Double(1e-3, 1.0));
  entry(prm, "map bin width", p.structure.map_bin_width, "Radial bin width of g(r, theta).",
        Patterns::Double(1e-3, 0.5));
  entry(prm, "angle bins", p.structure.angle_bins, "Angular bins of g(r, theta).",
        Patterns::Integer(8, 720));
  entry(prm, "batches", p.structure.batches, "Batches of snapshots for the error estimates.",
        Patterns::Integer(2, 1000));
  prm.leave_subsection();
}

void declare_neighbours(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("neighbours");
  entry(prm, "skin", p.packing.skin, "Verlet-list skin, in units of R.",
        Patterns::Double(0.01, 2.0));
  prm.leave_subsection();
}

void declare_output(ParameterHandler& prm, Entries& e) {
  MicroParameters& p = e.p;
  prm.enter_subsection("output");
  entry(prm, "file", e.output_file,
        "HDF5 result file (relative to the current directory); the command line "
        "option --output overrides it.",
        Patterns::Anything());
  entry(prm, "overwrite", p.overwrite, "Replace an existing output file.", Patterns::Bool());
  prm.leave_subsection();
}

// Every entry of a `micro run` file, subsection by subsection.
void declare(ParameterHandler& prm, Entries& e) {
  declare_model(prm, e);
  declare_particles(prm, e);
  declare_packing(prm, e);
  declare_contact_law(prm, e);
  declare_shear(prm, e);
  declare_drag(prm, e);
  declare_integrator(prm, e);
  declare_structure(prm, e);
  declare_neighbours(prm, e);
  declare_output(prm, e);
}

std::filesystem::path beside(const std::filesystem::path& prm_file, const std::string& name) {
  if (name.empty()) return {};
  const std::filesystem::path path(name);
  return path.is_absolute() ? path : prm_file.parent_path() / path;
}

// `text` (printed by ParameterHandler) without its top-level subsection `name`.
std::string without_subsection(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line, out;
  int depth = 0;
  bool skipping = false;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(' ');
    const std::string word = first == std::string::npos ? "" : line.substr(first);
    const bool opens = word.rfind("subsection ", 0) == 0, closes = word == "end";
    if (opens && depth == 0 && word == "subsection " + name) skipping = true;
    if (!skipping) out += line + '\n';
    depth += opens ? 1 : closes ? -1 : 0;
    if (skipping && depth == 0 && closes) skipping = false;
  }
  return out;
}

// The chosen law's coefficients, files resolved beside the parameter file,
// completed and checked by the registry.
ComponentValues law_coefficients(const Entries& e, const std::string& law,
                                 const std::filesystem::path& file) {
  ContactLawSpec spec{.name = law};
  for (const ComponentParameter& c : contact_laws().at(law).parameters) {
    const std::string name = law + " " + c.name;
    std::string value = e.law_coefficients.at(name);
    if (c.kind == ComponentParameter::Kind::file) {
      require(!value.empty(),
              fmt::format("contact law '{}' needs '{}' in subsection 'contact law'", law, name));
      value = beside(file, value).string();
    }
    spec.coefficients.set(c.name, value);
  }
  return completed(spec).coefficients;
}

// The engine's types from the parsed entries, checked as a whole.
MicroParameters convert(const ParameterHandler& prm, const Entries& e,
                        const std::filesystem::path& file) {
  MicroParameters p = e.p;
  p.packing.particles = e.particles;
  p.packing.seed = e.seed;
  p.packing.stage_iterations = e.stage_iterations;
  p.packing.relaxation.max_iterations = e.max_relaxation_iterations;
  p.shear_model.drag.coupling = parse_drag_coupling(e.coupling);
  p.shear_model.drag.film.velocity = parse_film_velocity(e.film_velocity);
  p.shear_model.drag.stokes.reference = parse_stokes_reference(e.stokes_reference);
  p.packing_input = beside(file, e.packing_input);
  p.contact_law.coefficients = law_coefficients(e, p.contact_law.name, file);
  p.output_file = e.output_file;
  require(!e.output_file.empty(), "output file name is empty");
  require(p.packing.initial_volume_fraction <= p.packing.volume_fraction,
          fmt::format("initial volume fraction = {} exceeds the volume fraction {}",
                      p.packing.initial_volume_fraction, p.packing.volume_fraction));
  require(p.protocol.max_strain >= p.protocol.min_strain,
          fmt::format("max strain = {} is below min strain = {}", p.protocol.max_strain,
                      p.protocol.min_strain));
  p.packing.validate();
  p.shear_model.validate();
  p.protocol.validate();
  p.integrator.validate();
  p.structure.validate();

  std::ostringstream text;
  prm.print_parameters(text, ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
  p.text = without_subsection(
      without_subsection(without_subsection(text.str(), "sweep"), "oscillation"), "walls");
  return p;
}

// The `sweep` subsection of a sweep file (micro/sweep/sweep_plan.h).
struct SweepEntries {
  SweepSpec spec;
  std::string directory = "sweep";
  unsigned long packings = 0, first_seed = 1, particles = 0, checkpoint_steps = 20000;
};

void declare_sweep(ParameterHandler& prm, SweepEntries& s) {
  prm.enter_subsection("sweep");
  entry(prm, "preset", s.spec.preset,
        "Fidelity: fast, standard or paper (docs/sweeps.md states their error and cost), or "
        "custom. A preset fixes N, the lists below when they are empty, the number of packings "
        "when it is 0, and each run's length (shear/target relative error, min and max strain, "
        "min stationary strain); custom takes all of them from this file.",
        Patterns::Selection("fast|standard|paper|custom"));
  entry(prm, "volume fractions", s.spec.volume_fractions,
        "Volume fractions phi (comma-separated); empty: the preset's. Overrides "
        "particles/volume fraction.",
        Patterns::List(Patterns::Double(0.64, 0.95), 0, 1000, ","));
  entry(prm, "gamma dot tildes", s.spec.gamma_tildes,
        "Shear rates gamma~ (comma-separated); empty: the preset's. Overrides "
        "shear/gamma dot tilde.",
        Patterns::List(Patterns::Double(1e-14, 1e-1), 0, 1000, ","));
  entry(prm, "packings", s.packings,
        "Packings (seeds first seed, first seed + 1, ...) per volume fraction; 0: the preset's.",
        Patterns::Integer(0, 1000));
  entry(prm, "first seed", s.first_seed, "Seed of the first packing.", Patterns::Integer(0));
  entry(prm, "particles", s.particles,
        "Particles per packing; 0: the preset's. Overrides particles/number.",
        Patterns::Integer(0, 50000000));
  entry(prm, "output directory", s.directory,
        "Folder of the sweep: packings/, runs/, flow_curve.csv, flow_curve_packings.csv, "
        "flow_curve.h5. Relative to the current directory.",
        Patterns::Anything());
  entry(prm, "checkpoint steps", s.checkpoint_steps,
        "A running case saves its state every this many accepted steps (about a minute for "
        "N = 1000 at the default) and a rerun goes on from it; 0: no checkpoints.",
        Patterns::Integer(0));
  entry(prm, "quasi-static", s.spec.quasi_static,
        "Add a quasi-static case per volume fraction and packing: athermal quasi-static shear "
        "(strain steps, each followed by energy minimisation) of the same packing, whose "
        "stationary stress is the dynamic yield stress sigma_y, written as the gamma~ = 0 row of "
        "the flow curve. It stops by the rule of subsection shear (min and max strain, target "
        "relative error); gamma dot tilde, drag and integrator do not apply to it.",
        Patterns::Bool());
  entry(prm, "quasi-static strain step", s.spec.quasi_static_strain_step,
        "Strain step of the quasi-static cases: > 0 and at most shear/sample interval. The "
        "default gives the stationary stresses of a five times finer step at half its cost "
        "(docs/sweeps.md).",
        Patterns::Double(0.0, kMaxAqsStrainStep));
  entry(prm, "quasi-static force tolerance", s.spec.quasi_static_force_tolerance,
        "Each quasi-static step is minimised until no particle's net force exceeds this times the "
        "mean contact force: > 0 and at most 1e-3 (docs/sweeps.md measures what it costs and "
        "changes).",
        Patterns::Double(0.0, kMaxAqsForceTolerance));
  prm.leave_subsection();
}

// The `oscillation` subsection of an oscillation file (micro/sweep/oscillation_plan.h).
struct OscillationEntries {
  OscillationSpec spec;
  std::string directory = "oscillation";
  unsigned long packings = 1, first_seed = 1, checkpoint_steps = 20000;
  unsigned long samples_per_cycle = 64, min_cycles = 4, max_cycles = 40, min_periodic_cycles = 3;
};

void declare_oscillation(ParameterHandler& prm, OscillationEntries& o) {
  prm.enter_subsection("oscillation");
  entry(prm, "amplitudes", o.spec.amplitudes,
        "Strain amplitudes gamma0 of gamma(t) = gamma0 sin(omega t) (comma-separated): an "
        "amplitude sweep.",
        Patterns::List(Patterns::Double(1e-6, 10.0), 1, 1000, ","));
  entry(prm, "frequencies", o.spec.frequencies,
        "Reduced angular frequencies omega~ = omega eta_s / E* (comma-separated): a frequency "
        "sweep. The model's gamma~ is each case's peak rate gamma0 omega~, which must lie in "
        "[1e-14, 1e-1].",
        Patterns::List(Patterns::Double(1e-16, 1e-2), 1, 1000, ","));
  entry(prm, "volume fractions", o.spec.volume_fractions,
        "Volume fractions phi (comma-separated); empty: particles/volume fraction.",
        Patterns::List(Patterns::Double(0.64, 0.95), 0, 1000, ","));
  entry(prm, "packings", o.packings,
        "Packings (seeds first seed, first seed + 1, ...) per volume fraction.",
        Patterns::Integer(1, 1000));
  entry(prm, "first seed", o.first_seed, "Seed of the first packing.", Patterns::Integer(0));
  entry(prm, "samples per cycle", o.samples_per_cycle,
        "Stress samples per cycle, at equally spaced phases (a multiple of 4: the strain "
        "reversals are samples); harmonics up to the fifth need at least 16.",
        Patterns::Integer(16, 4096));
  entry(prm, "min cycles", o.min_cycles,
        "Never stop before this many cycles (the first, a start-up from rest, is never used).",
        Patterns::Integer(3, 100000));
  entry(prm, "max cycles", o.max_cycles, "Stop (unconverged) after this many cycles.",
        Patterns::Integer(3, 100000));
  entry(prm, "min periodic cycles", o.min_periodic_cycles,
        "The periodic state must span at least this many cycles.", Patterns::Integer(2, 100000));
  entry(prm, "target relative error", o.spec.protocol.target_relative_error,
        "Stop when the standard errors of G' and G'' over the periodic cycles are below this "
        "fraction of |G*|.",
        Patterns::Double(1e-6, 1.0));
  entry(prm, "output directory", o.directory,
        "Folder of the sweep: packings/, runs/, oscillation.csv, oscillation_packings.csv, "
        "oscillation.h5. Relative to the current directory.",
        Patterns::Anything());
  entry(prm, "checkpoint steps", o.checkpoint_steps,
        "A running case saves its state every this many accepted steps and a rerun goes on "
        "from it; 0: no checkpoints.",
        Patterns::Integer(0));
  prm.leave_subsection();
}

// The `walls` subsection of a slip file (`micro slip`, protocol/wall_run.h).
struct WallEntries {
  SlipSpec spec;
  std::string directory = "slip";
  unsigned long packings = 1, first_seed = 1, bins = 20;
  std::string solvent = "local mean";
};

void declare_walls(ParameterHandler& prm, WallEntries& w) {
  prm.enter_subsection("walls");
  entry(prm, "apparent rates", w.spec.apparent_rates,
        "Apparent shear rates gamma~_app = (V_top - V_bottom) eta_s / (H E*) the walls impose "
        "(comma-separated); each is the model's gamma~ of its run.",
        Patterns::List(Patterns::Double(1e-14, 1e-1), 1, 1000, ","));
  entry(prm, "solvent flow", w.solvent,
        "What the reservoir share of the Stokes friction acts against between the walls: the "
        "local mean flow of the particles (the solvent is carried with them) or the affine flow "
        "of the apparent rate (docs/physics.md, 'Wall slip').",
        Patterns::Selection(solvent_reference_names()));
  entry(prm, "packings", w.packings, "Packings (seeds first seed, first seed + 1, ...).",
        Patterns::Integer(1, 1000));
  entry(prm, "first seed", w.first_seed, "Seed of the first packing.", Patterns::Integer(0));
  entry(prm, "strain", w.spec.run.strain,
        "Apparent strain of each run (the first part, a transient, is cut by MSER-5).",
        Patterns::Double(0.0, 1e4));
  entry(prm, "sample interval", w.spec.run.sample_interval, "Apparent strain between samples.",
        Patterns::Double(0.0, 1.0));
  entry(prm, "central fraction", w.spec.run.sampling.central_fraction,
        "Share of the gap, centred, in which the bulk stress and shear rate are measured.",
        Patterns::Double(0.0, 1.0));
  entry(prm, "profile bins", w.bins, "Bins of the velocity profile across the gap.",
        Patterns::Integer(2, 10000));
  entry(prm, "output directory", w.directory,
        "Folder of the runs: runs/*.h5 and *.csv, slip.csv. Relative to the current directory.",
        Patterns::Anything());
  prm.leave_subsection();
}

}  // namespace

// Parses `file`, then fills in what its model preset sets and the file does
// not; returns the entries the file sets.
std::vector<SetEntry> parse_with_model_preset(ParameterHandler& prm,
                                              const std::filesystem::path& file) {
  std::vector<SetEntry> set = parse_parameter_file(prm, file, "parameter file");
  apply_model_preset(prm, set);
  return set;
}

MicroParameters read_parameter_file(const std::filesystem::path& file) {
  ParameterHandler prm;
  Entries e;
  declare(prm, e);
  parse_with_model_preset(prm, file);
  return convert(prm, e, file);
}

namespace {

// Parses a file that extends a run file by subsection `extension` (declared
// in `prm` with the run's entries). A run file given to a sweep command would
// start hours of its defaults' work: such a file must set something in its
// subsection; `example` says what.
void parse_extended_file(ParameterHandler& prm, const std::filesystem::path& file,
                         const std::string& extension, const std::string& example) {
  const std::vector<SetEntry> set = parse_with_model_preset(prm, file);
  const auto in_extension = [&](const SetEntry& e) {
    return !e.subsections.empty() && e.subsections.front() == extension;
  };
  if (std::none_of(set.begin(), set.end(), in_extension)) {
    throw InputError(fmt::format(
        "'{}' sets nothing in subsection '{}': it is not {} file (a run file is for `micro "
        "run`); {}",
        file.string(), extension,
        extension == "sweep" ? "a sweep" : extension == "walls" ? "a slip" : "an oscillation",
        example));
  }
}

}  // namespace

SweepParameters read_sweep_file(const std::filesystem::path& file) {
  ParameterHandler prm;
  Entries e;
  SweepEntries s;
  declare(prm, e);
  declare_sweep(prm, s);
  parse_extended_file(prm, file, "sweep",
                      "a sweep file names at least its preset, e.g. 'subsection sweep / set "
                      "preset = fast' (docs/sweeps.md)");
  require(s.particles != 1, "sweep: particles = 1; allowed: 0 (the preset's N) or 2 ... 50000000");
  SweepParameters sweep;
  sweep.base = convert(prm, e, file);
  sweep.spec = s.spec;
  sweep.spec.packings = static_cast<unsigned>(s.packings);
  sweep.spec.first_seed = static_cast<unsigned>(s.first_seed);
  sweep.spec.particles = s.particles;
  sweep.spec.checkpoint_steps = s.checkpoint_steps;
  sweep.spec.scheme = sweep.base.integrator.name;
  sweep.spec.stokes = sweep.base.shear_model.drag.stokes.reference;
  require(!s.directory.empty(), "sweep: output directory is empty");
  sweep.spec.directory = s.directory;
  // A sample averages whole strain steps (protocol/quasi_static_run.h).
  require(!sweep.spec.quasi_static ||
              sweep.spec.quasi_static_strain_step <= sweep.base.protocol.sample_interval,
          fmt::format("sweep: 'quasi-static strain step' = {} exceeds shear/'sample interval' = {}",
                      sweep.spec.quasi_static_strain_step, sweep.base.protocol.sample_interval));
  return sweep;
}

OscillationParameters read_oscillation_file(const std::filesystem::path& file) {
  ParameterHandler prm;
  Entries e;
  OscillationEntries o;
  declare(prm, e);
  declare_oscillation(prm, o);
  parse_extended_file(prm, file, "oscillation",
                      "an oscillation file names at least its amplitudes, e.g. 'subsection "
                      "oscillation / set amplitudes = 1e-3, 1e-2, 0.1' (docs/oscillation.md)");
  OscillationParameters osc;
  osc.base = convert(prm, e, file);
  OscillationSpec& spec = osc.spec;
  spec = o.spec;
  if (spec.volume_fractions.empty()) spec.volume_fractions = {osc.base.packing.volume_fraction};
  spec.packings = static_cast<unsigned>(o.packings);
  spec.first_seed = static_cast<unsigned>(o.first_seed);
  spec.particles = osc.base.packing.particles;
  spec.protocol.samples_per_cycle = static_cast<unsigned>(o.samples_per_cycle);
  spec.protocol.min_cycles = static_cast<unsigned>(o.min_cycles);
  spec.protocol.max_cycles = static_cast<unsigned>(o.max_cycles);
  spec.protocol.min_periodic_cycles = static_cast<unsigned>(o.min_periodic_cycles);
  spec.checkpoint_steps = o.checkpoint_steps;
  spec.scheme = osc.base.integrator.name;
  spec.stokes = osc.base.shear_model.drag.stokes.reference;
  require(!o.directory.empty(), "oscillation: output directory is empty");
  spec.directory = o.directory;
  // The protocol's own checks (multiple of 4, cycles), at the first case's
  // amplitude and frequency; make_oscillation_plan checks every case.
  OscillationProtocol first = spec.protocol;
  first.amplitude = spec.amplitudes.front();
  first.frequency = spec.frequencies.front();
  try {
    first.validate();
  } catch (const InputError& error) {
    throw InputError(fmt::format("oscillation: {}", error.what()));
  }
  return osc;
}

SlipParameters read_slip_file(const std::filesystem::path& file) {
  ParameterHandler prm;
  Entries e;
  WallEntries w;
  declare(prm, e);
  declare_walls(prm, w);
  parse_extended_file(prm, file, "walls",
                      "a slip file names at least its apparent rates, e.g. 'subsection walls / set "
                      "apparent rates = 1e-6, 1e-5' (docs/physics.md, 'Wall slip')");
  SlipParameters slip;
  slip.base = convert(prm, e, file);
  slip.spec = w.spec;
  require_sorted_unique(slip.spec.apparent_rates, "apparent rates", "walls");
  slip.spec.packings = static_cast<unsigned>(w.packings);
  slip.spec.first_seed = static_cast<unsigned>(w.first_seed);
  slip.spec.run.sampling.bins = w.bins;
  slip.spec.solvent = parse_solvent_reference(w.solvent);
  require(!w.directory.empty(), "walls: output directory is empty");
  slip.spec.directory = w.directory;
  slip.spec.run.validate();
  return slip;
}

MicroParameters case_parameters(const MicroParameters& base, const SweepCaseSettings& c) {
  ParameterHandler prm;
  Entries e;
  declare(prm, e);
  try {
    prm.parse_input_from_string(base.text, "", true);
    prm.enter_subsection("particles");
    prm.set("number", static_cast<long int>(c.particles));
    prm.set("volume fraction", c.volume_fraction);
    prm.set("seed", static_cast<long int>(c.seed));
    prm.leave_subsection();
    prm.enter_subsection("shear");
    prm.set("gamma dot tilde", c.gamma_tilde);
    if (c.run) {
      prm.set("target relative error", c.run->target_relative_error);
      prm.set("min strain", c.run->min_strain);
      prm.set("max strain", c.run->max_strain);
      prm.set("min stationary strain", c.run->min_stationary_strain);
    }
    prm.leave_subsection();
    prm.enter_subsection("packing");
    prm.set("input file", c.packing_input.string());
    prm.leave_subsection();
    prm.enter_subsection("output");
    prm.set("file", c.output.string());
    prm.leave_subsection();
  } catch (const std::exception& error) {
    throw InputError(fmt::format("sweep case phi = {}, gamma~ = {}: {}", c.volume_fraction,
                                 c.gamma_tilde, deal_ii_message(error.what())));
  }
  MicroParameters p = convert(prm, e, std::filesystem::path());
  p.contact_law.coefficients = base.contact_law.coefficients;  // files already resolved
  return p;
}

std::string parameter_template(TemplateKind kind) {
  ParameterHandler prm;
  Entries e;
  SweepEntries s;
  OscillationEntries o;
  WallEntries w;
  declare(prm, e);
  if (kind == TemplateKind::sweep) declare_sweep(prm, s);
  if (kind == TemplateKind::oscillation) declare_oscillation(prm, o);
  if (kind == TemplateKind::slip) declare_walls(prm, w);
  std::ostringstream text;
  text
      << (kind == TemplateKind::sweep
              ? "# softglass micro: sweep file for `micro sweep` (docs/sweeps.md).\n"
          : kind == TemplateKind::oscillation
              ? "# softglass micro: oscillation file for `micro oscillate` (docs/oscillation.md).\n"
          : kind == TemplateKind::slip
              ? "# softglass micro: slip file for `micro slip` (docs/physics.md, 'Wall slip').\n"
              : "# softglass micro: parameter file for `micro pack` and `micro run`.\n")
      << "# Reduced units: lengths R (mean radius), stresses E*, time 1/gamma_dot (strain).\n";
  prm.print_parameters(text, ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
  return text.str();
}

}  // namespace softglass::micro
