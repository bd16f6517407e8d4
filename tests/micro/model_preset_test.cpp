// Model presets (micro/input/model_preset.h): one entry chooses a whole
// reading of the model, and whatever the file sets itself wins, wherever it
// stands in the file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/errors.h"
#include "micro/input/parameter_file.h"
#include "tests/common/test_files.h"

namespace softglass::micro {
namespace {

class ModelPreset : public ::testing::Test {
 protected:
  MicroParameters read(const std::string& text) {
    testing::write_text(folder_ / "model.prm", text);
    return read_parameter_file(folder_ / "model.prm");
  }
  testing::TemporaryDirectory folder_;
};

TEST_F(ModelPreset, LiteralIsThePapersReading) {
  const MicroParameters p = read("subsection model\n  set preset = literal\nend\n");
  EXPECT_EQ(p.contact_law.name, "seth2011");
  EXPECT_EQ(p.shear_model.drag.stokes.reference, StokesReference::affine);
  EXPECT_EQ(p.shear_model.mobility_factor, 0.01);
  EXPECT_EQ(p.shear_model.drag.rest_thickness, 0.0) << "the paper's film law";
}

TEST_F(ModelPreset, SoftglassSetsTheNominalBranchesAndTheNeighbourFriction) {
  const MicroParameters p = read("subsection model\n  set preset = softglass\nend\n");
  EXPECT_EQ(p.contact_law.name, "piecewise");
  EXPECT_EQ(p.shear_model.drag.rest_thickness, 0.002);
  EXPECT_EQ(p.contact_law.coefficients.numbers("breakpoints"), (std::vector<double>{0.4, 0.8}));
  EXPECT_EQ(p.contact_law.coefficients.numbers("exponents"), (std::vector<double>{1.5, 2, 3}));
  EXPECT_EQ(p.shear_model.drag.stokes.reference, StokesReference::neighbours);
  // The stored text is what was used: read back, it gives the same model.
  const MicroParameters again = read(p.text);
  EXPECT_EQ(again.contact_law.name, "piecewise");
  EXPECT_EQ(again.contact_law.coefficients.numbers("breakpoints"), (std::vector<double>{0.4, 0.8}));
  EXPECT_EQ(again.shear_model.drag.stokes.reference, StokesReference::neighbours);
}

TEST_F(ModelPreset, TheFilesOwnEntriesWinBeforeAndAfterThePreset) {
  const MicroParameters before = read(
      "subsection drag\n  set stokes reference = affine\nend\n"
      "subsection model\n  set preset = softglass\nend\n");
  EXPECT_EQ(before.shear_model.drag.stokes.reference, StokesReference::affine);
  EXPECT_EQ(before.contact_law.name, "piecewise");
  const MicroParameters after = read(
      "subsection model\n  set preset = softglass\nend\n"
      "subsection contact law\n  set piecewise breakpoints = 0.2, 0.4\nend\n");
  EXPECT_EQ(after.contact_law.coefficients.numbers("breakpoints"), (std::vector<double>{0.2, 0.4}));
  EXPECT_EQ(after.shear_model.drag.stokes.reference, StokesReference::neighbours);
}

TEST_F(ModelPreset, AnUnknownPresetIsRefusedNamingTheChoices) {
  try {
    read("subsection model\n  set preset = paper\nend\n");
    FAIL() << "an unknown preset was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("literal"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("softglass"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace softglass::micro
