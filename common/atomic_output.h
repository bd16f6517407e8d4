// Writing a result file so that it is either complete or absent.
//
// The file is written under a temporary name in the same directory and renamed
// onto the final path only when `commit()` is called; an exception or a kill
// before that leaves any earlier file at the final path untouched. A process
// ended by SIGINT, SIGTERM or SIGHUP removes its temporary files
// (`<final>.tmp<PID>`) before it terminates by the signal; one killed by
// SIGKILL cannot, and the next process that completes the same output removes
// those of processes no longer alive on this machine.
//
// An output not to be overwritten is claimed to the end: it is refused when
// it exists at the start, and its commit never replaces a file either, so
// that of two processes writing the same output at once the later one fails
// (OutputExistsError) instead of silently replacing the earlier one's result.
#pragma once

#include <csignal>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace softglass {

/// Writes what `body` puts into the stream to `path` (truncated first; text
/// or binary alike); NumericalError naming `shown` (the file the user asked
/// for) and the system's reason (a full disk, a quota) if any of it cannot be
/// written. Every file softglass writes goes through it.
void write_file(const std::filesystem::path& path, const std::string& shown,
                     const std::function<void(std::ostream&)>& body);

/// Removes, in `directory`, the temporaries (`<name>.tmp<PID>`) of processes
/// no longer alive on this machine (kill with signal 0 reports ESRCH); with
/// `name`, only that output's. A live process's temporary is kept, whoever
/// owns it; only the file name decides, so nothing else is ever removed.
void remove_dead_temporaries(const std::filesystem::path& directory, const std::string& name = "");

/// Holds back the terminating signals (SIGINT, SIGTERM, SIGHUP) of the calling
/// thread for its lifetime; one arriving meanwhile is delivered when released.
/// Around the renames that put one result's files in place, so that a signal
/// cannot leave new files beside old ones.
class TerminatingSignalsHeld {
 public:
  TerminatingSignalsHeld();
  ~TerminatingSignalsHeld();
  TerminatingSignalsHeld(const TerminatingSignalsHeld&) = delete;
  TerminatingSignalsHeld& operator=(const TerminatingSignalsHeld&) = delete;

 private:
  sigset_t previous_;
};

/// Registers the one line the terminating signals' handler prints on stderr
/// before the process ends (a resumable command tells how to resume); the
/// handler can only copy bytes, so the line is kept in a fixed buffer (cut at
/// its size); an empty line registers none. Installs the handler if it is
/// not yet.
void set_interruption_notice(const std::string& line);

class AtomicOutput {
 public:
  /// Refuses (OutputExistsError) when `final_path` exists and `overwrite` is
  /// false; InputError when it is a directory, or when its directory is
  /// missing or cannot be written (the temporary file is created here, before
  /// any work, and removed again unless committed).
  AtomicOutput(std::filesystem::path final_path, bool overwrite);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  /// Where to write; unique per process.
  const std::filesystem::path& temporary_path() const { return temporary_; }
  const std::filesystem::path& final_path() const { return final_; }

  /// Writes the temporary file with `body` (write_file) and commits.
  void write_and_commit(const std::function<void(std::ostream&)>& body);

  /// Renames the temporary file onto the final path (atomic on POSIX) and,
  /// with `tidy`, removes the temporaries of this output left by dead
  /// processes (a caller committing many files of one folder tidies it once,
  /// with remove_dead_temporaries); NumericalError naming both paths and the
  /// reason if it cannot. Without `overwrite` the rename never replaces a
  /// file (renameat2 with RENAME_NOREPLACE, or link() where the file system
  /// lacks the flag): a file that appeared at the final path since the claim was
  /// written by another process meanwhile, and is kept; OutputExistsError
  /// (exit code 3) says so, and this output's temporary is removed.
  void commit(bool tidy = true);

  /// Commits every output of one result (a law and its tables, a run folder)
  /// as a set: the terminating signals are held back while the temporaries
  /// are renamed, so Ctrl-C or a time limit arriving in between ends the
  /// process after the last rename rather than leaving new files beside old
  /// ones. When one output cannot be put in place (another process's result
  /// there, a failing rename), those this call put in place without replacing
  /// anything are removed again before the error is thrown, so that the other
  /// process's set stays whole and no part of this one is left; only SIGKILL,
  /// and a failure after a replacing rename (with `overwrite`), can still
  /// split a set. With `tidy`, removes each output's dead temporaries
  /// afterwards.
  static void commit_together(const std::vector<AtomicOutput*>& outputs, bool tidy = true);

  /// A temporary not among those a signal removes (all slots taken).
  static constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);

 private:
  // Removes the final file a commit without `overwrite` created, if it is
  // still the one this output put there (a set that could not be completed).
  void withdraw();

  std::filesystem::path final_;
  std::filesystem::path temporary_;
  bool overwrite_ = false;
  bool committed_ = false;
  // The committed file's identity, so that withdraw() removes only it.
  std::uint64_t device_ = 0, inode_ = 0;
  std::size_t slot_ = kNoSlot;  // among the temporaries a signal removes
};

}  // namespace softglass
