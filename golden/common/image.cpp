#include "common/image.hpp"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <limits>
#include <memory>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace tmu {

ImageRgb8 read_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::string why = OIIO::geterror();
    throw InputError(path, "", "cannot read image: " + (why.empty() ? "unknown format" : why));
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    throw InputError(path, "", "image has no pixels");
  }
  const int nch = spec.nchannels;
  std::vector<uint8_t> data(static_cast<size_t>(spec.width) * spec.height * nch);
  if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::UINT8, data.data())) {
    throw InputError(path, "", "corrupt image data: " + in->geterror());
  }
  ImageRgb8 img(spec.width, spec.height);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const uint8_t* p = &data[i * nch];
    img.pixels[i] = nch >= 3 ? Rgb8{p[0], p[1], p[2]} : Rgb8{p[0], p[0], p[0]};
  }
  return img;
}

void write_image(const std::string& path, const ImageRgb8& image) {
  write_atomically(path, [&](const std::string& tmp) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw InputError(path, "", "no image writer for this extension");
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(tmp, spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) ||
        !out->close()) {
      throw InputError(path, "", "cannot write image: " + out->geterror());
    }
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
