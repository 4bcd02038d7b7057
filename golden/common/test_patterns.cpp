#include "common/test_patterns.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace tmu::patterns {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

using Colour = std::array<double, 3>;  // linear mix space, 0..255 per channel

// Random numbers taken directly from the engine, whose sequence the standard specifies.
class Random {
 public:
  explicit Random(uint32_t seed) : engine_(seed) {}
  double unit() { return static_cast<double>(engine_()) / 4294967296.0; }  // [0, 1)
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  uint8_t byte() { return static_cast<uint8_t>(engine_() >> 24); }

 private:
  std::mt19937 engine_;
};

void check_size(int width, int height) {
  if (width < 1 || height < 1) throw std::invalid_argument("test pattern: size must be >= 1x1");
}

uint8_t to_byte(double v) {
  return static_cast<uint8_t>(std::floor(std::clamp(v, 0.0, 255.0) + 0.5));
}
Rgb8 to_rgb(const Colour& c) { return {to_byte(c[0]), to_byte(c[1]), to_byte(c[2])}; }

Colour mix(const Colour& x, const Colour& y, double t) {
  return {x[0] + (y[0] - x[0]) * t, x[1] + (y[1] - x[1]) * t, x[2] + (y[2] - x[2]) * t};
}

// Scales i in [0, n) to 0..255 with rounding; a single row/column is 0.
uint8_t ramp(int i, int n) {
  if (n <= 1) return 0;
  return static_cast<uint8_t>((255 * i + (n - 1) / 2) / (n - 1));
}

// A plane wave: amplitude * sin(2 pi * cycles * (u cos a + v sin a) + phase).
struct Wave {
  double amplitude, cycles, angle, phase;
  double at(double u, double v) const {
    return amplitude *
           std::sin(kTwoPi * cycles * (u * std::cos(angle) + v * std::sin(angle)) + phase);
  }
};

Wave random_wave(Random& rng, double min_amplitude, double max_amplitude, double max_cycles) {
  return {rng.range(min_amplitude, max_amplitude), rng.range(0.5, max_cycles),
          rng.range(0.0, kTwoPi), rng.range(0.0, kTwoPi)};
}

struct Disc {
  double u, v, radius;
  Colour colour;
  // Compares in pixel units so discs stay round on non-square images.
  bool contains(double u0, double v0, double aspect) const {
    const double du = (u0 - u) * aspect;
    const double dv = v0 - v;
    return du * du + dv * dv < radius * radius;
  }
};

// The 5 x 7 font: seven rows per glyph, top first, bit 4 the leftmost dot. Drawn for this
// project in the style of the classic dot-matrix character generators (LCD controllers, the
// VT100): capitals and digits with 1-dot strokes, readable down to one pixel per dot.
struct Glyph {
  char c;
  std::array<uint8_t, 7> rows;
};

constexpr std::array<Glyph, 61> kFont = {{
    {'A', {0b01110, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001}},
    {'B', {0b11110, 0b10001, 0b10001, 0b11110, 0b10001, 0b10001, 0b11110}},
    {'C', {0b01110, 0b10001, 0b10000, 0b10000, 0b10000, 0b10001, 0b01110}},
    {'D', {0b11110, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b11110}},
    {'E', {0b11111, 0b10000, 0b10000, 0b11110, 0b10000, 0b10000, 0b11111}},
    {'F', {0b11111, 0b10000, 0b10000, 0b11110, 0b10000, 0b10000, 0b10000}},
    {'G', {0b01110, 0b10001, 0b10000, 0b10111, 0b10001, 0b10001, 0b01111}},
    {'H', {0b10001, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001}},
    {'I', {0b01110, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}},
    {'J', {0b00111, 0b00010, 0b00010, 0b00010, 0b00010, 0b10010, 0b01100}},
    {'K', {0b10001, 0b10010, 0b10100, 0b11000, 0b10100, 0b10010, 0b10001}},
    {'L', {0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b11111}},
    {'M', {0b10001, 0b11011, 0b10101, 0b10101, 0b10001, 0b10001, 0b10001}},
    {'N', {0b10001, 0b10001, 0b11001, 0b10101, 0b10011, 0b10001, 0b10001}},
    {'O', {0b01110, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01110}},
    {'P', {0b11110, 0b10001, 0b10001, 0b11110, 0b10000, 0b10000, 0b10000}},
    {'Q', {0b01110, 0b10001, 0b10001, 0b10001, 0b10101, 0b10010, 0b01101}},
    {'R', {0b11110, 0b10001, 0b10001, 0b11110, 0b10100, 0b10010, 0b10001}},
    {'S', {0b01111, 0b10000, 0b10000, 0b01110, 0b00001, 0b00001, 0b11110}},
    {'T', {0b11111, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100}},
    {'U', {0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01110}},
    {'V', {0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01010, 0b00100}},
    {'W', {0b10001, 0b10001, 0b10001, 0b10101, 0b10101, 0b10101, 0b01010}},
    {'X', {0b10001, 0b10001, 0b01010, 0b00100, 0b01010, 0b10001, 0b10001}},
    {'Y', {0b10001, 0b10001, 0b01010, 0b00100, 0b00100, 0b00100, 0b00100}},
    {'Z', {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b10000, 0b11111}},
    {'0', {0b01110, 0b10001, 0b10011, 0b10101, 0b11001, 0b10001, 0b01110}},
    {'1', {0b00100, 0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}},
    {'2', {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b01000, 0b11111}},
    {'3', {0b11111, 0b00010, 0b00100, 0b00010, 0b00001, 0b10001, 0b01110}},
    {'4', {0b00010, 0b00110, 0b01010, 0b10010, 0b11111, 0b00010, 0b00010}},
    {'5', {0b11111, 0b10000, 0b11110, 0b00001, 0b00001, 0b10001, 0b01110}},
    {'6', {0b00110, 0b01000, 0b10000, 0b11110, 0b10001, 0b10001, 0b01110}},
    {'7', {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b01000, 0b01000}},
    {'8', {0b01110, 0b10001, 0b10001, 0b01110, 0b10001, 0b10001, 0b01110}},
    {'9', {0b01110, 0b10001, 0b10001, 0b01111, 0b00001, 0b00010, 0b01100}},
    {' ', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000}},
    {'.', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b01100, 0b01100}},
    {',', {0b00000, 0b00000, 0b00000, 0b00000, 0b01100, 0b00100, 0b01000}},
    {':', {0b00000, 0b01100, 0b01100, 0b00000, 0b01100, 0b01100, 0b00000}},
    {';', {0b00000, 0b01100, 0b01100, 0b00000, 0b01100, 0b00100, 0b01000}},
    {'!', {0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00000, 0b00100}},
    {'?', {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b00000, 0b00100}},
    {'-', {0b00000, 0b00000, 0b00000, 0b11111, 0b00000, 0b00000, 0b00000}},
    {'+', {0b00000, 0b00100, 0b00100, 0b11111, 0b00100, 0b00100, 0b00000}},
    {'=', {0b00000, 0b00000, 0b11111, 0b00000, 0b11111, 0b00000, 0b00000}},
    {'/', {0b00000, 0b00001, 0b00010, 0b00100, 0b01000, 0b10000, 0b00000}},
    {'(', {0b00010, 0b00100, 0b01000, 0b01000, 0b01000, 0b00100, 0b00010}},
    {')', {0b01000, 0b00100, 0b00010, 0b00010, 0b00010, 0b00100, 0b01000}},
    {'\'', {0b00100, 0b00100, 0b01000, 0b00000, 0b00000, 0b00000, 0b00000}},
    {'"', {0b01010, 0b01010, 0b01010, 0b00000, 0b00000, 0b00000, 0b00000}},
    {'_', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b11111}},
    {'*', {0b00000, 0b00100, 0b10101, 0b01110, 0b10101, 0b00100, 0b00000}},
    {'#', {0b01010, 0b01010, 0b11111, 0b01010, 0b11111, 0b01010, 0b01010}},
    {'%', {0b11000, 0b11001, 0b00010, 0b00100, 0b01000, 0b10011, 0b00011}},
    {'&', {0b01100, 0b10010, 0b10100, 0b01000, 0b10101, 0b10010, 0b01101}},
    {'<', {0b00010, 0b00100, 0b01000, 0b10000, 0b01000, 0b00100, 0b00010}},
    {'>', {0b01000, 0b00100, 0b00010, 0b00001, 0b00010, 0b00100, 0b01000}},
    {'[', {0b01110, 0b01000, 0b01000, 0b01000, 0b01000, 0b01000, 0b01110}},
    {']', {0b01110, 0b00010, 0b00010, 0b00010, 0b00010, 0b00010, 0b01110}},
    {'@', {0b01110, 0b10001, 0b10111, 0b10101, 0b10111, 0b10000, 0b01110}},
}};

// Any character the font lacks.
constexpr std::array<uint8_t, 7> kBox = {0b11111, 0b10001, 0b10001, 0b10001,
                                         0b10001, 0b10001, 0b11111};

constexpr const std::array<uint8_t, 7>& glyph(char c) {
  if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  for (const Glyph& g : kFont) {
    if (g.c == c) return g.rows;
  }
  return kBox;
}

}  // namespace

ImageRgb8 gradient(int width, int height) {
  check_size(width, height);
  ImageRgb8 img(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      img.at(x, y) = {ramp(x, width), ramp(y, height),
                      static_cast<uint8_t>(255 - ramp(x + y, width + height - 1))};
    }
  }
  return img;
}

ImageRgb8 checker(int width, int height, int cell, Rgb8 c0, Rgb8 c1) {
  check_size(width, height);
  if (cell < 1) throw std::invalid_argument("checker: cell must be >= 1");
  ImageRgb8 img(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) img.at(x, y) = ((x / cell + y / cell) % 2 == 0) ? c0 : c1;
  }
  return img;
}

ImageRgb8 noise(int width, int height, uint32_t seed) {
  check_size(width, height);
  Random rng(seed);
  ImageRgb8 img(width, height);
  for (Rgb8& p : img.pixels) p = {rng.byte(), rng.byte(), rng.byte()};
  return img;
}

ImageRgb8 smooth_field(int width, int height, uint32_t seed) {
  check_size(width, height);
  Random rng(seed);
  constexpr int kWavesPerChannel = 4;
  std::array<std::array<Wave, kWavesPerChannel>, 3> waves{};
  for (auto& channel : waves) {
    for (Wave& w : channel) w = random_wave(rng, 12.0, 36.0, 3.0);
  }
  const double aspect = static_cast<double>(width) / height;
  std::array<Disc, 2> discs{};
  for (Disc& d : discs) {
    d = {rng.range(0.2, 0.8),
         rng.range(0.2, 0.8),
         rng.range(0.08, 0.2),
         {rng.range(0, 255), rng.range(0, 255), rng.range(0, 255)}};
  }
  ImageRgb8 img(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width;
      const double v = (y + 0.5) / height;
      Colour c{};
      for (int k = 0; k < 3; ++k) {
        c[k] = 128.0;
        for (const Wave& w : waves[k]) c[k] += w.at(u, v);
      }
      for (const Disc& d : discs) {
        // Mostly the disc's colour, but keep some of the field's shading, as a lit object.
        if (d.contains(u, v, aspect)) c = mix(c, d.colour, 0.8);
      }
      for (double& ch : c) ch += rng.range(-3.0, 3.0);  // sensor grain
      img.at(x, y) = to_rgb(c);
    }
  }
  return img;
}

ImageRgb8 default_image(int width, int height) {
  check_size(width, height);
  Random rng(20240601u);
  const double aspect = static_cast<double>(width) / height;
  const Colour sky_top{38, 84, 180};
  const Colour sky_horizon{175, 208, 236};
  const Colour sun{255, 226, 130};
  const Colour far_hill{78, 118, 128};
  const Colour near_hill_dark{40, 110, 42};
  const Colour near_hill_light{128, 180, 60};
  const Colour tile_dark{190, 86, 58};
  const Colour tile_light{238, 222, 190};
  const Disc sun_disc{0.76, 0.2, 0.075, sun};

  std::array<Disc, 24> flowers{};
  const std::array<Colour, 4> petal = {Colour{220, 40, 60}, Colour{250, 210, 40},
                                       Colour{160, 70, 200}, Colour{250, 250, 250}};
  for (size_t i = 0; i < flowers.size(); ++i) {
    flowers[i] = {rng.range(0.02, 0.98), rng.range(0.66, 0.98), rng.range(0.008, 0.02),
                  petal[i % petal.size()]};
  }
  const Wave cloud_a{1.0, 2.3, 0.2, 0.7};
  const Wave cloud_b{0.8, 4.1, -0.3, 2.1};
  const Wave grass{1.0, 9.0, 1.2, 0.3};

  const auto near_ridge_at = [](double u) {
    return 0.62 + 0.06 * std::sin(kTwoPi * (0.9 * u + 0.65)) +
           0.02 * std::sin(kTwoPi * (5.3 * u + 0.2));
  };
  const double path_start = near_ridge_at(0.5);

  ImageRgb8 img(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width;
      const double v = (y + 0.5) / height;
      const double far_ridge = 0.47 + 0.05 * std::sin(kTwoPi * (1.3 * u + 0.1)) +
                               0.025 * std::sin(kTwoPi * (3.7 * u + 0.4));
      const double near_ridge = near_ridge_at(u);
      Colour c{};
      if (v < far_ridge) {
        c = mix(sky_top, sky_horizon, std::pow(v / far_ridge, 1.5));
        const double cloud = std::max(0.0, cloud_a.at(u, v * 2.5) + cloud_b.at(u, v * 2.5) - 0.9);
        c = mix(c, Colour{250, 250, 252}, std::min(1.0, cloud * 0.8));
        const double du = (u - sun_disc.u) * aspect;
        const double dv = v - sun_disc.v;
        c = mix(c, sun, 0.6 * std::exp(-(du * du + dv * dv) / 0.02));  // glow
        if (sun_disc.contains(u, v, aspect)) c = sun;
      } else if (v < near_ridge) {
        // Atmospheric perspective: the far hills fade toward the horizon colour upward.
        c = mix(far_hill, sky_horizon, 0.35 * (near_ridge - v) / (near_ridge - far_ridge + 1e-9));
      } else {
        const double shade = 0.5 + 0.5 * grass.at(u, v) * (v - near_ridge);
        c = mix(near_hill_dark, near_hill_light, std::clamp(shade + 0.4 * (1.0 - v), 0.0, 1.0));
        // A chequered path that widens toward the viewer, tiles in perspective. Its depth is
        // measured from the ridge above the path's centre line so that tile rows stay
        // straight.
        const double depth = v - path_start + 0.02;
        const double half_width = 0.03 + 0.5 * depth;
        if (v > path_start && std::abs(u - 0.5) < half_width) {
          const double tile_u = (u - 0.5) / depth * 1.5;
          const double tile_v = 0.25 / depth;
          const auto tile = static_cast<int>(std::floor(tile_u) + std::floor(tile_v));
          const bool dark = (tile & 1) != 0;  // parity, also for negative tiles
          c = mix(dark ? tile_dark : tile_light, Colour{90, 90, 90}, 0.25 * (1.0 - v));
        } else {
          for (const Disc& f : flowers) {
            if (f.contains(u, v, aspect)) c = f.colour;
          }
        }
      }
      for (double& ch : c) ch += rng.range(-2.5, 2.5);  // grain
      img.at(x, y) = to_rgb(c);
    }
  }
  return img;
}

ImageRgb8 text(int width, int height, const std::string& text, Rgb8 ink, Rgb8 paper) {
  check_size(width, height);
  constexpr int kGlyphRows = 7, kCellDots = 6;  // 5 dots of glyph and 1 of space
  const int dot = std::max(1, height / (kGlyphRows + 2));
  const int top = (height - kGlyphRows * dot) / 2;  // centred; a margin of >= one dot
  const std::string line = text + " ";              // the space between repetitions
  const int period = static_cast<int>(line.size()) * kCellDots;
  ImageRgb8 img(width, height);
  for (int y = 0; y < height; ++y) {
    const int row = y >= top ? (y - top) / dot : -1;
    for (int x = 0; x < width; ++x) {
      const int column = (x / dot) % period;
      const int dx = column % kCellDots;
      bool on = false;
      if (row >= 0 && row < kGlyphRows && dx < 5) {
        const char c = line[static_cast<size_t>(column / kCellDots)];
        on = (glyph(c)[static_cast<size_t>(row)] >> (4 - dx)) & 1;
      }
      img.at(x, y) = on ? ink : paper;
    }
  }
  return img;
}

}  // namespace tmu::patterns
