// memory_streams: the memory bandwidth one core gets when it reads k arrays at
// once and writes one, the roof against which bench/scaling.sh's large sizes
// are read (docs/validation.md §2).
//
// A step of the particle engine at N ≥ 10⁵ streams a dozen or more arrays
// from memory together — positions, accumulators, list rows, pair constants,
// velocities, the snapshot — and a core's bandwidth falls with the number of
// concurrent streams (each needs its own prefetch stream and DRAM pages), so a
// single-stream copy overstates what the engine can get. Here out[i] = Σ_q
// a_q[i] in blocks of 64 doubles (vectorised sums, so arithmetic never
// bounds it), the k inputs together `--megabytes` long, far beyond any cache.
// Output: `stream_bandwidth_GBps <k> <GB/s>` per k, the best of `--repeat`
// passes (reads and the write counted; the write's read-for-ownership not).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"memory_streams: one core's bandwidth with k concurrent read streams"};
  std::vector<int> streams{1, 2, 6, 12, 24};
  double megabytes = 512;
  int repeat = 3;
  app.add_option("--streams", streams, "numbers of concurrent read streams")
      ->check(CLI::Range(1, 64));
  app.add_option("--megabytes", megabytes, "size of all the inputs together")
      ->check(CLI::Range(64.0, 8192.0));
  app.add_option("--repeat", repeat, "passes per k (the best is reported)")
      ->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);

  constexpr std::size_t kBlock = 64;
  for (const int k : streams) {
    // Whole blocks only, so the block loop needs no tail.
    const std::size_t n = static_cast<std::size_t>(megabytes * 1e6 / 8.0 / k) / kBlock * kBlock;
    std::vector<std::vector<double>> in(k, std::vector<double>(n, 1.0));
    std::vector<double> out(n, 0.0);
    double best = 0.0;
    for (int pass = 0; pass < repeat; ++pass) {
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t b = 0; b < n; b += kBlock) {
        double* o = out.data() + b;
        std::fill(o, o + kBlock, 0.0);
        for (int q = 0; q < k; ++q) {
          const double* a = in[q].data() + b;
          for (std::size_t j = 0; j < kBlock; ++j) o[j] += a[j];
        }
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      best = std::max(best, static_cast<double>((k + 1) * n * sizeof(double)) / seconds / 1e9);
    }
    // The checksum keeps the sums from being optimised away.
    if (out[n / 2] != static_cast<double>(k)) {
      fmt::print(stderr, "memory_streams: wrong sum {} for {} streams\n", out[n / 2], k);
      return 1;
    }
    fmt::print("stream_bandwidth_GBps {} {:.1f}\n", k, best);
  }
  return 0;
}
