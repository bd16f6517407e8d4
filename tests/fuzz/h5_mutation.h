// Damaged HDF5 files for the fuzz tests of HDF5 readers, two ways:
//   - bytes: the file cut short or some bytes overwritten, as a crash during
//     a write or a bad disk leaves it;
//   - structure: a dataset, group or attribute removed, or rewritten (through
//     the project's own wrapper) with NaN, inf, a negative or huge value, one
//     value too few, another shape, no values, or text instead of numbers, as
//     another program or an older version could have written it.
// fuzz_h5 runs a campaign over such copies of a valid seed file.
#pragma once

#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "common/h5_file.h"
#include "fuzz_check.h"
#include "mutation.h"
#include "tests/common/test_files.h"

namespace softglass::testing::fuzz {

struct H5Object {
  std::string path;  // below the root, "packing/configuration/radius"
  bool group;
};

inline void collect_objects(const H5Group& group, const std::string& prefix,
                            std::vector<H5Object>& out) {
  for (const std::string& name : group.children()) {
    try {
      const H5Group child = group.group(name);
      out.push_back({prefix + name, true});
      collect_objects(child, prefix + name + "/", out);
    } catch (const InputError&) {  // not a group: a dataset
      out.push_back({prefix + name, false});
    }
  }
}

// The attributes our files carry; a group is damaged in one it has.
inline const std::vector<std::string>& known_attributes() {
  static const std::vector<std::string> names = {"format_version",   "kind",
                                                 "command",          "contact_law",
                                                 "converged",        "averaged_strain",
                                                 "transient_strain", "coordination",
                                                 "layering",         "mean",
                                                 "standard_error",   "samples",
                                                 "block_size",       "reliable"};
  return names;
}

// "%g" of `value`: std::to_string writes 1e308 in 309 digits.
inline std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

inline void damage_attribute(H5Group& group, const std::string& path, Mutator& m) {
  std::vector<std::string> present;
  for (const std::string& name : known_attributes())
    if (group.has_attribute(name)) present.push_back(name);
  if (present.empty()) return;
  const std::string& name = m.pick(present);
  const std::size_t kind = m.below(4);
  m.log("attribute '", name, "' of '/", path, "' set to ");
  if (kind == 0) {
    const std::string& value = m.pick(hostile_numbers());
    group.set_attribute(name, value);
    m.log("the text '", value, "'; ");
  } else if (kind == 1) {
    const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity(), -1.0, 1e308, 0.5};
    const double value = values[m.below(5)];
    group.set_attribute(name, value);
    m.log(shown(value), "; ");
  } else {
    const std::int64_t values[] = {-1, 0, 2, std::numeric_limits<std::int64_t>::max(),
                                   std::numeric_limits<std::int64_t>::min()};
    const std::int64_t value = values[m.below(5)];
    group.set_attribute(name, value);
    m.log(std::to_string(value), "; ");
  }
}

// Rewrites the numeric dataset `name` of `parent` in a damaged form.
inline void damage_numbers(H5Group& parent, const std::string& name, H5Array a, Mutator& m) {
  parent.remove_child(name);
  static const double hostile[] = {std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(),
                                   -1.0,
                                   0.0,
                                   1e308,
                                   -1e308,
                                   1e-320,
                                   1e19};
  const double value = hostile[m.below(std::size(hostile))];
  switch (m.below(7)) {
    case 0:
      if (!a.data.empty()) a.data[m.below(a.data.size())] = value;
      m.log("one value set to ", shown(value), "; ");
      break;
    case 1:
      for (double& v : a.data) v = value;
      m.log("every value set to ", shown(value), "; ");
      break;
    case 2:
      a.dims.clear();  // 1-D
      m.log("flattened; ");
      break;
    case 3:
      if (!a.data.empty()) a.data.pop_back();
      a.dims.clear();
      m.log("one value dropped; ");
      break;
    case 4:
      a = {};
      a.dims = {0};
      m.log("emptied; ");
      break;
    case 5:
      parent.write_string(name, "garbage");
      m.log("replaced by text; ");
      return;
    default:
      if (a.dims.size() > 1) {
        std::swap(a.dims.front(), a.dims.back());
        m.log("dims swapped; ");
      } else {
        a.data.push_back(value);
        a.dims.clear();
        m.log("one value added; ");
      }
  }
  if (a.dims.empty() && a.data.size() == 1 && m.below(2) == 0) {
    parent.write_scalar(name, a.data.front());
  } else {
    parent.write(name, a.data, a.dims);
  }
}

/// Removes or damages one object of `file`, chosen by `m`.
inline void damage_structure(const std::filesystem::path& file, Mutator& m) {
  H5File h5 = H5File::open_for_update(file);
  H5Group root = h5.root();
  std::vector<H5Object> objects;
  collect_objects(root, "", objects);
  const H5Object target = objects.empty() ? H5Object{"", true} : m.pick(objects);
  const auto slash = target.path.rfind('/');
  H5Group parent =
      slash == std::string::npos ? h5.root() : root.group(target.path.substr(0, slash));
  const std::string name = slash == std::string::npos ? target.path : target.path.substr(slash + 1);
  if (target.group || objects.empty()) {
    H5Group group = target.path.empty() ? h5.root() : root.group(target.path);
    if (!target.path.empty() && m.below(3) == 0) {
      parent.remove_child(name);
      m.log("group '/", target.path, "' removed; ");
    } else {
      damage_attribute(group, target.path, m);
    }
  } else if (m.below(6) == 0) {
    parent.remove_child(name);
    m.log("dataset '/", target.path, "' removed; ");
  } else {
    m.log("dataset '/", target.path, "' ");
    try {
      damage_numbers(parent, name, parent.read_array(name), m);
    } catch (const InputError&) {  // text: garbled, or numbers instead
      const std::string text = parent.read_string(name);
      parent.remove_child(name);
      if (m.below(4) == 0) {
        parent.write_scalar(name, 1.0);
        m.log("replaced by a number; ");
      } else {
        parent.write_string(name, m.mutate_text(text));
      }
    }
  }
  h5.close();
}

/// Checks that `read(seed_file, input)` accepts the seed, then gives it
/// `budget` damaged copies of it (a third damaged in bytes, the rest in
/// structure), each written to `work`.
template <class Read>
void fuzz_h5(const std::filesystem::path& seed_file, const std::filesystem::path& work,
             std::uint64_t seed, std::size_t budget, Read read) {
  ASSERT_TRUE(read(seed_file, describe(0, "seed, unchanged"))) << seed_file;
  const std::string bytes = read_text(seed_file);
  const std::size_t count = iterations(budget);
  for (std::size_t i = 0; i < count && !enough_failures(); ++i) {
    Mutator mutator(seed, i);
    if (mutator.below(3) == 0) {
      write_text(work, mutator.mutate_bytes(bytes));
    } else {
      std::filesystem::copy_file(seed_file, work,
                                 std::filesystem::copy_options::overwrite_existing);
      damage_structure(work, mutator);
    }
    read(work, describe(i, mutator.description()));
  }
}

}  // namespace softglass::testing::fuzz
