// What a rerun may reuse (micro/input/finished_work.h): a checkpoint keeps its
// run's parameter text and resumes only the same computation, compared entry
// by entry as a finished run is (the entries that say where files are may
// differ), the first entry that differs named.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.h"
#include "micro/input/finished_work.h"
#include "micro/io/checkpoint_file.h"
#include "tests/common/test_files.h"

namespace softglass::micro {
namespace {

class CheckpointComputation : public ::testing::Test {
 protected:
  void SetUp() override {
    checkpoint_.particles = Particles({{1.0, 1.0, 1.0}, {3.0, 1.0, 1.0}}, {1.0, 1.0});
    checkpoint_.box = LeesEdwardsBox(4.0);
  }
  const std::string made_ =
      "subsection integrator\n  set scheme = bdf2\n  set tolerance = 0\nend\n"
      "subsection output\n  set file = a.h5\nend\n";
  ShearCheckpoint checkpoint_;
  testing::TemporaryDirectory folder_;
  const std::filesystem::path file_ = folder_ / "run.checkpoint.h5";
};

TEST_F(CheckpointComputation, PassesTheComputationThatWroteIt) {
  write_checkpoint(file_, checkpoint_, made_);
  EXPECT_EQ(read_checkpoint(file_).particles.size(), 2u) << "the text does not disturb the rest";
  EXPECT_NO_THROW(require_checkpoint_of_same_computation(file_, made_));
  std::string moved = made_;
  moved.replace(moved.find("a.h5"), 4, "b.h5");
  EXPECT_NO_THROW(require_checkpoint_of_same_computation(file_, moved)) << "files may move";
}

TEST_F(CheckpointComputation, RefusesAnotherNamingTheEntryThatDiffers) {
  write_checkpoint(file_, checkpoint_, made_);
  std::string other = made_;
  other.replace(other.find("tolerance = 0"), 13, "tolerance = 1e-3");
  try {
    require_checkpoint_of_same_computation(file_, other);
    ADD_FAILURE() << "a checkpoint made at another tolerance passed";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* named :
         {"run.checkpoint.h5", "'integrator/tolerance = 0'", "'integrator/tolerance = 1e-3'"})
      EXPECT_NE(message.find(named), std::string::npos) << named << " in " << message;
  }
}

// Checkpoints written before they kept their parameters say nothing of them.
TEST_F(CheckpointComputation, PassesAnOlderCheckpointWithoutParameters) {
  write_checkpoint(file_, checkpoint_);
  EXPECT_NO_THROW(require_checkpoint_of_same_computation(file_, made_));
}

}  // namespace
}  // namespace softglass::micro
