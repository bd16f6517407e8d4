// Determinism: with one thread, two identical sheared runs from the same packing
// give bit-identical time series, counters and final configurations.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

#include "micro_test_support.h"

namespace softglass::micro {
namespace {

// Bitwise equality (EXPECT_EQ on doubles would also accept −0 == +0).
template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

TEST(Determinism, IdenticalRunsGiveBitIdenticalTimeSeries) {
  omp_set_num_threads(1);
  const PackingSpec spec = testing::small_packing_spec(4);
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(spec, law);

  const auto a = testing::shear_briefly(packing, law, spec.skin, 1.0, 0.5);
  const auto b = testing::shear_briefly(packing, law, spec.skin, 1.0, 0.5);
  const TimeSeries& s = a.result.series;
  const TimeSeries& t = b.result.series;
  ASSERT_EQ(s.size(), t.size());
  ASSERT_GT(s.size(), 100u);
  for (std::size_t k = 0; k < s.size(); ++k) {
    ASSERT_TRUE(same_bits(s.strain[k], t.strain[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(s.elastic[k], t.elastic[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(s.viscous[k], t.viscous[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(s.coordination[k], t.coordination[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(s.step[k], t.step[k])) << "sample " << k;
  }
  EXPECT_EQ(a.result.counters.steps, b.result.counters.steps);
  EXPECT_EQ(a.result.counters.rejected_steps, b.result.counters.rejected_steps);
  EXPECT_EQ(a.result.counters.newton_iterations, b.result.counters.newton_iterations);
  EXPECT_EQ(a.result.counters.cg_iterations, b.result.counters.cg_iterations);
  for (std::size_t i = 0; i < a.final_particles.size(); ++i) {
    ASSERT_TRUE(same_bits(a.final_particles.position[i], b.final_particles.position[i])) << i;
  }
  // The runs did something: the stress changed along the way.
  EXPECT_NE(s.elastic.front()(0, 1), s.elastic.back()(0, 1));
}

}  // namespace
}  // namespace softglass::micro
