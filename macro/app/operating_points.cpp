#include "macro/app/operating_points.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include "common/errors.h"
#include "common/progress.h"
#include "macro/app/mpi_gather.h"

namespace softglass::macro::app {

std::string describe_model(const Material& material, const fe::SolverSettings& settings) {
  return fmt::format("material: tau_y = {} Pa, K = {} Pa s^n, n = {}; solver: preset {}, {}",
                     material.shear.yield_stress, material.shear.consistency,
                     material.shear.flow_index, settings.preset,
                     settings.method == fe::Method::regularised
                         ? settings.regularisation + " regularisation"
                         : std::string("augmented Lagrangian"));
}

std::vector<std::vector<double>> solve_operating_points(Scene& scene,
                                                        const std::vector<double>& points,
                                                        const SweepDisplay& display) {
  const MPI_Comm comm = MPI_COMM_WORLD;
  const unsigned rank = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  const Column drive = scene.drive();
  const std::size_t first = points.size() * rank / ranks;
  const std::size_t last = points.size() * (rank + 1) / ranks;
  Progress progress(display.label, double(last - first), display.quiet || rank != 0);
  std::vector<std::vector<double>> mine;
  std::string failure;  // a rank that fails still joins the gather below
  for (std::size_t k = first; k < last && failure.empty(); ++k) {
    try {
      mine.push_back(scene.solve(points[k]));
      if (display.vtu == "all" || (display.vtu == "last" && k + 1 == points.size())) {
        AtomicOutput out(display.directory / fmt::format("solution_{:03d}.vtu", k), true);
        scene.write_vtu(out.temporary_path());
        out.commit();
      }
    } catch (const std::exception& error) {
      failure = fmt::format("{} = {}: {}", drive.name, points[k], error.what());
    }
    progress.update(double(k + 1 - first), fmt::format("{} = {:.4g}", drive.name, points[k]));
  }
  progress.finish();
  auto rows = gather_rows(comm, mine, scene.columns().size());
  for (const std::string& f : gather_text(comm, failure))
    if (!f.empty()) throw NumericalError(f);
  return rows;
}

ClaimedOutputs claim_outputs(const std::filesystem::path& directory,
                             const std::vector<std::string>& names, bool force) {
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  ClaimedOutputs claimed;
  std::string refusal;
  if (root) {
    std::filesystem::create_directories(directory);
    try {
      for (const std::string& name : names)
        claimed.files.push_back(std::make_unique<AtomicOutput>(directory / name, force));
    } catch (const OutputExistsError& error) {
      refusal = error.what();
      claimed.files.clear();
    }
  }
  if (broadcast_flag(comm, !refusal.empty())) {
    if (root) throw OutputExistsError(refusal);
    claimed.refused = true;
  }
  return claimed;
}

}  // namespace softglass::macro::app
