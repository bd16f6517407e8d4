// Valid HDF5 files for the micro fuzz tests, made by the project's own
// writers from a real (tiny) run: a packing of 150 particles sheared over a
// strain of 0.3, with snapshots, a structure analysis, and the first
// checkpoint the run saved. Small files keep a mutation cheap to read.
#pragma once

#include <filesystem>

#include "micro/results/run_structure.h"
#include "micro/contact/contact_law.h"
#include "micro/io/checkpoint_file.h"
#include "micro/io/run_file.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"
#include "tests/micro/micro_test_support.h"

namespace softglass::micro::testing {

struct SeedFiles {
  std::filesystem::path run, checkpoint;
};

/// Writes `run.h5` and `checkpoint.h5` into `directory`.
inline SeedFiles write_seed_files(const std::filesystem::path& directory) {
  PackingSpec spec;
  spec.particles = 150;
  spec.volume_fraction = 0.75;
  spec.skin = 0.3;
  spec.seed = 3;
  const std::shared_ptr<const ContactLaw> law = make_contact_law({});
  const Packing packing = make_packing(spec, law);

  RunRecord record = packing_record(packing, law, spec.skin);

  ShearModel model;
  model.gamma_tilde = 1e-4;
  OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model);
  ShearProtocol protocol;
  protocol.min_strain = protocol.max_strain = 0.3;
  protocol.sample_interval = 0.005;  // the stationary part needs 20 samples
  protocol.check_interval = 0.1;
  protocol.min_stationary_strain = 0.1;
  protocol.snapshot_interval = 0.05;
  SeedFiles files{directory / "run.h5", directory / "checkpoint.h5"};
  bool saved = false;
  const auto save = [&](const ShearCheckpoint& c) {
    if (!saved) write_checkpoint(files.checkpoint, c);
    saved = true;
  };
  const auto integrator = make_integrator({.name = "euler"});
  ShearResult result =
      run_shear(flow, *integrator, protocol, {},
                {20, save, [] { return make_integrator({.name = "euler"}); }, nullptr});
  const Particles final_particles = flow.system().wrapped_in_label_order();
  const std::vector<Snapshot> stationary = stationary_snapshots(result);
  StructureSettings settings;
  settings.batches = 2;
  record.structure = analyse_snapshots(stationary, final_particles.radius,
                                       flow.system().box().side(), *law, settings);
  record.shear =
      ShearRecord{model.gamma_tilde, std::move(result), final_particles, flow.system().box()};
  write_run_file(files.run, record);
  return files;
}

}  // namespace softglass::micro::testing
