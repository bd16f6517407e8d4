// The compiled part of the Python package softglass (python/softglass): the
// project's libraries in this process, nothing recomputed in Python.
// This file: the module itself, the project's errors as Python exceptions,
// and the readers of files — measured rheometer curves, micro run files,
// sweep tables and any softglass CSV table. Laws, predictions and materials
// are bound in bridge_bindings.cpp, macro scenes in macro_bindings.cpp.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "bridge/io/flow_curve_table.h"
#include "common/csv_table.h"
#include "common/errors.h"
#include "common/measured_curves.h"
#include "micro/io/run_file.h"
#include "micro/protocol/shear_protocol.h"
#include "micro/results/packing_average.h"
#include "python/src/bindings.h"

namespace softglass::python {

namespace {

using Path = std::filesystem::path;

// Python names of the measured quantities: the keys of a curve's dict. No
// default: a quantity the reader learns is a -Wswitch warning here.
const char* key(Measured q) {
  switch (q) {
    case Measured::shear_rate: return "shear_rate";
    case Measured::stress: return "stress";
    case Measured::N1: return "N1";
    case Measured::torque: return "torque";
    case Measured::angular_velocity: return "angular_velocity";
    case Measured::normal_force: return "normal_force";
    case Measured::storage_modulus: return "storage_modulus";
    case Measured::loss_modulus: return "loss_modulus";
    case Measured::strain_amplitude: return "strain_amplitude";
    case Measured::angular_frequency: return "angular_frequency";
  }
  return "unknown";
}

const char* key(CurveKind kind) {
  switch (kind) {
    case CurveKind::flow_curve: return "flow_curve";
    case CurveKind::amplitude_sweep: return "amplitude_sweep";
    case CurveKind::other: return "other";
  }
  return "other";
}

py::list rheometer_curves(const Path& file, const std::string& rate_unit,
                          const std::string& stress_unit, const std::string& format) {
  const MeasuredReading reading{.format = format, .rate = rate_unit, .stress = stress_unit};
  py::list curves;
  for (const RheometerCurve& c :
       read_rheometer_curves(read_measured_file(file, format), reading)) {
    py::dict d;
    d["label"] = c.label;
    d["kind"] = key(curve_kind(c));
    for (const auto& [quantity, values] : c.values) d[key(quantity)] = to_array(values);
    curves.append(d);
  }
  return curves;
}

py::list amplitude_sweeps(const Path& file, const std::string& format) {
  py::list sweeps;
  for (const MeasuredAmplitudeSweep& s : read_amplitude_sweeps(read_measured_file(file, format))) {
    py::dict d;
    d["label"] = s.label;
    d["strain_amplitude"] = to_array(s.strain);
    d["storage_modulus"] = to_array(s.storage);
    d["loss_modulus"] = to_array(s.loss);
    d["angular_frequency"] = s.angular_frequency ? py::cast(*s.angular_frequency) : py::none();
    sweeps.append(d);
  }
  return sweeps;
}

// One column of a table: numbers as an array, or, when a cell is not a
// number (the observable names of `micro summary --csv`), the cells as text.
py::object csv_column(const CsvTable& csv, std::size_t c) {
  std::vector<double> values(csv.rows());
  try {
    for (std::size_t r = 0; r < csv.rows(); ++r) values[r] = csv.number(r, c);
    return to_array(values);
  } catch (const InputError&) {
    std::vector<std::string> text;
    for (std::size_t r = 0; r < csv.rows(); ++r) text.push_back(csv.text(r, c));
    return py::cast(text);
  }
}

// Any CSV table the tools write (or read): its columns keyed by name without
// units, the units apart, and the `#` lines before the header.
py::dict csv_columns(const Path& file) {
  const CsvTable csv = CsvTable::read(file);
  py::dict columns, units;
  for (std::size_t c = 0; c < csv.columns(); ++c) {
    const ColumnName name = split_units(csv.header()[c]);
    columns[py::str(name.name)] = csv_column(csv, c);
    units[py::str(name.name)] = name.units;
  }
  py::dict d;
  d["columns"] = columns;
  d["units"] = units;
  d["comments"] = csv.comments();
  return d;
}

// The integer columns (packings, seeds) as integer arrays.
template <class Integer>
py::array_t<std::int64_t> to_integers(const std::vector<Integer>& values) {
  std::vector<std::int64_t> v(values.begin(), values.end());
  return py::array_t<std::int64_t>(py::ssize_t(v.size()), v.data());
}

// The state points of a sweep's table: the columns of
// docs/flow-curve-format.md, each quantity the table has with its standard
// error ("sigma", "sigma_se").
py::dict flow_curve_table(const Path& file) {
  const bridge::FlowCurveTable table = bridge::read_flow_curve_table(CsvTable::read(file));
  std::vector<double> phi, rate, modulus, modulus_se;
  std::vector<std::size_t> packings;
  for (const bridge::StatePoint& p : table.points) {
    phi.push_back(p.phi);
    rate.push_back(p.gamma_tilde);
    packings.push_back(p.packings);
    modulus.push_back(p.modulus.value);
    modulus_se.push_back(p.modulus.error);
  }
  py::dict d;
  d["source"] = table.source;
  d["comments"] = table.comments;
  d["phi"] = to_array(phi);
  d["gamma_tilde"] = to_array(rate);
  d["packings"] = to_integers(packings);
  d["G0"] = to_array(modulus);
  d["G0_se"] = to_array(modulus_se);
  for (const bridge::Quantity q : bridge::kAllQuantities) {
    if (!table.present[bridge::index(q)]) continue;
    std::vector<double> value, error;
    for (const bridge::StatePoint& p : table.points) {
      value.push_back(p.values[bridge::index(q)]->value);
      error.push_back(p.values[bridge::index(q)]->error);
    }
    d[bridge::column_name(q)] = to_array(value);
    d[py::str(fmt::format("{}_se", bridge::column_name(q)))] = to_array(error);
  }
  return d;
}

// The per-packing companion: one row per run, NaN where a run lacks a quantity.
py::dict packing_runs(const Path& file) {
  const std::vector<bridge::PackingRun> runs = bridge::read_packing_runs(CsvTable::read(file));
  std::vector<double> phi, rate, modulus;
  std::vector<std::uint64_t> seed;
  for (const bridge::PackingRun& r : runs) {
    phi.push_back(r.phi);
    rate.push_back(r.gamma_tilde);
    seed.push_back(r.seed);
    modulus.push_back(r.modulus);
  }
  py::dict d;
  d["phi"] = to_array(phi);
  d["gamma_tilde"] = to_array(rate);
  d["seed"] = to_integers(seed);
  d["G0"] = to_array(modulus);
  for (const bridge::Quantity q : bridge::kAllQuantities) {
    std::vector<double> value;
    for (const bridge::PackingRun& r : runs)
      value.push_back(r.values[bridge::index(q)].value_or(std::nan("")));
    if (std::any_of(value.begin(), value.end(), [](double v) { return !std::isnan(v); }))
      d[bridge::column_name(q)] = to_array(value);
  }
  return d;
}

py::dict estimate(const micro::MeanEstimate& e) {
  py::dict d;
  d["mean"] = e.mean;
  d["standard_error"] = e.standard_error;
  d["samples"] = e.samples;
  d["reliable"] = e.reliable;
  return d;
}

py::object value_and_error(const std::optional<micro::Estimate>& e) {
  if (!e) return py::none();
  return py::make_tuple(e->value, e->error);
}

// What `micro summary` reads of one run: its state point and steady state.
py::dict run_summary(const Path& file) {
  const micro::StoredRunSummary s = micro::read_run_summary(file);
  py::dict observables;
  for (const micro::ObservableEstimate& o : s.observables)
    observables[py::str(o.name)] = estimate(o.estimate);
  py::dict d;
  d["file"] = s.file;
  d["gamma_tilde"] = s.gamma_tilde;
  d["phi"] = s.volume_fraction;
  d["G0"] = s.shear_modulus;
  d["quasi_static"] = s.quasi_static;
  d["particles"] = s.particles;
  d["converged"] = s.converged;
  d["averaged_strain"] = s.averaged_strain;
  d["coordination"] = s.coordination;
  d["layering"] = s.layering;
  d["observables"] = observables;
  d["r_m"] = value_and_error(s.r_m);
  d["f_m"] = value_and_error(s.f_m);
  d["packing_fingerprint"] = s.packing_fingerprint;
  return d;
}

// The sampled stress history: strain, every scalar observable, Z, S_y.
py::dict time_series(const Path& file) {
  const micro::TimeSeries t = micro::read_time_series(file);
  py::dict d;
  d["strain"] = to_array(t.strain);
  for (const std::string& name : micro::shear_observable_names())
    d[py::str(name)] = to_array(t.component(name));
  d["coordination"] = to_array(t.coordination);
  d["layering"] = to_array(t.layering);
  d["step"] = to_array(t.step);
  return d;
}

py::dict averaged(const micro::AveragedObservable& o) {
  py::dict d;
  d["mean"] = o.mean;
  d["standard_error"] = o.standard_error();
  d["within"] = o.within;
  d["between"] = o.between;
  return d;
}

// `micro summary RUN...`: the average over packings of one state point.
py::dict packing_average(const std::vector<Path>& files) {
  std::vector<micro::StoredRunSummary> runs;
  for (const Path& f : files) runs.push_back(micro::read_run_summary(f));
  const micro::PackingAverage a = micro::average_over_packings(runs);
  py::dict observables;
  for (const micro::AveragedObservable& o : a.observables) observables[py::str(o.name)] = averaged(o);
  py::dict d;
  d["runs"] = a.runs;
  d["converged_runs"] = a.converged_runs;
  d["particles"] = a.particles;
  d["gamma_tilde"] = a.gamma_tilde;
  d["phi"] = a.volume_fraction;
  d["G0"] = a.shear_modulus;
  d["G0_se"] = a.shear_modulus_error;
  d["averaged_strain"] = a.averaged_strain;
  d["coordination"] = a.coordination;
  d["observables"] = observables;
  d["r_m"] = a.r_m ? py::object(averaged(*a.r_m)) : py::none();
  d["f_m"] = a.f_m ? py::object(averaged(*a.f_m)) : py::none();
  return d;
}

}  // namespace

void bind_readers(py::module_& m) {
  py::class_<MeasuredCurve>(m, "MeasuredCurve",
                            "A measured flow curve in SI units: shear rate [1/s], stress [Pa], "
                            "N1 [Pa] (optional).")
      .def(py::init([](std::string label, std::vector<double> rate, std::vector<double> stress,
                       std::optional<std::vector<double>> n1) {
             return MeasuredCurve{std::move(label), std::move(rate), std::move(stress),
                                  std::move(n1)};
           }),
           py::arg("label"), py::arg("shear_rate"), py::arg("stress"), py::arg("N1") = py::none())
      .def_readonly("label", &MeasuredCurve::label)
      .def_property_readonly("shear_rate",
                             [](const MeasuredCurve& c) { return to_array(c.shear_rate); })
      .def_property_readonly("stress", [](const MeasuredCurve& c) { return to_array(c.stress); })
      .def_property_readonly("N1",
                             [](const MeasuredCurve& c) -> py::object {
                               return c.N1 ? py::object(to_array(*c.N1)) : py::none();
                             })
      .def("__len__", [](const MeasuredCurve& c) { return c.shear_rate.size(); })
      .def("__repr__", [](const MeasuredCurve& c) {
        return fmt::format("MeasuredCurve('{}', {} points{})", c.label, c.shear_rate.size(),
                           c.N1 ? ", with N1" : "");
      });

  m.def(
      "read_measured_curves",
      [](const Path& file, const std::string& rate_unit, const std::string& stress_unit,
         const std::string& format) {
        const MeasuredReading reading{.format = format, .rate = rate_unit, .stress = stress_unit};
        return read_measured_curves(read_measured_file(file, format), reading);
      },
      py::arg("file"), py::arg("rate_unit") = "", py::arg("stress_unit") = "",
      py::arg("format") = "auto",
      "The flow curves of a measured rheometer file as the instrument exported it (TRIOS, "
      "RheoCompass, delimited, plain: docs/measured-files.md), as MeasuredCurve objects in SI "
      "units. rate_unit and stress_unit are the units of columns whose header has none; format "
      "overrides the detected export format.");
  m.def("read_rheometer_curves", &rheometer_curves, py::arg("file"), py::arg("rate_unit") = "",
        py::arg("stress_unit") = "", py::arg("format") = "auto",
        "Every curve of a measured rheometer file as a dict: 'label', 'kind' (flow_curve, "
        "amplitude_sweep, other) and an array per recognised column (shear_rate, stress, N1, "
        "torque, angular_velocity, normal_force, storage_modulus, loss_modulus, "
        "strain_amplitude, angular_frequency), in SI units.");
  m.def("read_amplitude_sweeps", &amplitude_sweeps, py::arg("file"), py::arg("format") = "auto",
        "The amplitude sweeps of a measured file: dicts of strain_amplitude [1], "
        "storage_modulus and loss_modulus [Pa], angular_frequency [rad/s] or None.");
  m.def("read_table", &csv_columns, py::arg("file"),
        "A CSV table with units in its header (every table softglass writes): dict with "
        "'columns' (name -> array, or list of text for a column that is not numbers), "
        "'units' (name -> unit) and 'comments' (the # lines).");
  m.def("read_flow_curve_table", &flow_curve_table, py::arg("file"),
        "A sweep's flow_curve.csv (docs/flow-curve-format.md), checked as bridge fit checks "
        "it: arrays phi, gamma_tilde, packings, G0, G0_se and per quantity the table has "
        "(sigma, N1, N2, f_m) its value and '_se' standard error, reduced units.");
  m.def("read_packing_runs", &packing_runs, py::arg("file"),
        "A sweep's per-packing table (flow_curve_packings.csv): arrays phi, gamma_tilde, seed, "
        "G0 and sigma, N1, N2, f_m (NaN where a run has none).");
  m.def("read_run", &run_summary, py::arg("file"),
        "The steady state of a micro run file (micro run, micro sweep's runs/*.h5): state "
        "point, G0, convergence and 'observables' (name -> mean, standard_error, samples, "
        "reliable), reduced units.");
  m.def("read_time_series", &time_series, py::arg("file"),
        "The sampled history of a micro run file: strain and every scalar observable "
        "(sigma, sigma_elastic, ..., N1, N2, pressure ...) as arrays, reduced units.");
  m.def("summarize_runs", &packing_average, py::arg("files"),
        "`micro summary`: the average over packings of runs of one state point, each "
        "observable with mean, standard_error (the larger of within and between).");
}

}  // namespace softglass::python

PYBIND11_MODULE(_softglass, m) {
  namespace py = pybind11;
  using namespace softglass;
  m.doc() = "softglass: soft glasses from particles to rheometer torques (compiled part)";
  // Bad input is a ValueError, a failed computation a RuntimeError, a result
  // that exists a FileExistsError: what Python code catches them as.
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<NumericalError>(m, "NumericalError", PyExc_RuntimeError);
  py::register_exception<OutputExistsError>(m, "OutputExistsError", PyExc_FileExistsError);
  python::bind_readers(m);
  python::bind_bridge(m);
  python::bind_macro(m);
}
