// H5File and H5Group: every kind of dataset and attribute survives a round
// trip, and a reader meeting a missing or mistyped object gets an error that
// names it.
#include "common/h5_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/atomic_output.h"
#include "common/errors.h"

namespace softglass {
namespace {

namespace fs = std::filesystem;

// Each test works in a directory of its own, removed afterwards.
class H5FileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("softglass-" + std::string(test->test_suite_name()) + "-" +
                                        test->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path file() const { return dir_ / "run.h5"; }

  fs::path dir_;
};

// Expects `call` to throw `Error` with every one of `parts` in its message.
template <class Error, class Call>
void expect_error(Call call, std::initializer_list<std::string> parts) {
  try {
    call();
    ADD_FAILURE() << "no exception thrown";
  } catch (const Error& error) {
    const std::string message = error.what();
    for (const auto& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
}

// A created file is written by close() (h5_file.h): `fill` writes into its
// root, then the file is closed.
template <class Fill>
void create_and_close(const fs::path& path, Fill fill) {
  H5File created = H5File::create(path);
  fill(created.root());
  created.close();
}

TEST_F(H5FileTest, RoundTripsOneDimensionalDoubles) {
  const std::vector<double> values = {1.5, -2.25, 1e-300, 1e300, 0.0};
  create_and_close(file(), [&](H5Group root) { root.write("values", values); });

  const auto array = H5File::open(file()).root().read_array("values");
  EXPECT_EQ(array.data, values);
  EXPECT_EQ(array.dims, std::vector<std::size_t>{5});
}

TEST_F(H5FileTest, RoundTripsRowsOfThree) {
  std::vector<double> positions;
  for (int i = 0; i < 7 * 3; ++i) positions.push_back(0.1 * i);
  create_and_close(file(), [&](H5Group root) { root.write("positions", positions, {7, 3}); });

  const auto root = H5File::open(file()).root();
  const auto array = root.read_array("positions");
  EXPECT_EQ(array.data, positions);
  EXPECT_EQ(array.dims, (std::vector<std::size_t>{7, 3}));
  EXPECT_EQ(root.dims("positions"), (std::vector<std::size_t>{7, 3}));
}

TEST_F(H5FileTest, CompressesLargeArraysAndReadsThemBack) {
  std::vector<double> series(100000);
  for (std::size_t i = 0; i < series.size(); ++i) series[i] = 0.25 * static_cast<double>(i);
  std::vector<double> rows(40000 * 3);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = static_cast<double>(i % 1000);
  create_and_close(file(), [&](H5Group root) {
    root.write("series", series);
    root.write("rows", rows, {40000, 3});
  });
  const auto raw_bytes = (series.size() + rows.size()) * sizeof(double);
  EXPECT_LT(fs::file_size(file()), raw_bytes / 4);

  const auto root = H5File::open(file()).root();
  EXPECT_EQ(root.read_array("series").data, series);
  const auto read_rows = root.read_array("rows");
  EXPECT_EQ(read_rows.data, rows);
  EXPECT_EQ(read_rows.dims, (std::vector<std::size_t>{40000, 3}));
}

TEST_F(H5FileTest, RoundTripsAnEmptyArray) {
  create_and_close(file(), [&](H5Group root) { root.write("none", std::span<const double>{}); });

  const auto array = H5File::open(file()).root().read_array("none");
  EXPECT_TRUE(array.data.empty());
  EXPECT_EQ(array.dims, std::vector<std::size_t>{0});
}

TEST_F(H5FileTest, RoundTripsIntegers) {
  const std::vector<std::int64_t> ids = {std::numeric_limits<std::int64_t>::min(), -1, 0,
                                         (std::int64_t{1} << 53) + 1,
                                         std::numeric_limits<std::int64_t>::max()};
  const std::vector<std::uint32_t> counts = {0, 7, std::numeric_limits<std::uint32_t>::max()};
  const std::vector<std::int64_t> pairs = {0, 1, 1, 2, 2, 0};
  create_and_close(file(), [&](H5Group root) {
    root.write("ids", ids);
    root.write("counts", counts);
    root.write("pairs", pairs, {3, 2});
  });
  const auto root = H5File::open(file()).root();
  EXPECT_EQ(root.read_int_array("ids"), ids);
  EXPECT_EQ(root.read_int_array("counts"), (std::vector<std::int64_t>{0, 7, 4294967295}));
  EXPECT_EQ(root.read_int_array("pairs"), pairs);
  EXPECT_EQ(root.dims("pairs"), (std::vector<std::size_t>{3, 2}));
  // Integers also read as doubles.
  EXPECT_EQ(root.read_array("counts").data, (std::vector<double>{0.0, 7.0, 4294967295.0}));
}

TEST_F(H5FileTest, RoundTripsStringsAndScalars) {
  const std::string text = "τ = σ/E*\nsecond line\n\tindented ✓";
  create_and_close(file(), [&](H5Group root) {
    root.write_string("notes", text);
    root.write_string("empty", "");
    root.write_scalar("phi", 0.64);
  });
  const auto root = H5File::open(file()).root();
  EXPECT_EQ(root.read_string("notes"), text);
  EXPECT_EQ(root.read_string("empty"), "");
  EXPECT_EQ(root.read_scalar("phi"), 0.64);
  EXPECT_TRUE(root.dims("phi").empty());
  EXPECT_EQ(root.read_array("phi").data, std::vector<double>{0.64});
}

TEST_F(H5FileTest, RoundTripsGroupAttributes) {
  create_and_close(file(), [&](H5Group root) {
    root.set_attribute("phi", 0.64);
    root.set_attribute("steps", 42);  // a plain int picks the integer overload
    root.set_attribute("seed", std::int64_t{1} << 40);
    root.set_attribute("model", std::string("Hertz, σ/E*"));
    root.set_attribute("status", "running");
    root.set_attribute("status", "done");  // replaces
  });
  const auto root = H5File::open(file()).root();
  EXPECT_EQ(root.attribute_double("phi"), 0.64);
  EXPECT_EQ(root.attribute_int("steps"), 42);
  EXPECT_EQ(root.attribute_double("steps"), 42.0);
  EXPECT_EQ(root.attribute_int("seed"), std::int64_t{1} << 40);
  EXPECT_EQ(root.attribute_string("model"), "Hertz, σ/E*");
  EXPECT_EQ(root.attribute_string("status"), "done");
  EXPECT_TRUE(root.has_attribute("phi"));
  EXPECT_FALSE(root.has_attribute("absent"));
  EXPECT_FALSE(root.has_child("phi"));  // attributes are not children
}

TEST_F(H5FileTest, NestsGroupsAndListsChildrenInOrder) {
  create_and_close(file(), [&](H5Group root) {
    root.create_group("zeta");
    auto inner = root.create_group("alpha").create_group("inner");
    inner.write_scalar("deep", 3.0);
    inner.set_attribute("level", 2);
    root.write_scalar("mid", 1.0);
  });
  const auto root = H5File::open(file()).root();
  EXPECT_EQ(root.children(), (std::vector<std::string>{"alpha", "mid", "zeta"}));
  EXPECT_TRUE(root.group("zeta").children().empty());
  EXPECT_TRUE(root.has_child("alpha/inner/deep"));
  EXPECT_FALSE(root.has_child("alpha/missing/deep"));
  EXPECT_FALSE(root.has_child(""));

  const auto inner = root.group("alpha").group("inner");
  EXPECT_EQ(inner.path(), "/alpha/inner");
  EXPECT_EQ(inner.read_scalar("deep"), 3.0);
  EXPECT_EQ(inner.attribute_int("level"), 2);
  EXPECT_EQ(root.group("alpha/inner").read_scalar("deep"), 3.0);
}

TEST_F(H5FileTest, AttachesUnitsAndDescriptionsToDatasets) {
  const std::vector<double> stress = {1.0, 2.0};
  const std::vector<double> strain = {0.01, 0.02};
  create_and_close(file(), [&](H5Group root) {
    auto series = root.create_group("timeseries");
    series.write("stress", stress, {}, {.units = "Pa", .description = "shear stress σ"});
    series.write("strain", strain);
    series.set_dataset_attribute("strain", "units", "1");
    series.write_scalar("rate", 0.5, {.units = "1/s", .description = ""});
  });
  const auto series = H5File::open(file()).root().group("timeseries");
  EXPECT_EQ(series.dataset_attribute("stress", "units"), "Pa");
  EXPECT_EQ(series.dataset_attribute("stress", "description"), "shear stress σ");
  EXPECT_EQ(series.dataset_attribute("strain", "units"), "1");
  EXPECT_EQ(series.dataset_attribute("rate", "units"), "1/s");
  expect_error<InputError>([&] { series.dataset_attribute("rate", "description"); },
                           {"description", "/timeseries/rate", "run.h5"});
}

TEST_F(H5FileTest, FilesAndGroupsMoveAndOutliveTheirFile) {
  auto created = H5File::create(file());
  H5File file_handle = std::move(created);
  auto root = file_handle.root();
  root.write_scalar("early", 1.0);
  file_handle.close();  // writes run.h5
  file_handle.close();  // closing twice is harmless
  root.write_scalar("late", 2.0);  // the group stays usable; the file holds what close() wrote
  root = H5File::open(file()).root();
  EXPECT_EQ(root.read_scalar("early"), 1.0);
  EXPECT_FALSE(root.has_child("late"));
}

// A file that is not closed is not written: an exception between create and
// close leaves no file that looks complete.
TEST_F(H5FileTest, AFileNotClosedIsNotWritten) {
  H5File::create(file()).root().write_scalar("answer", 42.0);
  expect_error<InputError>([&] { H5File::open(file()); }, {"run.h5", "not an HDF5 file"});
}

TEST_F(H5FileTest, WritesThroughAtomicOutput) {
  AtomicOutput output(file(), false);
  auto h5 = H5File::create(output.temporary_path());
  h5.root().write_scalar("answer", 42.0);
  h5.close();
  output.commit();
  EXPECT_EQ(H5File::open(file()).root().read_scalar("answer"), 42.0);
}

// ---- Errors

TEST_F(H5FileTest, OpeningAMissingFileNamesIt) {
  expect_error<InputError>([&] { H5File::open(dir_ / "absent.h5"); }, {"absent.h5", "not exist"});
}

TEST_F(H5FileTest, OpeningANonHdf5FileNamesIt) {
  std::ofstream(dir_ / "notes.txt") << "not HDF5 at all\n";
  expect_error<InputError>([&] { H5File::open(dir_ / "notes.txt"); },
                           {"notes.txt", "not an HDF5 file"});
  expect_error<InputError>([&] { H5File::open(dir_); }, {dir_.string()});
}

// A global heap whose object sizes do not tile it (a free-space object of
// size 0 here) makes HDF5 1.10 loop forever: it is refused on opening.
TEST_F(H5FileTest, AGlobalHeapThatDoesNotHoldTogetherIsRefused) {
  create_and_close(file(), [&](H5Group root) { root.set_attribute("kind", std::string("text")); });
  std::string bytes;
  {
    std::ifstream in(file(), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t heap = bytes.find(std::string("GCOL\x01\x00\x00\x00", 8));
  ASSERT_NE(heap, std::string::npos) << "the string lives in a global heap";
  EXPECT_EQ(H5File::open(file()).root().attribute_string("kind"), "text");
  // The first object (header at byte 16 of the collection): index 0, size 0.
  std::fill_n(bytes.begin() + static_cast<std::ptrdiff_t>(heap + 16), 2, '\0');
  std::fill_n(bytes.begin() + static_cast<std::ptrdiff_t>(heap + 24), 8, '\0');
  std::ofstream(file(), std::ios::binary) << bytes;
  expect_error<InputError>([&] { H5File::open(file()); }, {"run.h5", "global heap"});
}

// A root group whose object header is damaged is the file's fault: refused
// as bad input naming the file (it was a std::runtime_error from root(),
// found by the run-file fuzz campaign at iteration 1177).
TEST_F(H5FileTest, ADamagedRootGroupIsRefusedAsBadInput) {
  create_and_close(file(), [&](H5Group root) { root.set_attribute("kind", std::string("text")); });
  std::string bytes;
  {
    std::ifstream in(file(), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // Superblock version 0 (HDF5 file format specification): the root group's
  // symbol table entry at byte 56 holds its object header's address at +8.
  // That header (version 1) has a 16-byte prefix, then messages, each headed
  // by its type (2 bytes). The first is the symbol table message that makes
  // it a group (type 0x11) or the continuation to the block holding it
  // (0x10); made a null message (type 0), the root is no group any more.
  ASSERT_EQ(bytes[8], 0) << "superblock version 0";
  std::size_t header = 0;
  for (int k = 7; k >= 0; --k) header = (header << 8) | static_cast<unsigned char>(bytes[64 + k]);
  ASSERT_LT(header + 18, bytes.size());
  ASSERT_EQ(bytes[header], 1) << "an object header of version 1";
  const std::size_t message = header + 16;
  ASSERT_TRUE(bytes[message] == 0x10 || bytes[message] == 0x11) << int(bytes[message]);
  ASSERT_EQ(bytes[message + 1], 0);
  bytes[message] = 0;
  std::ofstream(file(), std::ios::binary) << bytes;
  expect_error<InputError>([&] { H5File::open(file()).root(); }, {"run.h5"});
}

TEST_F(H5FileTest, CreatingInAMissingDirectoryFails) {
  expect_error<std::runtime_error>([&] { H5File::create(dir_ / "missing" / "run.h5"); },
                                   {"missing/run.h5"});
}

TEST_F(H5FileTest, MissingObjectsAreNamedWithTheirPathAndFile) {
  create_and_close(file(), [&](H5Group root) { root.create_group("timeseries").write_scalar("rate", 1.0); });
  const auto root = H5File::open(file()).root();
  const auto series = root.group("timeseries");

  const std::initializer_list<std::string> strain = {"dataset '/timeseries/strain' not found",
                                                     "run.h5"};
  expect_error<InputError>([&] { series.read_array("strain"); }, strain);
  expect_error<InputError>([&] { series.read_int_array("strain"); }, strain);
  expect_error<InputError>([&] { series.read_string("strain"); }, strain);
  expect_error<InputError>([&] { series.read_scalar("strain"); }, strain);
  expect_error<InputError>([&] { series.dims("strain"); }, strain);
  expect_error<InputError>([&] { series.dataset_attribute("strain", "units"); }, strain);
  expect_error<InputError>([&] { root.read_array("timeseries/strain"); }, strain);
  expect_error<InputError>([&] { root.group("averages"); }, {"group '/averages' not found"});
  expect_error<InputError>([&] { series.attribute_double("phi"); },
                           {"attribute 'phi' of '/timeseries' not found", "run.h5"});
  expect_error<InputError>([&] { series.attribute_int("steps"); }, {"'steps'"});
  expect_error<InputError>([&] { series.attribute_string("model"); }, {"'model'"});
}

TEST_F(H5FileTest, ObjectsOfTheWrongKindAreRejected) {
  create_and_close(file(), [&](H5Group root) {
    const std::vector<double> values = {1.0, 2.0};
    root.write("values", values);
    root.write_string("text", "abc");
    root.set_attribute("phi", 0.5);
    root.create_group("group");
  });
  const auto root = H5File::open(file()).root();
  expect_error<InputError>([&] { root.read_string("values"); }, {"/values", "single string"});
  expect_error<InputError>([&] { root.read_int_array("values"); }, {"/values", "integers"});
  expect_error<InputError>([&] { root.read_scalar("values"); }, {"/values", "2 values"});
  expect_error<InputError>([&] { root.read_array("text"); }, {"/text", "numbers"});
  expect_error<InputError>([&] { root.read_array("group"); }, {"/group", "not a dataset"});
  expect_error<InputError>([&] { root.group("values"); }, {"/values", "not a group"});
  expect_error<InputError>([&] { root.attribute_int("phi"); }, {"'phi'", "integers"});
  expect_error<InputError>([&] { root.attribute_string("phi"); }, {"'phi'", "string"});
}

TEST_F(H5FileTest, DimsThatDoNotMatchTheDataAreRejected) {
  auto root = H5File::create(file()).root();
  const std::vector<double> values(5);
  const auto two_by_three = [&] { root.write("values", values, {2, 3}); };
  expect_error<std::invalid_argument>(two_by_three, {"/values", "2x3", "6 values", "5"});
  EXPECT_FALSE(root.has_child("values"));
}

TEST_F(H5FileTest, WriteFailuresThrow) {
  const std::vector<double> values = {1.0};
  create_and_close(file(), [&](H5Group root) {
    root.write("values", values);
    expect_error<std::runtime_error>([&] { root.write("values", values); },
                                     {"cannot create dataset '/values'", "exists"});
    expect_error<std::runtime_error>([&] { root.create_group("values"); }, {"'/values'"});
  });
  auto read_only = H5File::open(file()).root();
  expect_error<std::runtime_error>([&] { read_only.write("more", values); }, {"'/more'"});
}

}  // namespace
}  // namespace softglass
