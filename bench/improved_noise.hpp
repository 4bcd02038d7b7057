// A plain double-precision implementation of Perlin's improved noise (SIGGRAPH 2002: the
// quintic fade 6t^5 - 15t^4 + 10t^3, twelve gradient directions picked by a hashed
// permutation, trilinear blend), written here as the software peer of the golden noise unit.
// The permutation is a fixed-seed shuffle of 0..255 (Perlin's published table is one such).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>

namespace tmu::bench {

class ImprovedNoise {
 public:
  ImprovedNoise() {
    std::array<int, 256> p{};
    std::iota(p.begin(), p.end(), 0);
    std::shuffle(p.begin(), p.end(), std::mt19937(2002));
    for (int i = 0; i < 512; ++i) perm_[static_cast<size_t>(i)] = p[static_cast<size_t>(i & 255)];
  }

  double noise(double x, double y, double z) const {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int xi = static_cast<int>(fx) & 255, yi = static_cast<int>(fy) & 255,
              zi = static_cast<int>(fz) & 255;
    x -= fx;
    y -= fy;
    z -= fz;
    const double u = fade(x), v = fade(y), w = fade(z);
    const int a = perm(xi) + yi, aa = perm(a) + zi, ab = perm(a + 1) + zi;
    const int b = perm(xi + 1) + yi, ba = perm(b) + zi, bb = perm(b + 1) + zi;
    return lerp(
        w,
        lerp(v, lerp(u, grad(perm(aa), x, y, z), grad(perm(ba), x - 1, y, z)),
             lerp(u, grad(perm(ab), x, y - 1, z), grad(perm(bb), x - 1, y - 1, z))),
        lerp(
            v, lerp(u, grad(perm(aa + 1), x, y, z - 1), grad(perm(ba + 1), x - 1, y, z - 1)),
            lerp(u, grad(perm(ab + 1), x, y - 1, z - 1), grad(perm(bb + 1), x - 1, y - 1, z - 1))));
  }

  // Four octaves of abs(noise), amplitude halving: the turbulence the materials use.
  double turbulence(double x, double y, double z) const {
    double sum = 0, scale = 1;
    for (int i = 0; i < 4; ++i, scale *= 2)
      sum += std::abs(noise(x * scale, y * scale, z * scale)) / scale;
    return sum;
  }

 private:
  static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
  static double lerp(double t, double a, double b) { return a + t * (b - a); }
  static double grad(int hash, double x, double y, double z) {
    const int h = hash & 15;
    const double u = h < 8 ? x : y, v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
  }
  int perm(int i) const { return perm_[static_cast<size_t>(i)]; }

  std::array<int, 512> perm_{};
};

}  // namespace tmu::bench
