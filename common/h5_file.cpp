// The HDF5 wrapper declared in h5_file.h, on HDF5's C API.
//
// Debian builds HDF5 with the 1.8 API as default, so versioned calls are named
// explicitly (H5Dcreate2, H5Eset_auto2, ...) rather than through their macros.
#include "common/h5_file.h"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <functional>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "common/atomic_output.h"
#include "common/errors.h"

namespace softglass {

static_assert(std::is_same_v<hid_t, std::int64_t>,
              "h5_file.h holds HDF5 identifiers as std::int64_t");

namespace detail {
namespace {

// Each kind of identifier has its own close call; H5Fclose, for one, flushes.
herr_t close_id(hid_t id) {
  switch (H5Iget_type(id)) {
    case H5I_FILE:
      return H5Fclose(id);
    case H5I_GROUP:
      return H5Gclose(id);
    case H5I_DATASET:
      return H5Dclose(id);
    case H5I_ATTR:
      return H5Aclose(id);
    case H5I_DATATYPE:
      return H5Tclose(id);
    case H5I_DATASPACE:
      return H5Sclose(id);
    case H5I_GENPROP_LST:
      return H5Pclose(id);
    default:
      return H5Idec_ref(id);
  }
}

}  // namespace

H5Id& H5Id::operator=(H5Id&& other) noexcept {
  H5Id previous(std::move(other));
  std::swap(id_, previous.id_);  // `previous` now closes what this held
  return *this;
}

H5Id::~H5Id() {
  if (id_ >= 0) close_id(id_);
}

}  // namespace detail

namespace {

using detail::H5Id;

// HDF5 prints its error stack to stderr by default; we report failures as
// exceptions instead. Debian's HDF5 is thread-safe, which makes the setting
// per thread: create() and open() apply it to the thread that uses the file.
void silence_hdf5_errors() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

// The innermost entry of HDF5's error stack says what actually went wrong
// ("name already exists"); the outer ones only name the calls on the way.
std::string hdf5_reason() {
  const char* innermost = nullptr;
  auto take_innermost = [](unsigned depth, const H5E_error2_t* error, void* out) -> herr_t {
    if (depth == 0) *static_cast<const char**>(out) = error->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_innermost, &innermost);
  return innermost ? innermost : "unknown HDF5 error";
}

// Passes through the result of an HDF5 call, or throws Error with `what` and
// HDF5's reason if it failed (negative). Every HDF5 call clears the error
// stack, so `what` must be computed without HDF5 calls or before the call it
// describes: build labels into locals first.
template <class Error = std::runtime_error, class Result>
Result check(Result result, const std::string& what) {
  if (result < 0) throw Error(what + ": " + hdf5_reason());
  return result;
}

template <class Error = std::runtime_error>
H5Id own(hid_t id, const std::string& what) {
  return H5Id(check<Error>(id, what));
}

// HDF5 hands out names C-style: one call for the length, one to fill a buffer.
template <class Get>
std::string fetch_name(Get get) {
  const auto length = check(get(nullptr, 0), "cannot read a name from HDF5");
  std::string name(static_cast<std::size_t>(length), '\0');
  get(name.data(), name.size() + 1);
  return name;
}

std::string object_path(hid_t id) {
  return fetch_name([id](char* buffer, std::size_t size) { return H5Iget_name(id, buffer, size); });
}

std::string file_name(hid_t id) {
  return fetch_name([id](char* buffer, std::size_t size) { return H5Fget_name(id, buffer, size); });
}

// " in 'run.h5'": the tail of every message about an object in a file.
std::string in_file(hid_t id) {
  return " in '" + file_name(id) + "'";
}

// "dataset '/timeseries/strain'": how messages name the child `name` of `group`.
std::string name_of(const char* kind, hid_t group, const std::string& name) {
  const auto base = object_path(group);
  return std::string(kind) + " '" + (base == "/" ? base : base + "/") + name + "'";
}

// "attribute 'units' of '/timeseries/strain'"
std::string attribute_name_of(hid_t object, const std::string& name) {
  return "attribute '" + name + "' of '" + object_path(object) + "'";
}

std::string format_dims(const std::vector<std::size_t>& dims) {
  std::string text;
  for (const auto extent : dims) {
    if (!text.empty()) text += 'x';
    text += std::to_string(extent);
  }
  return text;
}

// ---- Finding and opening

// H5Lexists fails, rather than answering false, when an intermediate group of
// "a/b/c" is missing, so each prefix is checked in turn.
bool link_exists(hid_t group, const std::string& name) {
  if (name.empty()) return false;
  for (auto slash = name.find('/');; slash = name.find('/', slash + 1)) {
    if (H5Lexists(group, name.substr(0, slash).c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) return true;
  }
}

// Opens the child `name` of `group`, which must be a `kind` (group or dataset).
H5Id open_child(hid_t group, const std::string& name, H5I_type_t kind) {
  const char* noun = kind == H5I_GROUP ? "group" : "dataset";
  const auto label = name_of(noun, group, name);
  const auto where = in_file(group);
  if (!link_exists(group, name)) throw InputError(label + " not found" + where);
  auto object =
      own<InputError>(H5Oopen(group, name.c_str(), H5P_DEFAULT), "cannot open " + label + where);
  if (H5Iget_type(object.get()) != kind) {
    throw InputError(label + where + " is not a " + noun);
  }
  return object;
}

// ---- Reading

// Datasets and attributes are read alike but for the final call. A Source
// hides which, so that the checks and conversions below serve both.
struct Source {
  H5Id id;
  bool is_attribute;
  std::string label;  // "dataset '/timeseries/strain' in 'run.h5'"

  H5Id type() const {
    return own<InputError>(is_attribute ? H5Aget_type(id.get()) : H5Dget_type(id.get()),
                           "cannot read the type of " + label);
  }
  H5Id space() const {
    return own<InputError>(is_attribute ? H5Aget_space(id.get()) : H5Dget_space(id.get()),
                           "cannot read the shape of " + label);
  }
  void read(hid_t memory_type, void* buffer) const {
    check<InputError>(is_attribute
                          ? H5Aread(id.get(), memory_type, buffer)
                          : H5Dread(id.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer),
                      "cannot read " + label);
  }
};

Source dataset_source(hid_t group, const std::string& name) {
  auto label = name_of("dataset", group, name) + in_file(group);
  return {open_child(group, name, H5I_DATASET), false, std::move(label)};
}

Source attribute_source(hid_t object, const std::string& name) {
  const auto label = attribute_name_of(object, name);
  const auto where = in_file(object);
  if (H5Aexists(object, name.c_str()) <= 0) throw InputError(label + " not found" + where);
  return {
      own<InputError>(H5Aopen(object, name.c_str(), H5P_DEFAULT), "cannot open " + label + where),
      true, label + where};
}

std::vector<std::size_t> shape(const Source& source) {
  const auto space = source.space();
  const int rank = check<InputError>(H5Sget_simple_extent_ndims(space.get()),
                                     "cannot read the shape of " + source.label);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return {dims.begin(), dims.end()};
}

// Deflate expands data at most ~1032:1, so no honest dataset holds more bytes
// than this many times its file's size (the file may also be unfiltered).
constexpr double kMaxExpansion = 1100.0;

// `count` elements of a Container for the values of `source`. A damaged file
// can claim any size. A claim that no data in the file can back is refused
// before allocating (an allocation that large may not throw at all: the
// address sanitizer aborts, and Linux may grant it and then kill the process
// when it is filled); one that still cannot be allocated is refused too.
template <class Container>
Container allocate(std::size_t count, const Source& source) {
  // Claims under a megabyte are allocated as they come (most reads are
  // attributes and short series: no extra HDF5 calls for them).
  const double bytes = double(count) * double(H5Tget_size(source.type().get()));
  if (bytes > 1e6) {
    const auto file = own<InputError>(H5Iget_file_id(source.id.get()),
                                      "cannot find the file of " + source.label);
    hsize_t file_size = 0;
    check<InputError>(H5Fget_filesize(file.get(), &file_size),
                      "cannot read the size of the file of " + source.label);
    if (bytes > kMaxExpansion * double(file_size)) {
      throw InputError(source.label + " claims " + std::to_string(count) +
                       " values, more than its file of " + std::to_string(file_size) +
                       " bytes can hold");
    }
  }
  try {
    return Container(count, typename Container::value_type{});
  } catch (const std::bad_alloc&) {
  } catch (const std::length_error&) {
  }
  throw InputError(source.label + " claims a size of " + std::to_string(count) +
                   ", more than memory holds");
}

// Every value of a numeric source, converted by HDF5 to `memory_type`.
template <class T>
std::vector<T> read_numbers(const Source& source, hid_t memory_type, bool integers_only) {
  const auto type_class = H5Tget_class(source.type().get());
  if (type_class != H5T_INTEGER && (integers_only || type_class != H5T_FLOAT)) {
    throw InputError(source.label + " does not hold " + (integers_only ? "integers" : "numbers"));
  }
  const auto count = check<InputError>(H5Sget_simple_extent_npoints(source.space().get()),
                                       "cannot read the size of " + source.label);
  auto values = allocate<std::vector<T>>(static_cast<std::size_t>(count), source);
  if (!values.empty()) source.read(memory_type, values.data());  // HDF5 refuses a null buffer
  return values;
}

template <class T>
T read_one_number(const Source& source, hid_t memory_type, bool integers_only) {
  const auto values = read_numbers<T>(source, memory_type, integers_only);
  if (values.size() != 1) {
    throw InputError(source.label + " holds " + std::to_string(values.size()) +
                     " values, expected one");
  }
  return values.front();
}

// One string, variable-length (as written here) or fixed-length (as some
// other writers do), in whatever character set it was stored.
std::string read_text(const Source& source) {
  const auto file_type = source.type();
  const auto npoints = H5Sget_simple_extent_npoints(source.space().get());
  if (H5Tget_class(file_type.get()) != H5T_STRING || npoints != 1) {
    throw InputError(source.label + " does not hold a single string");
  }
  const auto memory_type = own(H5Tcopy(H5T_C_S1), "cannot create a string type");
  H5Tset_cset(memory_type.get(), H5Tget_cset(file_type.get()));
  if (H5Tis_variable_str(file_type.get()) > 0) {
    H5Tset_size(memory_type.get(), H5T_VARIABLE);
    char* chars = nullptr;
    source.read(memory_type.get(), &chars);
    std::string text = chars ? chars : "";
    H5free_memory(chars);
    return text;
  }
  // Null padding in memory: HDF5 then strips space padding (Fortran's) too.
  auto text = allocate<std::string>(H5Tget_size(file_type.get()), source);
  H5Tset_size(memory_type.get(), text.size());
  H5Tset_strpad(memory_type.get(), H5T_STR_NULLPAD);
  source.read(memory_type.get(), text.data());
  text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
  return text;
}

// ---- Writing

// Text is stored as variable-length UTF-8: no length limit, and h5py decodes
// symbols such as "σ" (h5dump 1.10 prints them as octal escapes).
H5Id utf8_string_type() {
  auto type = own(H5Tcopy(H5T_C_S1), "cannot create a string type");
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

// Sets the single-valued attribute `name` of `object`, replacing an old one.
void write_attribute(hid_t object, const std::string& name, hid_t type, const void* value) {
  const auto label = attribute_name_of(object, name) + in_file(object);
  if (H5Aexists(object, name.c_str()) > 0) {
    check(H5Adelete(object, name.c_str()), "cannot replace " + label);
  }
  const auto space = own(H5Screate(H5S_SCALAR), "cannot create a dataspace");
  const auto attribute =
      own(H5Acreate2(object, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
          "cannot create " + label);
  check(H5Awrite(attribute.get(), type, value), "cannot write " + label);
}

void write_text_attribute(hid_t object, const std::string& name, const std::string& text) {
  const char* chars = text.c_str();
  write_attribute(object, name, utf8_string_type().get(), &chars);
}

// Creates dataset `name` with the given type, shape and creation properties,
// writes all of `data` (null when there is nothing to write; HDF5 refuses a
// null buffer) and attaches `info`.
void write_dataset(hid_t group, const std::string& name, hid_t type, hid_t space, hid_t properties,
                   const void* data, const DatasetInfo& info) {
  const auto label = name_of("dataset", group, name) + in_file(group);
  const auto dataset =
      own(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, properties, H5P_DEFAULT),
          "cannot create " + label);
  if (data) {
    check(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "cannot write " + label);
  }
  if (!info.units.empty()) write_text_attribute(dataset.get(), "units", info.units);
  if (!info.description.empty()) {
    write_text_attribute(dataset.get(), "description", info.description);
  }
}

constexpr std::size_t kCompressAbove = 4096;  // values
constexpr hsize_t kChunkValues = 16384;
constexpr unsigned kDeflateLevel = 4;

// Chunks of about 16k values (128 KiB of doubles) fit HDF5's default 1 MiB
// chunk cache and give deflate enough to work on. A 2-D chunk spans whole rows
// where a row fits, so that reading a row touches one chunk.
std::vector<hsize_t> chunk_shape(const std::vector<hsize_t>& dims) {
  auto chunk = dims;
  const hsize_t row = dims.size() == 2 ? std::min(dims[1], kChunkValues) : 1;
  if (dims.size() == 2) chunk[1] = row;
  chunk[0] = std::clamp(kChunkValues / row, hsize_t{1}, dims[0]);
  return chunk;
}

// Large 1-D and 2-D arrays (trajectories, per-particle fields) are chunked and
// compressed. Shuffle first regroups the bytes of all values by significance,
// which gives deflate far longer runs in floating-point data. Small arrays stay
// contiguous: chunk indexing would cost more than compression saves.
H5Id creation_properties(const std::vector<hsize_t>& dims, std::size_t count) {
  auto properties = own(H5Pcreate(H5P_DATASET_CREATE), "cannot create dataset properties");
  if (count > kCompressAbove && dims.size() <= 2 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
    const auto chunk = chunk_shape(dims);
    const auto id = properties.get();
    check(H5Pset_chunk(id, static_cast<int>(chunk.size()), chunk.data()), "cannot set chunks");
    if (H5Zfilter_avail(H5Z_FILTER_SHUFFLE) > 0) check(H5Pset_shuffle(id), "cannot set shuffle");
    check(H5Pset_deflate(id, kDeflateLevel), "cannot set deflate");
  }
  return properties;
}

void write_array(hid_t group, const std::string& name, hid_t type, const void* data,
                 std::size_t size, std::vector<std::size_t> dims, const DatasetInfo& info) {
  if (dims.empty()) dims.push_back(size);
  const auto count = std::accumulate(dims.begin(), dims.end(), std::size_t{1}, std::multiplies<>());
  if (count != size) {
    throw std::invalid_argument(name_of("dataset", group, name) + in_file(group) + ": dims " +
                                format_dims(dims) + " hold " + std::to_string(count) +
                                " values, but " + std::to_string(size) + " were given");
  }
  const std::vector<hsize_t> extent(dims.begin(), dims.end());
  const auto space = own(H5Screate_simple(static_cast<int>(extent.size()), extent.data(), nullptr),
                         "cannot create a dataspace of dims " + format_dims(dims));
  const auto properties = creation_properties(extent, count);
  write_dataset(group, name, type, space.get(), properties.get(), size ? data : nullptr, info);
}

void write_single(hid_t group, const std::string& name, hid_t type, const void* value,
                  const DatasetInfo& info) {
  const auto space = own(H5Screate(H5S_SCALAR), "cannot create a dataspace");
  write_dataset(group, name, type, space.get(), H5P_DEFAULT, value, info);
}

}  // namespace

// ---- H5Group: structure

std::string H5Group::path() const {
  return object_path(id_.get());
}

H5Group H5Group::create_group(const std::string& name) {
  const auto label = name_of("group", id_.get(), name) + in_file(id_.get());
  return H5Group(own(H5Gcreate2(id_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     "cannot create " + label));
}

H5Group H5Group::group(const std::string& name) const {
  return H5Group(open_child(id_.get(), name, H5I_GROUP));
}

bool H5Group::has_child(const std::string& name) const {
  return link_exists(id_.get(), name);
}

bool H5Group::has_attribute(const std::string& name) const {
  return H5Aexists(id_.get(), name.c_str()) > 0;
}

void H5Group::remove_child(const std::string& name) {
  check(H5Ldelete(id_.get(), name.c_str(), H5P_DEFAULT), "cannot remove '" + name + "' from '" + path() + "'");
}

// Names are fetched by index rather than through H5Literate's callback, which
// a C++ exception must not cross.
std::vector<std::string> H5Group::children() const {
  const auto what = "cannot list group '" + path() + "'";
  H5G_info_t info;
  check<InputError>(H5Gget_info(id_.get(), &info), what);
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    names.push_back(fetch_name([this, i](char* buffer, std::size_t size) {
      return H5Lget_name_by_idx(id_.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, buffer, size,
                                H5P_DEFAULT);
    }));
  }
  return names;
}

// ---- H5Group: datasets

void H5Group::write(const std::string& name, std::span<const double> data,
                    std::vector<std::size_t> dims, const DatasetInfo& info) {
  write_array(id_.get(), name, H5T_NATIVE_DOUBLE, data.data(), data.size(), std::move(dims), info);
}

void H5Group::write(const std::string& name, std::span<const std::int64_t> data,
                    std::vector<std::size_t> dims, const DatasetInfo& info) {
  write_array(id_.get(), name, H5T_NATIVE_INT64, data.data(), data.size(), std::move(dims), info);
}

void H5Group::write(const std::string& name, std::span<const std::uint32_t> data,
                    std::vector<std::size_t> dims, const DatasetInfo& info) {
  write_array(id_.get(), name, H5T_NATIVE_UINT32, data.data(), data.size(), std::move(dims), info);
}

void H5Group::write_string(const std::string& name, const std::string& text,
                           const DatasetInfo& info) {
  const char* chars = text.c_str();
  write_single(id_.get(), name, utf8_string_type().get(), &chars, info);
}

void H5Group::write_scalar(const std::string& name, double value, const DatasetInfo& info) {
  write_single(id_.get(), name, H5T_NATIVE_DOUBLE, &value, info);
}

void H5Group::set_dataset_attribute(const std::string& dataset, const std::string& attribute,
                                    const std::string& value) {
  write_text_attribute(open_child(id_.get(), dataset, H5I_DATASET).get(), attribute, value);
}

H5Array H5Group::read_array(const std::string& name) const {
  const auto source = dataset_source(id_.get(), name);
  return {read_numbers<double>(source, H5T_NATIVE_DOUBLE, false), shape(source)};
}

std::vector<std::int64_t> H5Group::read_int_array(const std::string& name) const {
  return read_numbers<std::int64_t>(dataset_source(id_.get(), name), H5T_NATIVE_INT64, true);
}

std::string H5Group::read_string(const std::string& name) const {
  return read_text(dataset_source(id_.get(), name));
}

double H5Group::read_scalar(const std::string& name) const {
  return read_one_number<double>(dataset_source(id_.get(), name), H5T_NATIVE_DOUBLE, false);
}

std::vector<std::size_t> H5Group::dims(const std::string& name) const {
  return shape(dataset_source(id_.get(), name));
}

std::string H5Group::dataset_attribute(const std::string& dataset,
                                       const std::string& attribute) const {
  const auto object = open_child(id_.get(), dataset, H5I_DATASET);
  return read_text(attribute_source(object.get(), attribute));
}

// ---- H5Group: attributes

void H5Group::set_attribute(const std::string& name, double value) {
  write_attribute(id_.get(), name, H5T_NATIVE_DOUBLE, &value);
}

void H5Group::set_attribute(const std::string& name, const std::string& value) {
  write_text_attribute(id_.get(), name, value);
}

void H5Group::set_int_attribute(const std::string& name, std::int64_t value) {
  write_attribute(id_.get(), name, H5T_NATIVE_INT64, &value);
}

double H5Group::attribute_double(const std::string& name) const {
  return read_one_number<double>(attribute_source(id_.get(), name), H5T_NATIVE_DOUBLE, false);
}

std::int64_t H5Group::attribute_int(const std::string& name) const {
  return read_one_number<std::int64_t>(attribute_source(id_.get(), name), H5T_NATIVE_INT64, true);
}

std::string H5Group::attribute_string(const std::string& name) const {
  return read_text(attribute_source(id_.get(), name));
}

// ---- H5File

namespace {

// Files written by softglass live in memory (HDF5's core driver, no backing
// store) until close() writes their image through the one checked writer
// (atomic_output.h). HDF5 itself never writes to the disk: when its own write
// fails (a full disk) it leaves the file half-closed, and its exit handler
// then crashes closing it.
H5Id in_memory_access() {
  H5Id fapl = own(H5Pcreate(H5P_FILE_ACCESS), "cannot create an HDF5 property list");
  check(H5Pset_fapl_core(fapl.get(), 1 << 20, /*backing_store=*/false),
        "cannot select HDF5's in-memory driver");
  return fapl;
}

}  // namespace

H5File H5File::create(const std::filesystem::path& path) {
  silence_hdf5_errors();
  write_file(path, path.string(), [](std::ostream&) {});  // claimed now: a bad path fails here
  const H5Id fapl = in_memory_access();
  H5File file(own(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()),
                  "cannot create HDF5 file '" + path.native() + "'"));
  file.image_path_ = path;
  return file;
}

H5File H5File::open(const std::filesystem::path& path) { return open_with(path, H5F_ACC_RDONLY); }

H5File H5File::open_for_update(const std::filesystem::path& path) {
  H5File file = open_with(path, H5F_ACC_RDWR);
  file.image_path_ = path;
  return file;
}

namespace {

// The little-endian unsigned integer of `width` bytes at `at` of `bytes`.
std::uint64_t little_endian(std::string_view bytes, std::size_t at, int width) {
  std::uint64_t value = 0;
  for (int k = width - 1; k >= 0; --k)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return value;
}

// Reads pieces of a file by offset; a piece past the end comes back short.
class ByteReader {
 public:
  explicit ByteReader(const std::filesystem::path& path)
      : in_(path, std::ios::binary), size_(std::filesystem::file_size(path)) {}
  std::uint64_t size() const { return size_; }
  std::string read(std::uint64_t at, std::size_t count) {
    std::string bytes(at < size_ ? std::min<std::uint64_t>(count, size_ - at) : 0, '\0');
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in_.gcount(), 0)));
    return bytes;
  }

 private:
  std::ifstream in_;
  std::uint64_t size_;
};

// HDF5 (1.10) reads a global heap collection, where the variable-length
// strings live, object by object, each header giving the offset of the next;
// a damaged size field can make an object of size 0, and the library then
// loops forever (a damaged checkpoint in tests/fuzz did; docs/validation.md).
// Such a file is refused before HDF5 reads it: every collection, found by its
// signature, must be tiled by its objects, as HDF5 writes it. Layout (HDF5
// file format specification, "Global Heap"): "GCOL", version 1, 3 reserved
// bytes, the collection's size; then per object a 2-byte index, 2-byte
// reference count, 4 reserved bytes, its size and its data padded to 8
// bytes; index 0 is the free space, whose size includes its header. Only
// files with 8-byte lengths (the library's default) are checked. The file is
// streamed in chunks and each collection walked header by header, so a large
// run file costs one sequential read and no more memory than a chunk.
void refuse_looping_global_heaps(const std::filesystem::path& path, const std::string& quoted) {
  ByteReader file(path);
  // The superblock's size of lengths: byte 14 (versions 0, 1) or 10 (2, 3).
  const std::string superblock = file.read(0, 16);
  const std::string_view kFileSignature("\x89HDF\r\n\x1a\n", 8);
  if (superblock.size() < 16 || superblock.compare(0, 8, kFileSignature) != 0) return;
  if (superblock[superblock[8] < 2 ? 14 : 10] != 8) return;
  constexpr std::uint64_t kHeader = 16, kMinimumSize = 4096, kChunk = std::uint64_t{1} << 20;
  const std::string_view kSignature("GCOL\x01\x00\x00\x00", 8);
  const auto refuse_unless_tiled = [&](std::uint64_t at, std::uint64_t size) {
    const std::uint64_t end = at + size;
    for (std::uint64_t object = at + kHeader; object + kHeader <= end;) {
      const std::string header = file.read(object, kHeader);
      const std::uint64_t length = little_endian(header, 8, 8);
      const std::uint64_t step =
          little_endian(header, 0, 2) > 0 ? kHeader + (length + 7) / 8 * 8 : length;
      if (step == 0 || step > end - object)
        throw InputError(quoted + " is damaged: its global heap at byte " + std::to_string(at) +
                         " does not hold together");
      object += step;
    }
  };
  // Chunks overlap by a collection header less one byte, so that no header is
  // split between two of them and none is found twice.
  for (std::uint64_t chunk = 0; chunk < file.size(); chunk += kChunk) {
    const std::string bytes = file.read(chunk, kChunk + kHeader - 1);
    for (std::size_t hit = bytes.find(kSignature);
         hit != std::string::npos && hit + kHeader <= bytes.size() && hit < kChunk;
         hit = bytes.find(kSignature, hit + 1)) {
      const std::uint64_t at = chunk + hit, size = little_endian(bytes, hit + 8, 8);
      if (size < kMinimumSize || size > file.size() - at) continue;  // not a collection
      refuse_unless_tiled(at, size);
    }
  }
}

}  // namespace

H5File H5File::open_with(const std::filesystem::path& path, unsigned mode) {
  silence_hdf5_errors();
  const auto quoted = "'" + path.native() + "'";
  std::error_code ignored;
  if (!std::filesystem::exists(path, ignored)) {
    throw InputError("HDF5 file " + quoted + " does not exist");
  }
  // On a directory H5Fis_hdf5 fails with a wall of low-level detail instead.
  if (!std::filesystem::is_regular_file(path, ignored) ||
      check<InputError>(H5Fis_hdf5(path.c_str()), "cannot read " + quoted) == 0) {
    throw InputError(quoted + " is not an HDF5 file");
  }
  refuse_looping_global_heaps(path, quoted);
  // An update is read into memory and written back whole by close().
  const H5Id fapl = mode == H5F_ACC_RDWR ? in_memory_access() : H5Id();
  H5File file(own<InputError>(
      H5Fopen(path.c_str(), mode, mode == H5F_ACC_RDWR ? fapl.get() : H5P_DEFAULT),
      "cannot open HDF5 file " + quoted));
  // A damaged root group is the file's fault, not the program's: said here,
  // naming the file, before root() would fail anonymously.
  own<InputError>(H5Gopen2(file.id_.get(), "/", H5P_DEFAULT),
                  quoted + " is damaged: its root group cannot be opened");
  return file;
}

H5Group H5File::root() const {
  return H5Group(own(H5Gopen2(id_.get(), "/", H5P_DEFAULT), "cannot open the root group"));
}

void H5File::close() {
  if (id_.get() < 0) return;  // closed already
  if (!image_path_.empty()) {
    const auto what = "cannot write HDF5 file '" + image_path_.string() + "'";
    check(H5Fflush(id_.get(), H5F_SCOPE_LOCAL), what);
    const auto size = check(H5Fget_file_image(id_.get(), nullptr, 0), what);
    std::vector<char> image(static_cast<std::size_t>(size));
    check(H5Fget_file_image(id_.get(), image.data(), image.size()), what);
    write_file(image_path_, image_path_.string(), [&](std::ostream& out) {
      out.write(image.data(), static_cast<std::streamsize>(image.size()));
    });
  }
  id_ = detail::H5Id();
}

}  // namespace softglass
