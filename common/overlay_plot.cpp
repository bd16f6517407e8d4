#include "common/overlay_plot.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace softglass {

namespace {

// A gnuplot string: double quotes, in which \\, \" and \n are escapes (titles
// may hold file names and line breaks).
std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) {
    if (c == '\n')
      q += "\\n";
    else if (c == '"' || c == '\\')
      q += std::string("\\") + c;
    else
      q += c;
  }
  return q + "\"";
}

// Inline data block: x, measured, predicted, relative error of the prediction.
std::string data_block(const std::string& name, const OverlaySeries& s) {
  std::string block = fmt::format("${} << EOD\n", name);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const double error = s.predicted[i] / s.measured[i] - 1.0;
    block += fmt::format("{:.10g} {:.10g} {:.10g} {:.10g}\n", s.x[i], s.measured[i], s.predicted[i],
                         std::isfinite(error) ? 100.0 * error : NAN);
  }
  return block + "EOD\n";
}

std::string script(const OverlayPlot& plot, const std::filesystem::path& output) {
  std::ostringstream g;
  const std::size_t n = plot.panels.size();
  g << fmt::format("set terminal pngcairo size {},900 enhanced font 'DejaVu Sans,11'\n", 560 * n);
  g << "set output " << quoted(output.string()) << "\n";
  for (std::size_t p = 0; p < n; ++p)
    g << data_block(fmt::format("d{}", p), plot.panels[p]);
  g << fmt::format("set multiplot layout 2,{} title {} noenhanced font ',10'\n", n,
                   quoted(plot.title));
  g << "set logscale x\nset grid\nset key top left\nset format x '10^{%L}'\n";
  // Upper row: the curves on log-log axes; lower row: the relative error.
  for (std::size_t p = 0; p < n; ++p) {
    g << "set logscale y\nset format y '10^{%L}'\n";
    g << "set xlabel " << quoted(plot.panels[p].abscissa) << "\nset ylabel "
      << quoted(plot.panels[p].quantity) << "\n";
    g << fmt::format(
        "plot $d{0} using 1:2 with points pt 7 ps 1.1 lc rgb '#1f77b4' title 'measured', "
        "$d{0} using 1:3 with linespoints pt 6 lw 2 lc rgb '#d62728' title 'predicted'\n",
        p);
  }
  for (std::size_t p = 0; p < n; ++p) {
    g << "unset logscale y\nset format y '%g'\n";
    g << "set xlabel " << quoted(plot.panels[p].abscissa) << "\n";
    g << "set ylabel " << quoted("predicted / measured - 1 [%]") << "\n";
    g << fmt::format(
        "plot $d{0} using 1:4 with linespoints pt 7 lc rgb '#d62728' notitle, 0 with lines lc "
        "rgb 'black' notitle\n",
        p);
  }
  g << "unset multiplot\n";
  return g.str();
}

// gnuplot exits with success when the disk fills while it writes: the file
// must begin with PNG's signature and end with its IEND chunk.
bool complete_png(const std::filesystem::path& file) {
  static constexpr char kSignature[] = "\x89PNG\r\n\x1a\n";
  static constexpr char kEnd[] = "IEND\xae\x42\x60\x82";
  std::ifstream in(file, std::ios::binary);
  char head[8] = {}, tail[8] = {};
  in.read(head, 8);
  in.seekg(-8, std::ios::end);
  in.read(tail, 8);
  return in && std::equal(head, head + 8, kSignature) && std::equal(tail, tail + 8, kEnd);
}

// The errno of writing a block of data into `file` (truncated first and
// afterwards), 0 when it can be written. The block is larger than a plot,
// so that a disk with room for a part of one fails it too.
int probe_write(const std::filesystem::path& file) {
  constexpr std::size_t kBlock = 1 << 20;
  const int fd = ::open(file.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) return errno;
  const std::string block(kBlock, '\0');
  int failure = 0;
  for (std::size_t done = 0; done < kBlock && failure == 0;) {
    const ssize_t n = ::write(fd, block.data() + done, kBlock - done);
    if (n > 0)
      done += static_cast<std::size_t>(n);
    else if (n < 0 && errno != EINTR)
      failure = errno;
  }
  if (failure == 0 && ::fsync(fd) != 0) failure = errno;
  if (::ftruncate(fd, 0) != 0 && failure == 0) failure = errno;
  ::close(fd);
  return failure;
}

// SIGPIPE ignored for its lifetime: gnuplot missing, the shell exits before
// reading the script, and writing the rest of it must fail (EPIPE) rather
// than end the process.
class BrokenPipeIgnored {
 public:
  BrokenPipeIgnored() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, &previous_);
  }
  ~BrokenPipeIgnored() { ::sigaction(SIGPIPE, &previous_, nullptr); }
  BrokenPipeIgnored(const BrokenPipeIgnored&) = delete;
  BrokenPipeIgnored& operator=(const BrokenPipeIgnored&) = delete;

 private:
  struct sigaction previous_ {};
};

}  // namespace

PlotOutcome plot_outcome(int shell_status, const std::filesystem::path& file) {
  using Kind = PlotOutcome::Kind;
  const bool exited = shell_status != -1 && WIFEXITED(shell_status);
  if (exited && WEXITSTATUS(shell_status) == 127)
    return {Kind::no_gnuplot, "gnuplot is not installed"};
  const bool succeeded = exited && WEXITSTATUS(shell_status) == 0;
  if (succeeded && complete_png(file)) return {Kind::written, ""};
  if (const int failure = probe_write(file); failure != 0)
    return {Kind::write_failed, std::strerror(failure)};
  if (succeeded)
    return {Kind::write_failed, "the PNG is incomplete although gnuplot reported success"};
  if (shell_status == -1) return {Kind::gnuplot_failed, "gnuplot could not be started"};
  return {Kind::gnuplot_failed,
          WIFSIGNALED(shell_status)
              ? fmt::format("gnuplot was ended by signal {}", WTERMSIG(shell_status))
              : fmt::format("gnuplot failed (exit status {})", WEXITSTATUS(shell_status))};
}

PlotOutcome write_overlay_png(const OverlayPlot& plot, const std::filesystem::path& file) {
  const BrokenPipeIgnored ignored;
  FILE* gnuplot = popen("gnuplot 2>/dev/null", "w");
  if (!gnuplot)
    return {PlotOutcome::Kind::gnuplot_failed,
            fmt::format("gnuplot could not be started: {}", std::strerror(errno))};
  const std::string text = script(plot, file);
  std::fwrite(text.data(), 1, text.size(), gnuplot);  // a short write shows in the status
  return plot_outcome(pclose(gnuplot), file);
}

}  // namespace softglass
