#include "common/atomic_output.h"

#include <unistd.h>

#include <system_error>

#include "common/errors.h"

namespace softglass {

AtomicOutput::AtomicOutput(std::filesystem::path final_path, bool overwrite)
    : final_(std::move(final_path)) {
  if (final_.empty()) throw InputError("output path is empty");
  if (std::filesystem::exists(final_) && !overwrite) {
    throw OutputExistsError("output file '" + final_.string() +
                            "' exists; pass --force to overwrite it");
  }
  const auto dir = final_.has_parent_path() ? final_.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(dir)) {
    throw InputError("output directory '" + dir.string() + "' does not exist");
  }
  temporary_ = final_;
  temporary_ += ".tmp" + std::to_string(::getpid());
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicOutput::commit() {
  std::filesystem::rename(temporary_, final_);
  committed_ = true;
}

}  // namespace softglass
