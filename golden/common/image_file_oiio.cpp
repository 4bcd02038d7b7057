// The image file interface (image_file.hpp) on OpenImageIO. In texsim this file is part of its
// OpenImageIO plugin (common/oiio_plugin.hpp); everything else links it directly.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "common/image_file.hpp"

namespace tmu {
namespace {

class OiioReader final : public ImageFileReader {
 public:
  explicit OiioReader(std::unique_ptr<OIIO::ImageInput> in) : in_(std::move(in)) {}
  int width() const override { return in_->spec().width; }
  int height() const override { return in_->spec().height; }
  int channels() const override { return in_->spec().nchannels; }
  std::string attribute(const std::string& name) const override {
    return in_->spec().get_string_attribute(name);
  }
  bool read_uint8(uint8_t* data) override {
    return in_->read_image(0, 0, 0, in_->spec().nchannels, OIIO::TypeDesc::UINT8, data);
  }
  int mip_levels() override {
    int n = 0;
    while (in_->spec_dimensions(0, n).width > 0) ++n;
    return n;
  }
  std::pair<int, int> level_size(int level) override {
    const OIIO::ImageSpec s = in_->spec_dimensions(0, level);
    return {s.width, s.height};
  }
  int tile_width() const override { return in_->spec().tile_width; }
  int tile_height() const override { return in_->spec().tile_height; }
  bool read_tile_uint8(int level, int x, int y, uint8_t* data) override {
    // A tile of a level smaller than the tile is read as far as the level goes, into the
    // tile-shaped buffer (rows tile_width apart).
    const OIIO::ImageSpec s = in_->spec_dimensions(0, level);
    const int n = in_->spec().nchannels;
    const int tw = tile_width(), th = tile_height();
    return in_->read_tiles(0, level, x, std::min(x + tw, s.width), y, std::min(y + th, s.height), 0,
                           1, 0, n, OIIO::TypeDesc::UINT8, data, n, OIIO::stride_t{tw} * n);
  }
  std::string error() override { return in_->geterror(); }

 private:
  std::unique_ptr<OIIO::ImageInput> in_;
};

}  // namespace

std::unique_ptr<ImageFileReader> open_image_file(const std::string& path, std::string* why) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    *why = OIIO::geterror();
    return nullptr;
  }
  return std::make_unique<OiioReader>(std::move(in));
}

namespace {

// An image output for `spec` open on `file` (format from format_path's extension), and the pixel
// type it takes; nullptr with kNoWriter or kFailed (*error says why) in *result.
std::unique_ptr<OIIO::ImageOutput> open_output(const std::string& format_path,
                                               const std::string& file, const ImageFileSpec& spec,
                                               OIIO::TypeDesc* type, ImageWrite* result,
                                               std::string* error) {
  auto out = OIIO::ImageOutput::create(format_path);
  if (!out) {
    *result = ImageWrite::kNoWriter;
    return nullptr;
  }
  *type = spec.format == PixelFormat::kFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec s(spec.width, spec.height, spec.channels, *type);
  for (const auto& [name, value] : spec.attributes) s.attribute(name, value);
  if (!out->open(file, s)) {
    *error = out->geterror();
    *result = ImageWrite::kFailed;
    return nullptr;
  }
  return out;
}

ImageWrite failed(OIIO::ImageOutput& out, std::string* error) {
  *error = out.geterror();
  return ImageWrite::kFailed;
}

}  // namespace

ImageWrite write_image_file(const std::string& format_path, const std::string& file,
                            const ImageFileSpec& spec, const void* pixels, std::string* error) {
  OIIO::TypeDesc type;
  ImageWrite result = ImageWrite::kOk;
  const auto out = open_output(format_path, file, spec, &type, &result, error);
  if (!out) return result;
  if (!out->write_image(type, pixels) || !out->close()) return failed(*out, error);
  return ImageWrite::kOk;
}

ImageWrite write_image_file_rows(const std::string& format_path, const std::string& file,
                                 const ImageFileSpec& spec, int band, const ImageRows& fill,
                                 std::string* error) {
  OIIO::TypeDesc type;
  ImageWrite result = ImageWrite::kOk;
  const auto out = open_output(format_path, file, spec, &type, &result, error);
  if (!out) return result;
  const size_t row_bytes = static_cast<size_t>(spec.width) * spec.channels * type.size();
  std::vector<uint8_t> rows(static_cast<size_t>(band) * row_bytes);
  for (int y = 0; y < spec.height; y += band) {
    const int n = std::min(band, spec.height - y);
    fill(y, n, rows.data());
    if (!out->write_scanlines(y, y + n, 0, type, rows.data())) return failed(*out, error);
  }
  if (!out->close()) return failed(*out, error);
  return ImageWrite::kOk;
}

}  // namespace tmu
