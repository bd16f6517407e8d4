#include "micro/numerics/pair_block_product.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SOFTGLASS_PAIR_PRODUCT_AVX2 1
#endif

namespace softglass::micro {

// The pairs come particle by particle (runs of equal i): particle i's share is
// summed in registers over its run and stored once. Added to out[i] pair by
// pair, each addition waited for the store of the one before
// (store-to-load forwarding; bench/results/aqs_profile-2026-11-27.md).
// The loops run on raw pointers held
// in locals: Eigen stores its packets through may-alias types, so with the
// vectors themselves the compiler reloaded every data pointer after each store.
void pair_block_product_portable(const PairBlocks& pairs, std::span<const double> diagonal,
                                 double shift, const std::vector<Vec3>& in,
                                 std::vector<Vec3>& out) {
  const std::size_t n = in.size();
  const Vec3* x = in.data();
  Vec3* y = out.data();
  for (std::size_t a = 0; a < n; ++a)
    y[a] = ((diagonal.empty() ? 0.0 : diagonal[a]) + shift) * x[a];
  const Eigen::Matrix3d* block = pairs.block.data();
  const std::uint32_t* pair_i = pairs.i.data();
  const std::uint32_t* pair_j = pairs.j.data();
  const std::size_t m = pairs.block.size();
  std::size_t k = 0;
  while (k < m) {
    const std::uint32_t i = pair_i[k];
    const Vec3 xi = x[i];
    Vec3 yi = Vec3::Zero();
    for (; k < m && pair_i[k] == i; ++k) {
      const Vec3 f = block[k] * (xi - x[pair_j[k]]);
      yi += f;
      y[pair_j[k]] -= f;
    }
    y[i] += yi;
  }
}

#ifdef SOFTGLASS_PAIR_PRODUCT_AVX2
namespace {

__attribute__((target("avx2,fma"))) void pair_block_product_avx2(
    const PairBlocks& pairs, std::span<const double> diagonal, double shift,
    const std::vector<Vec3>& in, std::vector<Vec3>& out, std::vector<double>& padded) {
  const std::size_t n = in.size();
  if (n == 0) return;
  padded.resize(4 * n);
  const __m256i first_three = _mm256_setr_epi64x(-1, -1, -1, 0);
  const double* x = in.front().data();  // 3 per particle
  double* y = padded.data();            // 4 per particle, the last 0
  for (std::size_t a = 0; a < n; ++a) {
    const double s = (diagonal.empty() ? 0.0 : diagonal[a]) + shift;
    _mm256_storeu_pd(y + 4 * a,
                     _mm256_mul_pd(_mm256_set1_pd(s), _mm256_maskload_pd(x + 3 * a, first_three)));
  }
  // 9 per pair, column by column (none: the loop below does not run)
  const double* block = pairs.block.empty() ? nullptr : pairs.block.front().data();
  const std::uint32_t* pair_i = pairs.i.data();
  const std::uint32_t* pair_j = pairs.j.data();
  const std::size_t m = pairs.block.size();
  std::size_t k = 0;
  while (k < m) {
    const std::uint32_t i = pair_i[k];
    const __m256d xi = _mm256_maskload_pd(x + 3 * i, first_three);
    __m256d yi = _mm256_setzero_pd();
    for (; k < m && pair_i[k] == i; ++k) {
      const double* b = block + 9 * k;
      const __m256d d = _mm256_sub_pd(xi, _mm256_maskload_pd(x + 3 * pair_j[k], first_three));
      // f = B (x_i − x_j), column by column: b₀ dx + b₁ dy + b₂ dz.
      const __m256d b0 = _mm256_maskload_pd(b, first_three);
      const __m256d b1 = _mm256_maskload_pd(b + 3, first_three);
      const __m256d b2 = _mm256_maskload_pd(b + 6, first_three);
      __m256d f = _mm256_mul_pd(b0, _mm256_permute4x64_pd(d, 0x00));
      f = _mm256_fmadd_pd(b1, _mm256_permute4x64_pd(d, 0x55), f);
      f = _mm256_fmadd_pd(b2, _mm256_permute4x64_pd(d, 0xAA), f);
      yi = _mm256_add_pd(yi, f);
      double* yj = y + 4 * pair_j[k];
      _mm256_storeu_pd(yj, _mm256_sub_pd(_mm256_loadu_pd(yj), f));
    }
    double* own = y + 4 * i;
    _mm256_storeu_pd(own, _mm256_add_pd(_mm256_loadu_pd(own), yi));
  }
  Vec3* result = out.data();
  for (std::size_t a = 0; a < n; ++a) result[a] = Vec3(y[4 * a], y[4 * a + 1], y[4 * a + 2]);
}

}  // namespace
#endif

bool pair_block_product_vectorised() {
#ifdef SOFTGLASS_PAIR_PRODUCT_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return avx2;
#else
  return false;
#endif
}

void pair_block_product(const PairBlocks& pairs, std::span<const double> diagonal, double shift,
                        const std::vector<Vec3>& in, std::vector<Vec3>& out,
                        std::vector<double>& padded) {
#ifdef SOFTGLASS_PAIR_PRODUCT_AVX2
  if (pair_block_product_vectorised()) {
    pair_block_product_avx2(pairs, diagonal, shift, in, out, padded);
    return;
  }
#endif
  (void)padded;
  pair_block_product_portable(pairs, diagonal, shift, in, out);
}

}  // namespace softglass::micro
