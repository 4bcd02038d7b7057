// The OIIO side of texram/oiio_sampler.hpp (and oiio_wrap of oiio_texture.hpp). It calls
// nothing of golden/ but header-only code: texsim's OpenImageIO plugin is built from it.
#include "texram/oiio_sampler.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>

#include <memory>
#include <vector>

#include "common/error.hpp"
#include "texram/oiio_texture.hpp"

namespace tmu::texram {

OIIO::TextureOpt::Wrap oiio_wrap(Border border) {
  switch (border) {
    case Border::kWrap:
      return OIIO::TextureOpt::WrapPeriodic;
    case Border::kClamp:
      return OIIO::TextureOpt::WrapClamp;
    case Border::kMirror:
      return OIIO::TextureOpt::WrapMirror;
    case Border::kBorder:
      return OIIO::TextureOpt::WrapBlack;
  }
  return OIIO::TextureOpt::WrapDefault;
}

void make_oiio_texture(const std::string& path, int width, int height, std::vector<float> rgba) {
  const OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
  const OIIO::ImageBuf level0(spec, rgba.data());
  OIIO::ImageSpec cfg;
  cfg.format = OIIO::TypeDesc::FLOAT;
  cfg.tile_width = cfg.tile_height = 64;
  cfg.tile_depth = 1;
  cfg.attribute("maketx:filtername", "box");
  cfg.attribute("maketx:compute_average", 0);
  if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, level0, path, cfg)) {
    throw InputError(path, "", "make_texture failed: " + OIIO::geterror());
  }
}

namespace {

class TextureSystemSampler final : public OiioAnisoSampler {
 public:
  TextureSystemSampler(const std::vector<OiioTextureFile>& files, int max_probes)
      : ts_(OIIO::TextureSystem::create(false)) {
    for (const OiioTextureFile& f : files) {
      OIIO::TextureOpt o;
      o.mipmode = OIIO::TextureOpt::MipModeAniso;
      o.interpmode = OIIO::TextureOpt::InterpBilinear;
      o.anisotropic = max_probes;
      o.swrap = oiio_wrap(f.border_u);
      o.twrap = oiio_wrap(f.border_v);
      options_.push_back(o);
      handles_.push_back(ts_->get_texture_handle(OIIO::ustring(f.path)));
    }
    thread_info_ = ts_->get_perthread_info();
  }
  ~TextureSystemSampler() override { OIIO::TextureSystem::destroy(ts_); }
  TextureSystemSampler(const TextureSystemSampler&) = delete;
  TextureSystemSampler& operator=(const TextureSystemSampler&) = delete;

  bool lookup(size_t index, float s, float t, float dsdx, float dtdx, float dsdy, float dtdy,
              float rgba[4]) override {
    return ts_->texture(handles_[index], thread_info_, options_[index], s, t, dsdx, dtdx, dsdy,
                        dtdy, 4, rgba);
  }
  std::string error() override { return ts_->geterror(); }
  std::string statistics() override { return ts_->getstats(1, false); }

 private:
  OIIO::TextureSystem* ts_;
  std::vector<OIIO::TextureOpt> options_;
  std::vector<OIIO::TextureSystem::TextureHandle*> handles_;
  OIIO::TextureSystem::Perthread* thread_info_ = nullptr;
};

}  // namespace

std::unique_ptr<OiioAnisoSampler> make_oiio_aniso_sampler(const std::vector<OiioTextureFile>& files,
                                                          int max_probes) {
  return std::make_unique<TextureSystemSampler>(files, max_probes);
}

}  // namespace tmu::texram
