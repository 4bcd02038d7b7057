#include "render/video_pattern.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace tmu::render {
namespace {

using texram::video::VideoFormat;
using texram::video::VideoFrame;
using Colour = std::array<uint8_t, 3>;

constexpr std::array<Colour, 8> kBars = {{{235, 235, 235},
                                          {235, 235, 16},
                                          {16, 235, 235},
                                          {16, 235, 16},
                                          {235, 16, 235},
                                          {235, 16, 16},
                                          {16, 16, 235},
                                          {16, 16, 16}}};

Colour video_bars(const VideoFormat& f, uint32_t x, uint32_t y, uint32_t k) {
  const uint32_t w = f.width(), h = f.height();
  const uint32_t shift = k * std::max<uint32_t>(1, w / 16);
  Colour c = kBars[(((x + shift) % w) * 8) / w];
  // A dark band an eighth of the height, a line lower each frame: vertical motion too.
  if (((y + h - k % h) % h) < std::max<uint32_t>(1, h / 8)) {
    for (uint8_t& v : c) v = static_cast<uint8_t>(v / 4);
  }
  return c;
}

// A triangle wave 0..255..0 over 512 levels.
uint8_t video_triangle(uint32_t t) {
  t &= 511;
  return static_cast<uint8_t>(t < 256 ? t : 511 - t);
}

Colour video_rings(const VideoFormat& f, uint32_t x, uint32_t y, uint32_t k) {
  // The centre walks 16 points of a circle (a table of 16 steps, integer: sin and cos x 64).
  static constexpr std::array<int, 16> kSin = {0, 24,  45,  59,  64,  59,  45,  24,
                                               0, -24, -45, -59, -64, -59, -45, -24};
  const auto w = static_cast<int64_t>(f.width()), h = static_cast<int64_t>(f.height());
  const int64_t cx = w / 2 + kSin[(k + 4) % 16] * w / 256;
  const int64_t cy = h / 2 + kSin[k % 16] * h / 256;
  const int64_t dx = static_cast<int64_t>(x) - cx, dy = static_cast<int64_t>(y) - cy;
  // Squared distance scaled so a ring is about an eighth of the smaller side wide.
  const int64_t side = std::max<int64_t>(1, std::min(w, h));
  const auto r = static_cast<uint32_t>((dx * dx + dy * dy) * 2048 / (side * side));
  const uint32_t t = r * 8 + 512 - (k * 8) % 512;
  return {video_triangle(t), video_triangle(t + 170), video_triangle(t + 340)};
}

uint8_t video_grey(const Colour& c) {
  return static_cast<uint8_t>((77u * c[0] + 150u * c[1] + 29u * c[2] + 128u) >> 8);
}

}  // namespace

VideoFrame generated_video_frame(const std::string& pattern, const VideoFormat& format,
                                 uint32_t k) {
  if (pattern == "noise") return texram::video::test_frame(format, k);
  if (pattern != "bars" && pattern != "rings")
    throw std::invalid_argument("generated video: no pattern '" + pattern + "'");
  VideoFrame frame(static_cast<size_t>(format.planes),
                   texram::Level8(format.width(), format.height()));
  for (uint32_t y = 0; y < format.height(); ++y) {
    for (uint32_t x = 0; x < format.width(); ++x) {
      const Colour c =
          pattern == "bars" ? video_bars(format, x, y, k) : video_rings(format, x, y, k);
      if (format.planes == 1) {
        frame[0].at(x, y) = video_grey(c);
      } else {
        for (size_t p = 0; p < 3; ++p) frame[p].at(x, y) = c[p];
        frame[3].at(x, y) = 255;
      }
    }
  }
  return frame;
}

}  // namespace tmu::render
