// An 8-bit RGB image and its file I/O (through OpenImageIO: common/image_file.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/image_file.hpp"

namespace tmu {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

// Packs to / unpacks from the Rgb888 port format (R in 23:16, G in 15:8, B in 7:0).
constexpr uint32_t pack_rgb(Rgb8 c) { return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b; }
constexpr Rgb8 unpack_rgb(uint32_t v) {
  return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

struct ImageRgb8 {
  int width = 0;
  int height = 0;
  std::vector<Rgb8> pixels;  // row-major

  ImageRgb8() = default;
  ImageRgb8(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h) {}
  Rgb8& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const Rgb8& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
  friend bool operator==(const ImageRgb8&, const ImageRgb8&) = default;
};

// Reads any format OpenImageIO knows; grey is replicated to RGB, alpha and extra channels
// are dropped, other bit depths are converted to 8 bits. Throws InputError naming the file.
ImageRgb8 read_image(const std::string& path);

// Writes an image (format from the extension) atomically. Throws InputError naming the file.
void write_image(const std::string& path, const ImageRgb8& image);
// Writes `pixels` (spec's layout) to `path` atomically, in the format its extension names
// (common/image_file.hpp); InputError naming the file when no writer takes the extension or the
// write fails, and the file that was there is kept.
void write_image_file_atomically(const std::string& path, const ImageFileSpec& spec,
                                 const void* pixels);

// Writes a width x height RGB image too large for memory atomically, `band` rows at a time, each
// band's pixels filled by `fill(y, n, rows)` (rows y .. y + n - 1) just before it is written.
// Errors as write_image.
void write_image_rows(const std::string& path, int width, int height, int band,
                      const std::function<void(int y, int n, Rgb8* rows)>& fill);

// Peak signal-to-noise ratio over all RGB samples, in dB (infinity when identical).
double psnr(const ImageRgb8& a, const ImageRgb8& b);

}  // namespace tmu
