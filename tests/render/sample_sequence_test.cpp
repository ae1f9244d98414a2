// The stratified sampler against the definition of what it promises: the
// first 2^m samples of a pixel's 2D dimension pair form a (0, m, 2)-net in
// base 2 (Sobol 1967; kept by Owen scrambling, Owen 1995): every
// elementary box of area 2^-m, 2^k by 2^(m-k) cells for any k, holds
// exactly one point. 1D dimensions are stratified into 2^m equal cells.
// Different pixels, and different dimension pairs, are scrambled apart.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "random_stream.h"

namespace dp::render {
namespace {

TEST(render_sample_sequence, EachDimensionPairIsAZeroNet) {
  constexpr int m = 8, n = 1 << m;
  for (int dimension = 0; dimension < 4; ++dimension) {
    std::vector<Sample2> points;
    std::vector<float> singles;
    for (int i = 0; i < n; ++i) {
      RandomStream r(3, 17, 5, static_cast<std::uint32_t>(i), SampleSequence::Sobol);
      for (int d = 0; d < dimension; ++d) r.uniform2();
      singles.push_back(r.uniform());
      points.push_back(r.uniform2());
    }
    for (int k = 0; k <= m; ++k) {
      std::vector<int> count(n, 0);
      for (const Sample2& p : points)
        ++count[static_cast<std::size_t>(static_cast<int>(p.u1 * (1 << k)) * (1 << (m - k)) + static_cast<int>(p.u2 * (1 << (m - k))))];
      for (int c : count) ASSERT_EQ(c, 1) << "dimension pair " << dimension << ", boxes " << (1 << k) << " x " << (1 << (m - k));
    }
    std::set<int> cells;
    for (float v : singles) cells.insert(static_cast<int>(v * n));
    EXPECT_EQ(cells.size(), static_cast<std::size_t>(n)) << "1D dimension after pair " << dimension;
  }
}

TEST(render_sample_sequence, PixelsAndDimensionsAreScrambledApart) {
  RandomStream a(3, 0, 0, 0, SampleSequence::Sobol), b(3, 1, 0, 0, SampleSequence::Sobol);
  const Sample2 a1 = a.uniform2(), a2 = a.uniform2(), b1 = b.uniform2();
  EXPECT_NE(a1.u1, b1.u1);
  EXPECT_NE(a1.u1, a2.u1);
}

}  // namespace
}  // namespace dp::render
