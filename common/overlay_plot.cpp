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

constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};

// Inline data block of a curve: x, y.
std::string data_block(const std::string& name, const PlotCurve& c) {
  std::string block = fmt::format("${} << EOD\n", name);
  for (std::size_t i = 0; i < c.x.size(); ++i)
    block += fmt::format("{:.10g} {:.10g}\n", c.x[i], c.y[i]);
  return block + "EOD\n";
}

// The plot command of `curves`, whose data blocks are $<prefix><k>.
std::string plot_command(const std::vector<PlotCurve>& curves, const std::string& prefix) {
  std::string command = "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const PlotCurve& c = curves[k];
    const std::string colour = kPalette[static_cast<std::size_t>(c.colour) % std::size(kPalette)];
    command += fmt::format("{}${}{} using 1:2 with {} lc rgb '{}' title {}", k ? ", " : "", prefix,
                           k, c.line ? "linespoints pt 6 ps 0.6 lw 2" : "points pt 7 ps 1.0",
                           colour, quoted(c.title));
  }
  return command;
}

std::string script(const OverlayPlot& plot, const std::filesystem::path& output) {
  std::ostringstream g;
  const std::size_t n = plot.panels.size();
  g << fmt::format("set terminal pngcairo size {},900 enhanced font 'DejaVu Sans,11'\n", 560 * n);
  g << "set output " << quoted(output.string()) << "\n";
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t k = 0; k < plot.panels[p].curves.size(); ++k)
      g << data_block(fmt::format("c{}_{}", p, k), plot.panels[p].curves[k]);
    for (std::size_t k = 0; k < plot.panels[p].errors.size(); ++k)
      g << data_block(fmt::format("e{}_{}", p, k), plot.panels[p].errors[k]);
  }
  g << fmt::format("set multiplot layout 2,{} title {} noenhanced font ',10'\n", n,
                   quoted(plot.title));
  g << "set logscale x\nset grid\nset key top left\nset format x '10^{%L}'\n";
  // Upper row: the curves on log-log axes; lower row: the relative errors.
  for (std::size_t p = 0; p < n; ++p) {
    g << "set logscale y\nset format y '10^{%L}'\n";
    g << "set xlabel " << quoted(plot.panels[p].abscissa) << "\nset ylabel "
      << quoted(plot.panels[p].quantity) << "\n";
    g << plot_command(plot.panels[p].curves, fmt::format("c{}_", p)) << "\n";
  }
  for (std::size_t p = 0; p < n; ++p) {
    g << "unset logscale y\nset format y '%g'\n";
    g << "set xlabel " << quoted(plot.panels[p].abscissa) << "\n";
    g << "set ylabel " << quoted("predicted / measured - 1 [%]") << "\n";
    g << plot_command(plot.panels[p].errors, fmt::format("e{}_", p))
      << ", 0 with lines lc rgb 'black' notitle\n";
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

PlotCurve relative_errors(std::string title, const std::vector<double>& x,
                          const std::vector<double>& measured, const std::vector<double>& predicted,
                          int colour) {
  PlotCurve c{.title = std::move(title), .x = {}, .y = {}, .line = true, .colour = colour};
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double error = predicted[i] / measured[i] - 1.0;
    if (!std::isfinite(error)) continue;  // a measured zero: no relative error
    c.x.push_back(x[i]);
    c.y.push_back(100.0 * error);
  }
  return c;
}

OverlayPanel compared_panel(std::string quantity, std::string abscissa,
                            const std::vector<double>& x, const std::vector<double>& measured,
                            const std::vector<double>& predicted) {
  return {.quantity = std::move(quantity),
          .abscissa = std::move(abscissa),
          .curves = {{"measured", x, measured, false, 0}, {"predicted", x, predicted, true, 1}},
          .errors = {relative_errors("", x, measured, predicted, 1)}};
}

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
