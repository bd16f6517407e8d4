// Result files in HDF5: a small RAII wrapper for writing and reading them.
//
// Every softglass tool writes its results as one HDF5 file. Groups hold
// datasets (arrays of numbers, or text) and attributes (single numbers or short
// strings), and each dataset carries `units` and `description` attributes so
// that the file explains itself in h5dump or h5py:
//
//   auto file = H5File::create(output.temporary_path());
//   auto series = file.root().create_group("timeseries");
//   series.write("strain", strain, {}, {.units = "1", .description = "shear strain"});
//   series.set_attribute("steps", steps);
//   file.close();
//   output.commit();
//
// Reading something absent or of the wrong kind throws InputError naming the
// object's full path and the file; a failed write throws std::runtime_error
// carrying HDF5's own reason. HDF5 never prints to stderr.
//
// This header includes no HDF5 header on purpose: deal.II's include path
// carries an OpenMPI build of HDF5 whose headers must not meet the serial one
// linked here. Since HDF5 1.10 an identifier (hid_t) is a 64-bit integer, so it
// is held as std::int64_t and every HDF5 call stays in h5_file.cpp.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace softglass {

namespace detail {

/// Owns one HDF5 identifier (file, group, dataset, ...) and closes it on
/// destruction. Move-only: two owners would close it twice.
class H5Id {
 public:
  H5Id() = default;
  explicit H5Id(std::int64_t id) noexcept : id_(id) {}
  H5Id(H5Id&& other) noexcept : id_(std::exchange(other.id_, -1)) {}
  H5Id& operator=(H5Id&& other) noexcept;
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  ~H5Id();

  std::int64_t get() const { return id_; }

 private:
  std::int64_t id_ = -1;
};

}  // namespace detail

/// Physical units and a one-line meaning of a dataset, stored as its string
/// attributes `units` and `description`. Empty fields are not written. The
/// `{}` initialisers let a caller name one field alone, `{.units = "Pa"}`,
/// without a -Wmissing-field-initializers warning.
struct DatasetInfo {
  std::string units{};
  std::string description{};
};

/// A numeric dataset read back as doubles. `data` is in row-major order;
/// `dims` is its shape, empty for a scalar dataset.
struct H5Array {
  std::vector<double> data;
  std::vector<std::size_t> dims;
};

/// A group in an open file: a folder of datasets and further groups, with
/// attributes of its own. Names are relative to this group; a name with
/// slashes ("a/b") reaches into subgroups that already exist.
class H5Group {
 public:
  /// The group's absolute path in its file, e.g. "/timeseries".
  std::string path() const;

  // ---- Structure

  /// Creates the subgroup `name`; throws std::runtime_error if it exists.
  H5Group create_group(const std::string& name);
  /// Opens the existing subgroup `name`; InputError if absent or not a group.
  H5Group group(const std::string& name) const;
  /// Whether a group or dataset called `name` exists below this group.
  bool has_child(const std::string& name) const;
  /// Whether this group has the attribute `name`.
  bool has_attribute(const std::string& name) const;
  /// Removes the link `name` (a group with all it holds, or a dataset).
  void remove_child(const std::string& name);
  /// Names of the groups and datasets directly below, in alphabetical order.
  std::vector<std::string> children() const;

  // ---- Writing datasets
  //
  // A dataset is written once, whole; writing an existing name throws
  // std::runtime_error. `dims` gives the shape of row-major `data` (an N×3
  // array of positions is dims {N, 3}); empty means 1-D of data.size(). A
  // product of dims other than data.size() throws std::invalid_argument.
  // Arrays of more than 4096 values with one or two dimensions are stored
  // chunked and compressed (shuffle + deflate); smaller ones contiguously.

  void write(const std::string& name, std::span<const double> data,
             std::vector<std::size_t> dims = {}, const DatasetInfo& info = {});
  void write(const std::string& name, std::span<const std::int64_t> data,
             std::vector<std::size_t> dims = {}, const DatasetInfo& info = {});
  void write(const std::string& name, std::span<const std::uint32_t> data,
             std::vector<std::size_t> dims = {}, const DatasetInfo& info = {});
  /// Stores `text` as one variable-length UTF-8 string (h5py reads it as
  /// bytes, or as str through `.asstr()`). Text ends at an embedded '\0'.
  void write_string(const std::string& name, const std::string& text, const DatasetInfo& info = {});
  /// Stores a single number as a scalar dataset.
  void write_scalar(const std::string& name, double value, const DatasetInfo& info = {});
  /// Sets (or replaces) the string attribute `attribute` of the existing
  /// dataset `dataset`; InputError if the dataset is absent.
  void set_dataset_attribute(const std::string& dataset, const std::string& attribute,
                             const std::string& value);

  // ---- Reading datasets
  //
  // A missing dataset, or one holding the wrong kind of data, throws
  // InputError naming it, e.g. "dataset '/timeseries/strain' not found in 'run.h5'".

  /// Any integer or floating-point dataset, converted to double.
  H5Array read_array(const std::string& name) const;
  /// Any integer dataset as int64 in row-major order; `dims()` gives its shape.
  std::vector<std::int64_t> read_int_array(const std::string& name) const;
  /// A dataset holding exactly one string, fixed- or variable-length.
  std::string read_string(const std::string& name) const;
  /// A dataset holding exactly one number.
  double read_scalar(const std::string& name) const;
  /// The shape of dataset `name`; empty for a scalar.
  std::vector<std::size_t> dims(const std::string& name) const;
  /// The string attribute `attribute` of dataset `dataset`, e.g. its units.
  std::string dataset_attribute(const std::string& dataset, const std::string& attribute) const;

  // ---- Attributes of this group
  //
  // Setting an existing attribute replaces it. Getting a missing one, or one
  // of another kind, throws InputError naming it.

  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, const std::string& value);
  /// Any integer type is stored as int64. A template so that a plain `42`
  /// picks this overload rather than being ambiguous with `double`.
  template <std::integral T>
  void set_attribute(const std::string& name, T value) {
    set_int_attribute(name, static_cast<std::int64_t>(value));
  }

  double attribute_double(const std::string& name) const;  // integers convert
  std::int64_t attribute_int(const std::string& name) const;
  std::string attribute_string(const std::string& name) const;

 private:
  friend class H5File;
  explicit H5Group(detail::H5Id id) : id_(std::move(id)) {}
  void set_int_attribute(const std::string& name, std::int64_t value);

  detail::H5Id id_;
};

/// An open HDF5 file; closed when the object is destroyed. Movable, not
/// copyable. Groups taken from it stay usable after it is gone: HDF5 keeps
/// the file open until the last of them is closed too.
class H5File {
 public:
  /// Creates `path`, truncating any existing file (empty until close());
  /// std::runtime_error on failure.
  static H5File create(const std::filesystem::path& path);
  /// Opens `path` read-only; InputError naming the path if it is missing or
  /// not an HDF5 file.
  static H5File open(const std::filesystem::path& path);
  /// Opens `path` for reading and writing (same checks as open). Pair it with
  /// AtomicOutput on a copy so that a failed update leaves the original whole.
  static H5File open_for_update(const std::filesystem::path& path);

  /// The root group "/".
  H5Group root() const;

  /// Writes a created or updated file to its path and closes it. Such a file
  /// lives in memory until then (HDF5's core driver): a file destroyed without
  /// close() is not written at all, and a failed write (a full disk) is a
  /// NumericalError naming the file and the system's reason. Call it before
  /// AtomicOutput::commit().
  void close();

 private:
  explicit H5File(detail::H5Id id) : id_(std::move(id)) {}
  static H5File open_with(const std::filesystem::path& path, unsigned mode);

  detail::H5Id id_;
  std::filesystem::path image_path_;  // where close() writes a created or updated file
};

}  // namespace softglass
