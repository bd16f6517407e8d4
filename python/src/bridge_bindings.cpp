// Laws, predictions and materials of the bridge in Python: a law file read
// once (with the simulated points and the model's error beside it), the four
// prediction modes of bridge/material/prediction.h at any rates with their
// bands, and the two kinds of material a macro scene takes — each made by the
// very functions `bridge predict` and `bridge material` call, so that the
// numbers are the command line's.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bridge/app/law_file.h"
#include "bridge/law/law.h"
#include "bridge/material/material.h"
#include "bridge/material/model_error.h"
#include "bridge/material/prediction.h"
#include "bridge/material/tabulated_material.h"
#include "common/errors.h"
#include "common/version.h"
#include "python/src/bindings.h"

namespace softglass::python {

namespace {

using namespace softglass::bridge;
using Path = std::filesystem::path;

// A law file with what lies beside it: the simulated points (read when a
// prediction or a tabulated material first needs them: a law without them
// still makes Herschel–Bulkley materials) and the scoreboard's model error.
struct LoadedLaw {
  Path path;
  Law law;
  std::optional<ModelError> model_error;
  std::optional<SimulatedCurves> curves;

  const SimulatedCurves& simulated() {
    if (!curves) curves = read_simulated_curves(path, law);
    return *curves;
  }
};

// A material with the comment lines that open its fragment.
struct HbMaterial {
  Material material;
  std::vector<std::string> provenance;
};
struct TableMaterial {
  TabulatedMaterial material;
  std::vector<std::string> provenance;
};

// The keyword arguments every mode takes, named as `bridge predict`'s
// options (whose names the library's messages use).
struct ModeArguments {
  double phi = 0.0, viscosity = 0.0;
  std::optional<double> modulus, plateau_modulus, yield_stress, interfacial_tension, radius;
  std::optional<MeasuredCurve> fit_to;
  bool extrapolate = false;
};

std::vector<std::string> opening_lines(const std::string& title, const Path& law) {
  return {title, fmt::format("software: softglass {} ({}), Python module", kVersion, kGitRevision),
          "law:      " + law.string()};
}

// E* as given, or 9.92 γ_i/R of an emulsion (a provenance line then).
std::optional<double> given_modulus(const ModeArguments& a, std::vector<std::string>& lines) {
  if (a.interfacial_tension || a.radius) {
    require(a.interfacial_tension && a.radius,
            "give the interfacial tension and the radius together (E* = 9.92 gamma_i / R)");
    require(!a.modulus, "give E* (modulus) or the interfacial tension and radius, not both");
    const double e_star = emulsion_contact_modulus(*a.interfacial_tension, *a.radius);
    lines.push_back(fmt::format(
        "E* = 9.92 gamma_i / R = 9.92 x {:.6g} N/m / {:.6g} m = {:.6g} Pa (Seth et al. 2006, "
        "emulsions)",
        *a.interfacial_tension, *a.radius, e_star));
    return e_star;
  }
  return a.modulus;
}

PredictionInputs prediction_inputs(const LoadedLaw& law, const ModeArguments& a,
                                   const std::string& form, std::vector<std::string>& lines) {
  require(form == "tabulated" || form == "herschel-bulkley",
          fmt::format("form = '{}': tabulated or herschel-bulkley", form));
  PredictionInputs in;
  in.phi = a.phi;
  in.viscosity = a.viscosity;
  in.extrapolate = a.extrapolate;
  in.modulus = given_modulus(a, lines);
  in.plateau_modulus = a.plateau_modulus;
  in.yield_stress = a.yield_stress;
  in.measured_curve = a.fit_to;
  in.form = form == "tabulated" ? LawForm::tabulated : LawForm::herschel_bulkley;
  in.model_error = law.model_error;
  return in;
}

Prediction predict_at(LoadedLaw& law, const std::vector<double>& rates, const ModeArguments& a,
                      const std::string& form) {
  std::vector<std::string> lines;
  const PredictionInputs in = prediction_inputs(law, a, form, lines);
  Prediction p = predict(law.law, law.simulated(), in, rates);
  p.notes.insert(p.notes.begin(), lines.begin(), lines.end());
  return p;
}

// `bridge material` without --tabulated: E* given, from γ_i and R, or from
// a measured G′ matched to the law's static G0 (modes a and b).
HbMaterial hb_material(const LoadedLaw& law, const ModeArguments& a) {
  require(!a.yield_stress && !a.fit_to,
          "modes (c) and (d) (yield_stress, fit_to) give the simulated flow curve itself: use "
          "tabulated_material");
  std::vector<std::string> lines =
      opening_lines("softglass: a Herschel-Bulkley material from a law file", law.path);
  std::optional<double> e_star = given_modulus(a, lines);
  require(!(e_star && a.plateau_modulus),
          "give E* (modulus, or interfacial_tension with radius) or the measured G' "
          "(plateau_modulus), not both: each sets E*");
  if (a.plateau_modulus) {
    const MaterialValue m =
        contact_modulus_from_plateau(law.law, a.phi, *a.plateau_modulus, a.extrapolate);
    lines.push_back(fmt::format("E* = G' / (G0/E*)(phi), the law's static G0 = {:.6g} Pa {}",
                                m.value, relative_error_text(m)));
    e_star = m.value;
  }
  require(e_star.has_value(),
          "no E*: give modulus, interfacial_tension with radius, or plateau_modulus");
  const std::string mode = mode_name(a.plateau_modulus ? PredictionMode::plateau_modulus
                                                       : PredictionMode::nothing_fitted);
  lines.push_back("mode:     " + mode);
  Material material = make_material(law.law, {a.phi, *e_star, a.viscosity, a.extrapolate});
  material.source = mode;
  return {std::move(material), std::move(lines)};
}

// `bridge material --tabulated`, in the mode the inputs call for.
TableMaterial tabulated(LoadedLaw& law, const ModeArguments& a) {
  std::vector<std::string> lines = opening_lines(
      "softglass: the simulated flow curve, tabulated, from a law file", law.path);
  const PredictionInputs in = prediction_inputs(law, a, "tabulated", lines);
  const PredictionScales scales = prediction_scales(law.law, law.simulated(), in);
  lines.push_back("mode:     " + mode_name(scales.mode));
  for (const std::string& note : scales.notes) lines.push_back("          " + note);
  return {tabulated_material_in_mode(law.law, law.simulated(), in, scales), std::move(lines)};
}

const char* quantity_key(Quantity q) { return column_name(q); }

Quantity quantity_of(const std::string& name) {
  for (const Quantity q : kAllQuantities)
    if (name == column_name(q)) return q;
  throw InputError(fmt::format("no quantity '{}': sigma, N1, N2 or f_m", name));
}

py::dict estimates(const std::vector<Estimate>& values, const char* name) {
  std::vector<double> value, error;
  for (const Estimate& e : values) {
    value.push_back(e.value);
    error.push_back(e.error);
  }
  py::dict d;
  d[name] = to_array(value);
  d[py::str(fmt::format("{}_error", name))] = to_array(error);
  return d;
}

// The Herschel–Bulkley law of one quantity per φ: yield, consistency,
// exponent with their errors, and the correlation of ln|k| and the exponent.
py::dict hb_law(const LoadedLaw& l, const std::string& name) {
  const std::optional<HbLaw>& hb = l.law.hb[index(quantity_of(name))];
  require(hb.has_value(), fmt::format("{} has no law for {}", l.path.string(), name));
  py::dict d;
  d["phi"] = to_array(l.law.phi);
  for (const auto& [values, key] : {std::pair{&hb->yield, "yield"},
                                    std::pair{&hb->consistency, "consistency"},
                                    std::pair{&hb->exponent, "exponent"}})
    for (const auto& item : estimates(*values, key)) d[item.first] = item.second;
  d["correlation"] = to_array(hb->correlation);
  return d;
}

// The per-point values of one quantity of a prediction: None when the law
// has none.
py::object predicted(const Prediction& p, Quantity q, bool band) {
  if (p.points.empty() || !p.points.front().value[index(q)]) return py::none();
  std::vector<double> v;
  for (const PredictedPoint& point : p.points) {
    const Band& b = *point.value[index(q)];
    v.push_back(band ? b.band : b.value);
  }
  return to_array(v);
}

// A tabulated material's rows: rate and each quantity with its error.
py::dict material_rows(const std::vector<TabulatedRow>& rows) {
  std::vector<double> rate;
  for (const TabulatedRow& r : rows) rate.push_back(r.rate);
  py::dict d;
  d["rate"] = to_array(rate);
  for (const Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
    if (rows.empty() || !rows.front().value[index(q)]) continue;
    std::vector<double> value, error;
    for (const TabulatedRow& r : rows) {
      value.push_back(r.value[index(q)]->value);
      error.push_back(r.value[index(q)]->error());
    }
    d[quantity_key(q)] = to_array(value);
    d[py::str(fmt::format("{}_error", quantity_key(q)))] = to_array(error);
  }
  return d;
}

// Every mode's keyword arguments, after the φ and η_s that every call takes.
template <class Function>
auto with_mode_arguments(Function f) {
  return [f](LoadedLaw& law, double phi, double viscosity, std::optional<double> modulus,
             std::optional<double> plateau_modulus, std::optional<double> yield_stress,
             std::optional<MeasuredCurve> fit_to, std::optional<double> interfacial_tension,
             std::optional<double> radius, bool extrapolate) {
    return f(law, ModeArguments{phi, viscosity, modulus, plateau_modulus, yield_stress,
                                interfacial_tension, radius, std::move(fit_to), extrapolate});
  };
}

auto mode_keywords() {
  return std::tuple{py::kw_only(),
                    py::arg("phi"),
                    py::arg("viscosity"),
                    py::arg("modulus") = py::none(),
                    py::arg("plateau_modulus") = py::none(),
                    py::arg("yield_stress") = py::none(),
                    py::arg("fit_to") = py::none(),
                    py::arg("interfacial_tension") = py::none(),
                    py::arg("radius") = py::none(),
                    py::arg("extrapolate") = false};
}

void bind_values(py::module_& m) {
  py::class_<MaterialValue>(m, "MaterialValue",
                            "A value with its statistical and interpolation errors (one "
                            "standard deviation each, in the value's units; NaN: unknown).")
      .def_readonly("value", &MaterialValue::value)
      .def_readonly("statistical", &MaterialValue::statistical)
      .def_readonly("interpolation", &MaterialValue::interpolation)
      .def_property_readonly("error", &MaterialValue::error,
                             "both errors in quadrature (the statistical alone when the "
                             "interpolation error is unknown)")
      .def("__float__", [](const MaterialValue& v) { return v.value; })
      .def("__repr__", [](const MaterialValue& v) {
        return fmt::format("MaterialValue({:.6g} {})", v.value, relative_error_text(v));
      });
}

void bind_prediction(py::module_& m) {
  py::class_<Prediction>(m, "Prediction",
                         "A predicted flow curve (bridge predict): arrays per rate in SI "
                         "units, each quantity with its one-sigma band.")
      .def_property_readonly("mode", [](const Prediction& p) { return mode_name(p.mode); })
      .def_readonly("modulus", &Prediction::modulus, "E* [Pa] the mode used")
      .def_readonly("notes", &Prediction::notes, "the mode's inputs and what the band holds")
      .def_property_readonly("rate",
                             [](const Prediction& p) {
                               std::vector<double> r;
                               for (const PredictedPoint& q : p.points) r.push_back(q.rate);
                               return to_array(r);
                             })
      .def_property_readonly("sigma", [](const Prediction& p) { return predicted(p, Quantity::sigma, false); })
      .def_property_readonly("sigma_band", [](const Prediction& p) { return predicted(p, Quantity::sigma, true); })
      .def_property_readonly("N1", [](const Prediction& p) { return predicted(p, Quantity::N1, false); })
      .def_property_readonly("N1_band", [](const Prediction& p) { return predicted(p, Quantity::N1, true); })
      .def_property_readonly("N2", [](const Prediction& p) { return predicted(p, Quantity::N2, false); })
      .def_property_readonly("N2_band", [](const Prediction& p) { return predicted(p, Quantity::N2, true); })
      .def_property_readonly(
          "sigma_model_error",
          [](const Prediction& p) {
            std::vector<double> e;
            for (const PredictedPoint& q : p.points) e.push_back(q.model_error.value_or(std::nan("")));
            return to_array(e);
          },
          "the model's systematic error of the shear stress [Pa] (NaN: not measured for the mode)")
      .def_property_readonly("extrapolated",
                             [](const Prediction& p) {
                               std::vector<bool> x;
                               for (const PredictedPoint& q : p.points) x.push_back(q.extrapolated);
                               return py::array(py::cast(x));
                             })
      .def(
          "table",
          [](const Prediction& p) { return prediction_table(p, {"softglass: a predicted flow curve"}); },
          "the CSV text `bridge predict` writes")
      .def("__len__", [](const Prediction& p) { return p.points.size(); })
      .def("__repr__", [](const Prediction& p) {
        return fmt::format("Prediction({}, {} rates, E* = {:.6g} Pa)", mode_name(p.mode),
                           p.points.size(), p.modulus.value);
      });
}

void bind_materials(py::module_& m) {
  py::class_<HbMaterial>(m, "HerschelBulkleyMaterial",
                         "tau = tau_y + K rate^n in SI units at one phi (bridge material).")
      .def_property_readonly("yield_stress", [](const HbMaterial& h) { return h.material.laws[0]->yield; })
      .def_property_readonly("consistency", [](const HbMaterial& h) { return h.material.laws[0]->consistency; })
      .def_property_readonly("flow_index", [](const HbMaterial& h) { return h.material.laws[0]->index; })
      .def(
          "normal_stress",
          [](const HbMaterial& h, const std::string& name) -> py::object {
            const Quantity q = quantity_of(name);
            require(q == Quantity::N1 || q == Quantity::N2, "normal_stress: N1 or N2");
            const std::optional<MaterialLaw>& law = h.material.laws[index(q)];
            if (!law) return py::none();
            return py::make_tuple(law->yield, law->consistency, law->index);
          },
          py::arg("name"), "(yield, consistency, index) of N1 or N2 [Pa, Pa s^n, 1], or None")
      .def_property_readonly("rate_range", [](const HbMaterial& h) {
        return py::make_tuple(h.material.rate_min, h.material.rate_max);
      }, "the simulated rates [1/s]: where the law holds")
      .def_property_readonly("placement", [](const HbMaterial& h) { return h.material.placement; })
      .def_property_readonly("source", [](const HbMaterial& h) { return h.material.source; })
      .def("text", [](const HbMaterial& h) { return material_text(h.material, h.provenance); },
           "the material fragment of docs/material-format.md (what `bridge material` writes)")
      .def("__repr__", [](const HbMaterial& h) {
        const MaterialLaw& s = *h.material.laws[0];
        return fmt::format("HerschelBulkleyMaterial(tau_y = {:.6g} Pa, K = {:.6g} Pa s^n, n = {:.4g})",
                           s.yield.value, s.consistency.value, s.index.value);
      });

  py::class_<TableMaterial>(m, "TabulatedMaterial",
                            "The simulated flow curve itself at one phi in SI units (bridge "
                            "material --tabulated).")
      .def_property_readonly("yield_stress", [](const TableMaterial& t) { return t.material.yield; })
      .def_property_readonly("rows", [](const TableMaterial& t) { return material_rows(t.material.rows); },
                             "rate [1/s] and sigma, N1, N2 [Pa] with '_error', per row")
      .def_property_readonly("plateau_rows",
                             [](const TableMaterial& t) { return material_rows(t.material.plateau_rows); },
                             "the lowest rates left out: on the yield plateau")
      .def_property_readonly("placement", [](const TableMaterial& t) { return t.material.placement; })
      .def_property_readonly("source", [](const TableMaterial& t) { return t.material.source; })
      .def("text", [](const TableMaterial& t) { return tabulated_material_text(t.material, t.provenance); },
           "the material fragment of docs/material-format.md (what `bridge material --tabulated` "
           "writes)")
      .def("__repr__", [](const TableMaterial& t) {
        return fmt::format("TabulatedMaterial({} rows, tau_y = {:.6g} Pa, {})", t.material.rows.size(),
                           t.material.yield.value, t.material.source);
      });
}

void bind_law(py::module_& m) {
  auto law = py::class_<LoadedLaw>(m, "Law", "A law file of `bridge fit` (load_law).");
  law.def_property_readonly("path", [](const LoadedLaw& l) { return l.path; })
      .def_property_readonly("phi", [](const LoadedLaw& l) { return to_array(l.law.phi); })
      .def_property_readonly("gamma_tilde_range", [](const LoadedLaw& l) {
        return py::make_tuple(l.law.gamma_tilde_min, l.law.gamma_tilde_max);
      })
      .def_property_readonly("G0", [](const LoadedLaw& l) { return estimates(l.law.modulus, "G0"); },
                             "G0/E* per phi, with 'G0_error'")
      .def_property_readonly("yield_strain",
                             [](const LoadedLaw& l) { return estimates(l.law.yield_strain, "yield_strain"); })
      .def_property_readonly("quantities",
                             [](const LoadedLaw& l) {
                               std::vector<std::string> names;
                               for (const Quantity q : kAllQuantities)
                                 if (l.law.hb[index(q)]) names.push_back(quantity_key(q));
                               return names;
                             })
      .def("herschel_bulkley", &hb_law, py::arg("quantity") = "sigma",
           "per phi: yield, consistency, exponent (reduced units) with '_error', correlation")
      .def_property_readonly("k",
                             [](const LoadedLaw& l) {
                               py::dict d;
                               for (const Quantity q : kAllQuantities)
                                 if (const auto& k = l.law.k[index(q)])
                                   d[quantity_key(q)] = py::make_tuple(k->value, k->error);
                               return d;
                             },
                             "the universal constants k, k', k'' (value, error) by quantity")
      .def_property_readonly("provenance", [](const LoadedLaw& l) { return l.law.provenance; })
      .def_property_readonly("has_model_error", [](const LoadedLaw& l) { return l.model_error.has_value(); })
      .def("text", [](const LoadedLaw& l) { return law_text(l.law); });
  std::apply(
      [&](auto... keywords) {
        law.def(
            "predict",
            [](LoadedLaw& l, const std::vector<double>& rates, double phi, double viscosity,
               std::optional<double> modulus, std::optional<double> plateau_modulus,
               std::optional<double> yield_stress, std::optional<MeasuredCurve> fit_to,
               std::optional<double> interfacial_tension, std::optional<double> radius,
               bool extrapolate, const std::string& form) {
              return predict_at(l, rates,
                                {phi, viscosity, modulus, plateau_modulus, yield_stress,
                                 interfacial_tension, radius, std::move(fit_to), extrapolate},
                                form);
            },
            py::arg("rates"), keywords..., py::arg("form") = "tabulated",
            "The flow curve at `rates` [1/s] in the mode the arguments call for (docs/bridge.md, "
            "bridge predict): (a) modulus, or interfacial_tension with radius; (b) "
            "plateau_modulus; (c) yield_stress with plateau_modulus or modulus; (d) fit_to a "
            "MeasuredCurve. phi, viscosity [Pa s]; form 'tabulated' or 'herschel-bulkley'.");
        law.def("material", with_mode_arguments(&hb_material), keywords...,
                "The Herschel-Bulkley material at phi (bridge material): E* from modulus, "
                "interfacial_tension with radius, or plateau_modulus.");
        law.def("tabulated_material", with_mode_arguments(&tabulated), keywords...,
                "The simulated flow curve as a material at phi (bridge material --tabulated), "
                "in any of the four modes.");
      },
      mode_keywords());
  law.def("__repr__", [](const LoadedLaw& l) {
    return fmt::format("Law('{}', phi {:.4g} ... {:.4g})", l.path.string(), l.law.phi.front(),
                       l.law.phi.back());
  });

  m.def(
      "load_law",
      [](const Path& file) {
        return LoadedLaw{file, read_law_file(file), read_model_error(file), std::nullopt};
      },
      py::arg("file"),
      "Reads a law file of `bridge fit` (e.g. cases/bridge_law_paper_sweep.prm); its "
      "_points.csv and _phi.csv beside it are read when a prediction needs them.");
}

}  // namespace

void bind_bridge(py::module_& m) {
  bind_values(m);
  bind_prediction(m);
  bind_materials(m);
  bind_law(m);
}

}  // namespace softglass::python
