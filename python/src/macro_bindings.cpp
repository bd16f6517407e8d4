// Macro scenes solved in the Python process: the scene file read and checked
// as `macro run` reads it, solved at its operating points by the loop `macro
// run` and `macro compare` use (macro/app/operating_points.h), and the rows
// of its results.csv returned as arrays instead of written. The only
// translation unit of the module that sees deal.II.
//
// MPI. deal.II's distributed vectors and p4est meshes need MPI even on one
// rank, so the first solve starts it, as the lean singleton `macro` starts
// (common/mpi_launch.h), through deal.II's MPI_InitFinalize (which also
// starts p4est); it is finished when the interpreter exits. MPI cannot start
// again once finished, hence once per process. An interpreter started by
// mpirun spreads the points over the ranks like `macro run`: rank 0 gets the
// rows, the others an empty table.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/mpi_launch.h"
#include "macro/app/input_scales.h"
#include "macro/app/operating_points.h"
#include "macro/app/scene_file.h"
#include "macro/scenes/scene.h"
#include "python/src/bindings.h"

namespace softglass::python {

namespace {

using Path = std::filesystem::path;
namespace app = macro::app;

std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;

void start_mpi() {
  int started = 0;
  MPI_Initialized(&started);
  if (started) return;  // by an earlier solve, or by another module (mpi4py)
  prefer_lean_mpi_singleton();
  static char name[] = "python";
  static char* arguments[] = {name, nullptr};
  int argc = 1;
  char** argv = arguments;
  // One thread for deal.II's own tasks, as `macro` runs.
  mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
  py::module_::import("atexit").attr("register")(py::cpp_function([] { mpi.reset(); }));
}

// The operating points: the scene file's sweep, or the caller's (then the
// file's sweep entries are not the points, and are not checked as such).
std::vector<double> operating_points(dealii::ParameterHandler& prm,
                                     const std::optional<std::vector<double>>& given,
                                     std::vector<SetEntry>& entries) {
  if (!given) return app::read_sweep(prm);
  require(!given->empty(), "points: give at least one operating point");
  for (const double p : *given)
    require(p > 0 && std::isfinite(p),
            fmt::format("points: {} is not an operating point (> 0, finite)", p));
  std::erase_if(entries, [](const SetEntry& e) {
    return !e.subsections.empty() && e.subsections.front() == "sweep";
  });
  return *given;
}

py::dict table_columns(const UnitTable& table, py::dict& units) {
  py::dict columns;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    std::vector<double> values;
    for (const std::vector<double>& row : table.rows) values.push_back(row[c]);
    columns[py::str(table.columns[c].name)] = to_array(values);
    units[py::str(table.columns[c].name)] = table.columns[c].unit;
  }
  return columns;
}

py::dict run_scene(const Path& scene_file, const Path& material, const std::string& preset,
                   const std::optional<std::vector<double>>& given_points, bool quiet) {
  start_mpi();
  dealii::ParameterHandler prm;
  auto [model, settings, entries] = app::read_scene_input(prm, scene_file, preset, material);
  const std::vector<double> points = operating_points(prm, given_points, entries);
  const app::RankGroups groups(points.size(), 0);
  settings.mesh_communicator = groups.mesh_communicator();
  app::check_entry_scales(entries, scene_file);
  std::unique_ptr<macro::Scene> scene =
      macro::make_scene(prm, model, settings, scene_file.parent_path());
  app::check_derived_scales(*scene, model, settings, points, entries, scene_file);
  std::vector<macro::SceneResult> results;
  {
    py::gil_scoped_release unlocked;  // other Python threads run meanwhile
    results = app::solve_operating_points(
        *scene, points, groups,
        {.settings = settings,
         .label = fmt::format("softglass {}", scene_file.filename().string()),
         .quiet = quiet});
  }
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const UnitTable table =
      app::results_table(*scene, root ? points : std::vector<double>{}, results);
  py::dict units;
  py::dict d;
  d["columns"] = table_columns(table, units);
  d["units"] = units;
  d["drive"] = scene->drive().name;
  d["description"] = scene->description();
  d["model"] = app::describe_model(model, settings);
  d["source"] = model.source;
  d["extrapolation"] = app::extrapolation_note(*scene, model, points);
  if (const auto instrument = scene->instrument()) {
    py::dict i;
    i["strain_constant"] = instrument->strain_constant;
    i["stress_constant"] = instrument->stress_constant;
    i["convention"] = instrument->convention;
    d["instrument"] = i;
  } else {
    d["instrument"] = py::none();
  }
  return d;
}

}  // namespace

void bind_macro(py::module_& m) {
  // deal.II's own checks throw (and are reported as RuntimeError) instead of
  // aborting the interpreter or printing backtraces.
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  m.def("_run_scene", &run_scene, py::arg("scene_file"), py::arg("material") = Path(),
        py::arg("preset") = "", py::arg("points") = py::none(), py::arg("quiet") = true,
        "Solves a scene file (`macro run`) in this process; see softglass.run_scene.");
}

}  // namespace softglass::python
