#include "common/atomic_output.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include "common/errors.h"

namespace softglass {

namespace {

const std::string kTemporarySuffix = ".tmp";

std::filesystem::path directory_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

// The temporaries this process holds, for the handler of the terminating
// signals (SIGINT: Ctrl-C, SIGTERM: a batch system's time limit, SIGHUP: a
// closed terminal): it may only call async-signal-safe functions, so the
// paths sit in fixed slots, each published by its flag after it is written.
// A temporary beyond the slots is left to remove_dead_temporaries, as after
// SIGKILL.
constexpr std::size_t kSlots = 256;
constexpr std::size_t kPathBytes = 4096;
char temporary_slots[kSlots][kPathBytes];
volatile std::sig_atomic_t slot_used[kSlots];
constexpr int kTerminatingSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction previous_actions[std::size(kTerminatingSignals)];

// The line set_interruption_notice registered, published by its length.
constexpr std::size_t kNoticeBytes = 1024;
char interruption_notice[kNoticeBytes];
volatile std::sig_atomic_t notice_length = 0;

// Removes every held temporary, says so when a command registered a notice,
// then gives the signal back to the action it had before (the default:
// termination) and raises it again — delivered when this handler returns —
// so that the exit status still names the signal.
void remove_temporaries_and_terminate(int signal) {
  for (std::size_t k = 0; k < kSlots; ++k)
    if (slot_used[k] != 0) ::unlink(temporary_slots[k]);
  const std::size_t length = static_cast<std::size_t>(notice_length);
  if (length > 0 && ::write(STDERR_FILENO, interruption_notice, length) < 0) {
    // Nothing to do about a closed stderr: the process ends all the same.
  }
  for (std::size_t s = 0; s < std::size(kTerminatingSignals); ++s)
    if (kTerminatingSignals[s] == signal) ::sigaction(signal, &previous_actions[s], nullptr);
  ::raise(signal);
}

void install_signal_cleanup() {
  static const bool installed = [] {
    for (std::size_t s = 0; s < std::size(kTerminatingSignals); ++s) {
      const int signal = kTerminatingSignals[s];
      ::sigaction(signal, nullptr, &previous_actions[s]);
      // An ignored signal (nohup, a background job of a script) ends nothing.
      if (previous_actions[s].sa_handler == SIG_IGN) continue;
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_terminate;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal, &action, nullptr);
    }
    return true;
  }();
  (void)installed;
}

// The slot holding `path`, or AtomicOutput::kNoSlot when none was free.
std::size_t hold(const std::filesystem::path& path) {
  install_signal_cleanup();
  const std::string text = path.string();
  if (text.size() >= kPathBytes) return AtomicOutput::kNoSlot;
  for (std::size_t k = 0; k < kSlots; ++k) {
    if (slot_used[k] != 0) continue;
    std::memcpy(temporary_slots[k], text.c_str(), text.size() + 1);
    slot_used[k] = 1;
    return k;
  }
  return AtomicOutput::kNoSlot;
}

// Frees the slot (once: it may be held by another output afterwards).
void release(std::size_t& slot) {
  if (slot < kSlots) slot_used[slot] = 0;
  slot = AtomicOutput::kNoSlot;
}

// Puts `from` at `to` unless `to` exists: 0, or the errno (EEXIST when it
// exists). The check and the rename are one step, so that of two processes
// only one can succeed.
int rename_without_replacing(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  // Some file systems (older NFS, FUSE) do not take the flag; link() never
  // replaces a file either.
  if (errno != EINVAL && errno != ENOSYS) return errno;
  if (::link(from.c_str(), to.c_str()) == 0) {
    ::unlink(from.c_str());
    return 0;
  }
  if (errno != EPERM && errno != EOPNOTSUPP) return errno;
  // Nor hard links (vfat, some FUSE): a check just before the rename is the
  // best such a file system allows.
  struct stat existing {};
  if (::stat(to.c_str(), &existing) == 0) return EEXIST;
  return ::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

}  // namespace

void set_interruption_notice(const std::string& line) {
  install_signal_cleanup();
  notice_length = 0;  // no half-written notice is ever printed
  if (line.empty()) return;
  // On a terminal the notice begins a line of its own, after "^C" or a
  // progress bar; in a log it is a line like the others.
  const std::string text = fmt::format("{}{}\n", ::isatty(STDERR_FILENO) ? "\n" : "", line);
  const std::size_t length = std::min(text.size(), kNoticeBytes);
  std::memcpy(interruption_notice, text.data(), length);
  notice_length = static_cast<std::sig_atomic_t>(length);
}

void remove_dead_temporaries(const std::filesystem::path& directory, const std::string& name) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string file = entry.path().filename().string();
    const auto suffix = file.rfind(kTemporarySuffix);
    if (suffix == std::string::npos || suffix == 0) continue;
    if (!name.empty() && file.compare(0, suffix, name) != 0) continue;
    const std::string digits = file.substr(suffix + kTemporarySuffix.size());
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      std::filesystem::remove(entry.path(), ignored);
    }
  }
}

void write_file(const std::filesystem::path& path, const std::string& shown,
                     const std::function<void(std::ostream&)>& body) {
  errno = 0;
  std::ofstream file(path, std::ios::binary);
  if (file) body(file);
  file.close();
  if (!file) {
    throw NumericalError(fmt::format("cannot write '{}': {}", shown,
                                     errno != 0 ? std::strerror(errno) : "write error"));
  }
}

void AtomicOutput::write_and_commit(const std::function<void(std::ostream&)>& body) {
  write_file(temporary_, final_.string(), body);
  commit();
}

AtomicOutput::AtomicOutput(std::filesystem::path final_path, bool overwrite)
    : final_(std::move(final_path)), overwrite_(overwrite) {
  if (final_.empty()) throw InputError("output path is empty");
  if (std::filesystem::exists(final_) && !overwrite) {
    throw OutputExistsError("output file '" + final_.string() +
                            "' exists; pass --force to overwrite it");
  }
  const auto dir = directory_of(final_);
  if (!std::filesystem::is_directory(dir)) {
    throw InputError("output directory '" + dir.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(final_)) {
    throw InputError("output '" + final_.string() + "' is a directory; name a file to write");
  }
  temporary_ = final_;
  temporary_ += kTemporarySuffix + std::to_string(::getpid());
  // The temporary file is claimed now, so that an output that cannot be
  // written (a read-only folder, a full quota) is refused before the work, not
  // after it.
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (fd < 0) {
    throw InputError(fmt::format("cannot write in output directory '{}': {}", dir.string(),
                                 std::strerror(errno)));
  }
  ::close(fd);
  slot_ = hold(temporary_);
}

AtomicOutput::~AtomicOutput() {
  release(slot_);
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicOutput::commit(bool tidy) {
  std::error_code error;
  // The file as it is put in place, for withdraw(): a writer may have made
  // the temporary anew.
  if (struct stat identity {}; ::stat(temporary_.c_str(), &identity) == 0) {
    device_ = static_cast<std::uint64_t>(identity.st_dev);
    inode_ = static_cast<std::uint64_t>(identity.st_ino);
  }
  if (overwrite_) {
    std::filesystem::rename(temporary_, final_, error);
  } else if (const int failure = rename_without_replacing(temporary_, final_); failure == EEXIST) {
    throw OutputExistsError(fmt::format(
        "'{}' was written by another process while this one ran: that result is kept and this "
        "one's discarded (pass --force to replace it)",
        final_.string()));
  } else if (failure != 0) {
    error = std::error_code(failure, std::generic_category());
  }
  if (error) {
    throw NumericalError(fmt::format("cannot put the finished '{}' in place of '{}': {}",
                                     temporary_.string(), final_.string(), error.message()));
  }
  committed_ = true;
  release(slot_);
  if (tidy) remove_dead_temporaries(directory_of(final_), final_.filename().string());
}

TerminatingSignalsHeld::TerminatingSignalsHeld() {
  sigset_t held;
  sigemptyset(&held);
  for (const int signal : kTerminatingSignals) sigaddset(&held, signal);
  ::pthread_sigmask(SIG_BLOCK, &held, &previous_);
}

TerminatingSignalsHeld::~TerminatingSignalsHeld() {
  ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

void AtomicOutput::withdraw() {
  if (!committed_ || overwrite_) return;  // a replaced file cannot be brought back
  struct stat identity {};
  if (::stat(final_.c_str(), &identity) == 0 &&
      static_cast<std::uint64_t>(identity.st_dev) == device_ &&
      static_cast<std::uint64_t>(identity.st_ino) == inode_)
    ::unlink(final_.c_str());
  committed_ = false;
}

void AtomicOutput::commit_together(const std::vector<AtomicOutput*>& outputs, bool tidy) {
  {
    const TerminatingSignalsHeld held;
    std::size_t done = 0;
    try {
      for (; done < outputs.size(); ++done) outputs[done]->commit(/*tidy=*/false);
    } catch (...) {
      while (done > 0) outputs[--done]->withdraw();
      throw;
    }
  }
  if (!tidy) return;
  for (AtomicOutput* out : outputs)
    remove_dead_temporaries(directory_of(out->final_), out->final_.filename().string());
}

}  // namespace softglass
