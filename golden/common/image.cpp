#include "common/image.hpp"

#include <cmath>
#include <limits>
#include <memory>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image_file.hpp"

namespace tmu {

ImageRgb8 read_image(const std::string& path) {
  std::string why;
  const auto in = open_image_file(path, &why);
  if (!in) {
    throw InputError(path, "", "cannot read image: " + (why.empty() ? "unknown format" : why));
  }
  if (in->width() <= 0 || in->height() <= 0 || in->channels() <= 0) {
    throw InputError(path, "", "image has no pixels");
  }
  const int nch = in->channels();
  std::vector<uint8_t> data(static_cast<size_t>(in->width()) * in->height() * nch);
  if (!in->read_uint8(data.data())) {
    throw InputError(path, "", "corrupt image data: " + in->error());
  }
  ImageRgb8 img(in->width(), in->height());
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const uint8_t* p = &data[i * nch];
    img.pixels[i] = nch >= 3 ? Rgb8{p[0], p[1], p[2]} : Rgb8{p[0], p[0], p[0]};
  }
  return img;
}

namespace {

// The InputError of a write that did not succeed, naming the file.
void check_written(const std::string& path, ImageWrite result, const std::string& why) {
  switch (result) {
    case ImageWrite::kOk:
      return;
    case ImageWrite::kNoWriter:
      throw InputError(path, "", "no image writer for this extension");
    case ImageWrite::kFailed:
      throw InputError(path, "", "cannot write image: " + why);
  }
}

ImageFileSpec rgb8_spec(int width, int height) {
  ImageFileSpec spec;
  spec.width = width;
  spec.height = height;
  spec.channels = 3;
  return spec;
}

}  // namespace

void write_image_file_atomically(const std::string& path, const ImageFileSpec& spec,
                                 const void* pixels) {
  write_atomically(path, [&](const std::string& tmp) {
    std::string why;
    check_written(path, write_image_file(path, tmp, spec, pixels, &why), why);
  });
}

void write_image(const std::string& path, const ImageRgb8& image) {
  write_image_file_atomically(path, rgb8_spec(image.width, image.height), image.pixels.data());
}

void write_image_rows(const std::string& path, int width, int height, int band,
                      const std::function<void(int y, int n, Rgb8* rows)>& fill) {
  const ImageRows rows = [&](int y, int n, void* data) { fill(y, n, static_cast<Rgb8*>(data)); };
  write_atomically(path, [&](const std::string& tmp) {
    std::string why;
    check_written(
        path, write_image_file_rows(path, tmp, rgb8_spec(width, height), band, rows, &why), why);
  });
}

double psnr(const ImageRgb8& a, const ImageRgb8& b) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument("psnr: image sizes differ");
  }
  double se = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const double dr = a.pixels[i].r - b.pixels[i].r;
    const double dg = a.pixels[i].g - b.pixels[i].g;
    const double db = a.pixels[i].b - b.pixels[i].b;
    se += dr * dr + dg * dg + db * db;
  }
  if (se == 0.0) return std::numeric_limits<double>::infinity();
  const double mse = se / (3.0 * static_cast<double>(a.pixels.size()));
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace tmu
