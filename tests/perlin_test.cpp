// The golden noise unit (golden/perlin/noise.hpp): the xor-table hash, the fade table, the
// lerp, the hard cases (lattice points, cell boundaries, negative and very large coordinates,
// the wrap, the accumulator's range) each with its stated expectation, and the error against
// the ideal model within a bound derived from the widths. The definition the two models share
// (noise_definition.hpp: T's rows) on its own, and the ideal's own hash equal to golden's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <set>

#include "perlin/noise.hpp"
#include "perlin/noise_ideal.hpp"

namespace tmu::perlin {
namespace {

constexpr int64_t kOne = int64_t{1} << kCoordFracBits;  // 1.0 as raw SolidCoord

// T's rows on their own: 12-bit rows of a matrix that is invertible over GF(2) (Gaussian
// elimination finds a pivot in every column), so that T permutes the 12-bit values.
TEST(PerlinDefinitionTest, XorRowsFormAnInvertibleMatrix) {
  std::array<uint32_t, kLatticeBits> m = kXorRows;
  for (const uint32_t row : m) EXPECT_LT(row, 1u << kLatticeBits);
  for (int col = 0; col < kLatticeBits; ++col) {
    const auto c = static_cast<size_t>(col);
    const auto pivot =
        std::find_if(m.begin() + col, m.end(), [col](uint32_t row) { return (row >> col) & 1u; });
    ASSERT_NE(pivot, m.end()) << "no pivot in column " << col;
    std::swap(m[c], *pivot);
    for (size_t r = 0; r < m.size(); ++r) {
      if (r != c && ((m[r] >> col) & 1u)) m[r] ^= m[c];
    }
  }
  for (int j = 0; j < kLatticeBits; ++j) EXPECT_EQ(m[static_cast<size_t>(j)], 1u << j);
}

// Two implementations of one definition: the ideal's T (by columns) is golden's (by rows' parity)
// on every 12-bit value, and both ignore the bits above.
TEST(PerlinHashTest, IdealScrambleIsGoldensOnEveryValue) {
  for (uint32_t x = 0; x < (1u << kLatticeBits); ++x) {
    ASSERT_EQ(ideal::scramble(x), xor_table(x)) << x;
    ASSERT_EQ(ideal::scramble(x | (0x5Au << kLatticeBits)), xor_table(x)) << x;
  }
}

// The ideal's lattice value is golden's over 128, on every value of each index with the other
// two drawn at random (3 x 4096 x 64 lattice points), and for indices beyond one period (the
// ideal wraps them itself, golden takes them mod 4096). At a lattice point the ideal noise is
// the lattice value exactly (the weights are sm(0) = 0).
TEST(PerlinHashTest, IdealLatticeValueIsGoldensOverOneTwentyEight) {
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int64_t> any(-(int64_t{1} << 40), int64_t{1} << 40);
  const auto golden = [](int64_t i, int64_t j, int64_t k) {
    const auto m = [](int64_t x) { return static_cast<uint32_t>(x) & 0xFFF; };
    return lattice_value(m(i), m(j), m(k)) / 128.0;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int64_t x = 0; x < (int64_t{1} << kLatticeBits); ++x) {
      for (int n = 0; n < 64; ++n) {
        int64_t p[3] = {any(rng), any(rng), any(rng)};
        p[axis] = n % 2 ? x : x - (n + 1) * 4096;  // in the first period, or below it
        ASSERT_EQ(ideal::lattice_value(p[0], p[1], p[2]), golden(p[0], p[1], p[2]))
            << p[0] << " " << p[1] << " " << p[2];
      }
    }
  }
  for (int n = 0; n < 2000; ++n) {
    const int64_t i = any(rng) % 100000, j = any(rng) % 100000, k = any(rng) % 100000;
    EXPECT_EQ(ideal::noise(double(i), double(j), double(k)), ideal::lattice_value(i, j, k));
  }
}

TEST(PerlinHashTest, XorTableIsAPermutation) {
  std::set<uint32_t> seen;
  for (uint32_t x = 0; x < (1u << kLatticeBits); ++x) {
    const uint32_t y = xor_table(x);
    ASSERT_LT(y, 1u << kLatticeBits);
    seen.insert(y);
  }
  EXPECT_EQ(seen.size(), 1u << kLatticeBits);
}

// Every lattice value is about equally likely over a 32^3 block of lattice points, and the
// hash is far from linear along every axis: the values of four aligned neighbours xor to
// zero in at most 2.5 % of the groups (0.4 % for random values; 50 % along w for a hash
// whose last coordinate passes one linear scramble only).
TEST(PerlinHashTest, LatticeValuesSpreadAndAreNotLinear) {
  std::array<int, 256> count{};
  int64_t sum = 0;
  std::array<int, 3> aligned_zero{};
  int groups = 0;
  for (uint32_t a = 0; a < 32; ++a) {
    for (uint32_t b = 0; b < 32; ++b) {
      for (uint32_t m = 0; m < 32; m += 4) {
        ++groups;
        std::array<int32_t, 3> x4{};
        for (uint32_t k = 0; k < 4; ++k) {
          const int32_t r = lattice_value(a, b, m + k);
          ASSERT_GE(r, -128);
          ASSERT_LE(r, 127);
          ++count[static_cast<size_t>(r + 128)];
          sum += r;
          x4[0] ^= lattice_value(m + k, a, b);
          x4[1] ^= lattice_value(a, m + k, b);
          x4[2] ^= r;
        }
        for (size_t i = 0; i < 3; ++i) aligned_zero[i] += x4[i] == 0;
      }
    }
  }
  EXPECT_NEAR(static_cast<double>(sum) / (32 * 32 * 32), -0.5, 2.0);  // mean of -128..127
  EXPECT_GE(*std::min_element(count.begin(), count.end()), 80);       // 128 expected per value
  EXPECT_LE(*std::max_element(count.begin(), count.end()), 180);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_LE(aligned_zero[i], groups / 40) << "axis " << i;
    std::cout << "axis " << i << ": " << aligned_zero[i] << " of " << groups
              << " aligned groups xor to zero\n";
  }
}

TEST(PerlinFadeTest, TableIsMonotoneSymmetricAndEndsAtZero) {
  for (const NoiseConfig c : {NoiseConfig{}, NoiseConfig{12, 10, 12, 8}, NoiseConfig{4, 3, 4, 0}}) {
    EXPECT_EQ(fade_entry(c, 0), 0u);
    const uint32_t n = 1u << c.fade_index_bits;
    for (uint32_t k = 1; k < n; ++k) {
      EXPECT_GE(fade_entry(c, k), fade_entry(c, k - 1));
      // sm(x) + sm(1 - x) = 1: the rounded pair sums to 2^B within the two roundings.
      const int64_t pair = int64_t{fade_entry(c, k)} + fade_entry(c, n - k);
      EXPECT_LE(std::abs(pair - (int64_t{1} << c.fade_bits)), 1) << k;
    }
  }
}

TEST(PerlinLerpTest, StaysBetweenItsEndsAndRoundsHalfUp) {
  constexpr int kB = 8;
  for (int32_t a : {-2048, -5, 0, 7, 2047}) {
    for (int32_t b : {-2048, -6, 0, 9, 2047}) {
      EXPECT_EQ(lerp(a, b, 0, kB), a);
      EXPECT_EQ(lerp(a, b, 1u << kB, kB), b);
      for (uint32_t c = 0; c <= (1u << kB); c += 17) {
        const int32_t f = lerp(a, b, c, kB);
        EXPECT_GE(f, std::min(a, b));
        EXPECT_LE(f, std::max(a, b));
        EXPECT_EQ(f, a + static_cast<int32_t>(std::floor(double(c) * (b - a) / 256.0 + 0.5)));
      }
    }
  }
}

// At a lattice point every fraction is 0, every weight 0: P is the lattice value, exactly,
// for negative indices too (floor, then mod 4096).
TEST(PerlinNoiseTest, LatticePointsGiveTheirValueExactly) {
  const NoiseConfig c;
  for (int64_t x : {-4097, -2048, -1, 0, 1, 5, 2047}) {
    for (int64_t y : {-3, 0, 11}) {
      for (int64_t z : {-1, 0, 1000}) {
        const auto m = [](int64_t i) { return static_cast<uint32_t>(i) & 0xFFF; };
        EXPECT_EQ(noise(c, x * kOne, y * kOne, z * kOne),
                  lattice_value(m(x), m(y), m(z)) * noise_one(c) / 128)
            << x << " " << y << " " << z;
      }
    }
  }
}

// Continuity across a cell boundary: one coordinate LSB below a lattice plane and on it, P
// differs by at most the fade's slope there (zero: sm'(1) = 0) plus roundings: a few LSB.
TEST(PerlinNoiseTest, ContinuousAcrossCellBoundaries) {
  const NoiseConfig c;
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int64_t> any(-2048 * kOne, 2047 * kOne);
  const int64_t step = int64_t{1} << (kCoordFracBits - c.frac_bits);  // one used LSB
  int worst = 0;
  for (int n = 0; n < 20000; ++n) {
    int64_t p[3] = {any(rng), any(rng), any(rng)};
    const int axis = n % 3;
    p[axis] = (p[axis] >> kCoordFracBits) << kCoordFracBits;  // onto a lattice plane
    const int32_t on = noise(c, p[0], p[1], p[2]);
    p[axis] -= step;
    const int32_t below = noise(c, p[0], p[1], p[2]);
    worst = std::max(worst, std::abs(on - below));
  }
  std::cout << "largest jump across a cell boundary: " << worst << " LSB of 2^-"
            << 7 + c.lerp_extra_bits << "\n";
  // sm(1 - 2^-S) rounds to 2^B for S = B = 8, so the weight does not move: only the other
  // axes' rounding paths differ (none: same lerps). Allow 2 LSB.
  EXPECT_LE(worst, 2);
}

// The noise repeats every 4096 units on each axis, and so do the fractal sums (octave i
// repeats every 4096 / 2^i); coordinates far beyond SolidCoord's range wrap the same way,
// without overflow.
TEST(PerlinNoiseTest, WrapsEvery4096UnitsEvenFarOut) {
  const NoiseConfig c;
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int64_t> any(-2048 * kOne, 2047 * kOne);
  const int64_t period = int64_t{4096} * kOne;
  for (int n = 0; n < 2000; ++n) {
    const int64_t u = any(rng), v = any(rng), w = any(rng);
    const int32_t p = noise(c, u, v, w);
    const int64_t k = (n % 7) - 3;
    EXPECT_EQ(noise(c, u + k * period, v, w - k * period), p);
    EXPECT_EQ(noise(c, u + (int64_t{1} << 30) * period, v, w), p);
    const FractalSums s = fractal_sums(c, u, v, w), t = fractal_sums(c, u - period, v + period, w);
    EXPECT_EQ(s.fractal_sum, t.fractal_sum);
    EXPECT_EQ(s.turbulence, t.turbulence);
  }
}

// The accumulator: |P| <= 1 per octave, so |sums| <= 15/8 of 1.0, inside SQ2.(10 + X); the
// turbulence is never negative; the fractal sum is the signed sum of the same terms.
TEST(PerlinNoiseTest, SumsStayInTheAccumulatorsRange) {
  for (const NoiseConfig c : {NoiseConfig{}, NoiseConfig{12, 12, 12, 8}}) {
    const int32_t limit = sum_one(c) * 15 / 8;
    EXPECT_LT(limit, int32_t{1} << (11 + c.lerp_extra_bits));  // SQ2.(10 + X) holds +-2
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int64_t> any(-2048 * kOne, 2047 * kOne);
    for (int n = 0; n < 20000; ++n) {
      const FractalSums s = fractal_sums(c, any(rng), any(rng), any(rng));
      EXPECT_GE(s.turbulence, 0);
      EXPECT_LE(s.turbulence, limit);
      EXPECT_LE(std::abs(s.fractal_sum), s.turbulence);
    }
  }
}

TEST(PerlinNoiseTest, ConfigOutOfRangeIsNamed) {
  EXPECT_THROW(check(NoiseConfig{0, 1, 8, 4}), std::invalid_argument);
  EXPECT_THROW(check(NoiseConfig{8, 9, 8, 4}), std::invalid_argument);
  EXPECT_THROW(check(NoiseConfig{8, 8, 13, 4}), std::invalid_argument);
  EXPECT_THROW(check(NoiseConfig{8, 8, 8, 9}), std::invalid_argument);
  try {
    check(NoiseConfig{8, 9, 8, 4});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("fade_index_bits"), std::string::npos);
  }
  EXPECT_NO_THROW(check(NoiseConfig{}));
}

// Against the ideal (exact fraction, fade and lerps). Per lerp level the weight is off by at
// most 1.5 2^-S (the fraction truncated to S bits; sm' <= 1.5) plus 2^-(B+1) (the table's
// rounding), which moves the result by that times |b - a| <= 2, plus half an LSB of rounding
// 2^-(8+X); three levels: bound = 3 (2 (1.5 2^-S + 2^-(B+1)) + 2^-(8+X)). The sums add the
// octaves' errors with weights 1 + 1/2 + 1/4 + 1/8 (|x| is 1-Lipschitz for the turbulence).
TEST(PerlinNoiseTest, GoldenWithinTheBoundOfTheIdeal) {
  for (const NoiseConfig c : {NoiseConfig{}, NoiseConfig{12, 10, 12, 8}, NoiseConfig{6, 6, 6, 2}}) {
    const double bound =
        3 * (2 * (1.5 * std::ldexp(1, -c.fade_index_bits) + std::ldexp(1, -(c.fade_bits + 1))) +
             std::ldexp(1, -(8 + c.lerp_extra_bits)));
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int64_t> any(-2048 * kOne, 2047 * kOne);
    double worst = 0, worst_sum = 0, mean = 0;
    constexpr int kSamples = 50000;
    for (int n = 0; n < kSamples; ++n) {
      const int64_t u = any(rng), v = any(rng), w = any(rng);
      const double du = double(u) / kOne, dv = double(v) / kOne, dw = double(w) / kOne;
      const double e =
          std::abs(double(noise(c, u, v, w)) / noise_one(c) - ideal::noise(du, dv, dw));
      worst = std::max(worst, e);
      mean += e / kSamples;
      const FractalSums s = fractal_sums(c, u, v, w);
      const ideal::FractalSums x = ideal::fractal_sums(du, dv, dw);
      worst_sum = std::max({worst_sum, std::abs(double(s.fractal_sum) / sum_one(c) - x.fractal_sum),
                            std::abs(double(s.turbulence) / sum_one(c) - x.turbulence)});
    }
    std::cout << "F,S,B,X = " << c.frac_bits << "," << c.fade_index_bits << "," << c.fade_bits
              << "," << c.lerp_extra_bits << ": |P - ideal| max " << worst << ", mean " << mean
              << ", sums max " << worst_sum << " (bound " << bound << ", sums " << 1.875 * bound
              << ")\n";
    EXPECT_LE(worst, bound);
    EXPECT_LE(worst_sum, 1.875 * bound);
  }
}

}  // namespace
}  // namespace tmu::perlin
