// The ideal trilinear model cross-checked against OpenImageIO's TextureSystem on the same
// requests and the same texels: the golden model's reference is itself checked against an
// independent implementation.
//
// Matching the two:
// - OIIO reads a MIP-mapped OpenEXR file whose levels are the ideal's exact box pyramid
//   (write_oiio_mip_texture, texram/oiio_texture.hpp), so both filter the same texels.
// - OIIO chooses levels from derivatives and blends linearly in filter width: with the filter
//   width f (in texels) at the first level m where f <= 1, it blends levels m - 1 and m by
//   2f - 1. Our lambda = (m - 1) + t blends them by t, so we pass the derivative that gives
//   f = (1 + t) / 2 at level m (oiio_trilinear_derivative). Square textures only: OIIO uses
//   min(width, height) per level.
// - Wrap modes: oiio_wrap() (texram/oiio_texture.hpp), WrapBlack = border with a (0, 0, 0, 0)
//   border colour. Same texel-centre convention, (i + 0.5) / w.
//
// Tolerance: both compute the same weighted sums, OIIO in single precision on texels / 255
// stored as float; float rounding of the data and weights stays far below 0.01 of a level.
#include <OpenImageIO/texture.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "common/test_patterns.hpp"
#include "texram/oiio_texture.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::texram {
namespace {

TEST(TexramIdealOiioTest, IdealTrilinearMatchesOpenImageIO) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tmu_oiio_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  OIIO::TextureSystem* ts = OIIO::TextureSystem::create(false);
  double worst = 0;
  for (int side : {1, 4, 32, 256}) {
    const TexramTexture tex =
        import_image(patterns::smooth_field(side, side, 3), TexelKind::kTrueColour);
    SamplerConfig c;
    c.kind = TexelKind::kTrueColour;
    c.filter = Filter::kTrilinear;
    c.border_rgba = 0;
    const std::string path = (dir / ("tex" + std::to_string(side) + ".exr")).string();
    const IdealTexture ideal_tex = ideal_texture(tex.source);
    write_oiio_mip_texture(path, ideal_tex, c);
    const int top = tex.geometry.levels() - 1;
    for (Border b : {Border::kWrap, Border::kClamp, Border::kMirror, Border::kBorder}) {
      c.border_u = c.border_v = b;
      OIIO::TextureOpt opt;
      opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
      opt.interpmode = OIIO::TextureOpt::InterpBilinear;
      opt.swrap = opt.twrap = oiio_wrap(b);
      std::mt19937 rng(static_cast<uint32_t>(side));
      double max_err = 0;
      for (int i = 0; i < 3000; ++i) {
        const double u = std::uniform_real_distribution<double>(-1.5 * side, 2.5 * side)(rng);
        const double v = std::uniform_real_distribution<double>(-1.5 * side, 2.5 * side)(rng);
        const double lambda = std::uniform_real_distribution<double>(-1.0, top + 1.0)(rng);
        const auto ideal = ideal_sample(ideal_tex, c, u, v, lambda);
        const float d = oiio_trilinear_derivative(lambda, top, side);
        float got[4] = {0, 0, 0, 0};
        ASSERT_TRUE(ts->texture(OIIO::ustring(path), opt, static_cast<float>(u / side),
                                static_cast<float>(v / side), d, 0.0f, 0.0f, d, 4, got))
            << ts->geterror();
        for (size_t ch = 0; ch < 4; ++ch) {
          max_err = std::max(max_err, std::abs(ideal[ch] - 255.0 * got[ch]));
        }
      }
      EXPECT_LE(max_err, 0.01) << side << "x" << side << " " << name(b);
      worst = std::max(worst, max_err);
    }
  }
  std::cout << "ideal vs OpenImageIO TextureSystem: max difference " << worst
            << " (8-bit levels)\n";
  OIIO::TextureSystem::destroy(ts);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tmu::texram
