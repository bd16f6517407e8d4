#include "common/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace softglass {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  if (seconds < 60) return fmt::format("{:.1f}s", seconds);
  const auto s = static_cast<long>(seconds);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

double time_left(double elapsed, double done, double total, double carried) {
  const double timed = done - carried;
  return timed > 0 ? elapsed * std::max(total - done, 0.0) / timed : NAN;
}

Progress::Progress(std::string label, double total, bool quiet)
    : label_(std::move(label)),
      total_(total),
      quiet_(quiet),
      terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  finish();
}

void Progress::update(double done, const std::string& note) {
  if (quiet_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  const double fraction = total_ > 0 ? std::clamp(done / total_, 0.0, 1.0) : 0.0;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = time_left(elapsed, done, total_, carried_);
  const std::string text =
      fmt::format("{} {:5.1f}%  {}  left {}{}{}", label_, 100.0 * fraction,
                  format_duration(elapsed), format_duration(left), note.empty() ? "" : "  ", note);
  if (terminal_) {
    if (now - last_draw_ < std::chrono::milliseconds(200) && fraction < 1.0) return;
    constexpr int kWidth = 24;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r[%s%s] %s\033[K", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), text.c_str());
    std::fflush(stderr);
    last_draw_ = now;
  } else {
    const int decile = static_cast<int>(fraction * 10);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s\n", text.c_str());
  }
}

void Progress::finish() {
  if (quiet_ || finished_) return;
  finished_ = true;
  if (terminal_) std::fprintf(stderr, "\n");
}

}  // namespace softglass
