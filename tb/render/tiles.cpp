#include "render/tiles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image_file.hpp"

namespace tmu::render {

Band band_of(int index, int count, int width, int height) {
  Band b;
  b.index = index;
  b.count = count;
  b.frame_width = width;
  b.frame_height = height;
  b.row_begin = static_cast<int>(int64_t{index} * height / count);
  b.row_end = static_cast<int>(int64_t{index + 1} * height / count);
  return b;
}

std::string band_stem(int index, int count) {
  return count > 1 ? fmt::format("render.tile-{}-of-{}", index, count) : "render";
}

std::pair<int, int> parse_tile(const std::string& text) {
  int i = 0, n = 0;
  char slash = 0;
  if (std::sscanf(text.c_str(), "%d%c%d", &i, &slash, &n) != 3 || slash != '/' || n < 1 || i < 0 ||
      i >= n) {
    throw InputError("--tile", "", "'" + text + "' is not i/n with 0 <= i < n");
  }
  return {i, n};
}

void write_band(const std::string& path, const ImageRgb8& image, const Band& band) {
  ImageFileSpec spec;
  spec.width = image.width;
  spec.height = image.height;
  spec.channels = 3;
  spec.attributes = {{"tmu:band", fmt::format("{}/{}", band.index, band.count)},
                     {"tmu:frame", fmt::format("{}x{}", band.frame_width, band.frame_height)},
                     {"tmu:rows", fmt::format("{}-{}", band.row_begin, band.row_end)}};
  write_image_file_atomically(path, spec, image.pixels.data());
}

ImageRgb8 merge_bands(const std::vector<std::string>& paths) {
  std::map<int, std::pair<Band, ImageRgb8>> bands;  // by first row
  int width = -1, height = -1, count = -1;
  for (const std::string& path : paths) {
    std::string why;
    const auto in = open_image_file(path, &why);
    if (!in) throw InputError(path, "", "cannot read image: " + why);
    Band b;
    const std::string band = in->attribute("tmu:band");
    const std::string frame = in->attribute("tmu:frame");
    const std::string rows = in->attribute("tmu:rows");
    if (std::sscanf(band.c_str(), "%d/%d", &b.index, &b.count) != 2 ||
        std::sscanf(frame.c_str(), "%dx%d", &b.frame_width, &b.frame_height) != 2 ||
        std::sscanf(rows.c_str(), "%d-%d", &b.row_begin, &b.row_end) != 2) {
      throw InputError(path, "tmu:band", "not a band written by texsim render --tile");
    }
    if (width < 0) {
      width = b.frame_width;
      height = b.frame_height;
      count = b.count;
    }
    if (b.frame_width != width || b.frame_height != height || b.count != count) {
      throw InputError(path, "tmu:frame",
                       fmt::format("band of a {}x{} frame in {} bands, the first was {}x{} in {}",
                                   b.frame_width, b.frame_height, b.count, width, height, count));
    }
    if (in->width() != width || in->height() != b.row_end - b.row_begin) {
      throw InputError(path, "size", "image size does not match its band");
    }
    ImageRgb8 img(in->width(), in->height());
    std::vector<uint8_t> data(static_cast<size_t>(in->width()) * in->height() * in->channels());
    if (!in->read_uint8(data.data())) {
      throw InputError(path, "", "corrupt image data: " + in->error());
    }
    for (size_t i = 0; i < img.pixels.size(); ++i) {
      const uint8_t* p = &data[i * static_cast<size_t>(in->channels())];
      img.pixels[i] = {p[0], p[1], p[2]};
    }
    if (!bands.emplace(b.row_begin, std::pair{b, std::move(img)}).second) {
      throw InputError(path, "tmu:rows",
                       fmt::format("rows {}-{} are given twice", b.row_begin, b.row_end));
    }
  }
  if (bands.empty()) throw InputError("merge", "", "no bands");
  ImageRgb8 frame(width, height);
  int next_row = 0;
  for (const auto& [first, entry] : bands) {
    const auto& [b, img] = entry;
    if (first != next_row) {
      throw InputError("merge", "", fmt::format("rows {}-{} are missing", next_row, first));
    }
    std::copy(img.pixels.begin(), img.pixels.end(),
              frame.pixels.begin() + static_cast<ptrdiff_t>(first) * width);
    next_row = b.row_end;
  }
  if (next_row != height)
    throw InputError("merge", "", fmt::format("rows {}-{} are missing", next_row, height));
  return frame;
}

}  // namespace tmu::render
