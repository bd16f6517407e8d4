// A progress line with the time left, on stderr.
//
// On a terminal it redraws one line at most five times a second; when stderr is
// a file or a pipe (batch jobs, CI logs) it prints a plain line every 10 % so
// logs stay readable. Quiet mode prints nothing.
#pragma once

#include <chrono>
#include <string>

namespace softglass {

class Progress {
 public:
  /// `label` names the task; `total` is the amount of work (e.g. strain units).
  Progress(std::string label, double total, bool quiet);
  ~Progress();

  /// Reports `done` out of the total, with an optional note (e.g. current error).
  void update(double done, const std::string& note = "");
  /// Declares `amount` of the work as done before this process started (a task
  /// resumed from a checkpoint): it counts as done but not towards the rate
  /// that the time left is extrapolated from.
  void carry(double amount) { carried_ += amount; }
  /// Ends the line (also done by the destructor).
  void finish();

 private:
  std::string label_;
  double total_, carried_ = 0.0;
  bool quiet_, terminal_, finished_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

/// Seconds left for `total` work when `done` of it is done after `elapsed`
/// seconds, `carried` of that done before the clock started (NaN while
/// nothing has been done since).
double time_left(double elapsed, double done, double total, double carried = 0.0);

/// "1h02m", "3m05s", "12.4s".
std::string format_duration(double seconds);

}  // namespace softglass
