#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "blocks/ccc_cache_bilinear/texture_memory.hpp"
#include "ccc/ccc_cache_bilinear.hpp"
#include "ccc/ccc_decoder.hpp"
#include "common/error.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/ccc/ccc_cache_bilinear_sc.hpp"
#include "rtl_models_ccc_cache_bilinear.hpp"

TMU_DESCRIBE_SC(ccc_cache_bilinear)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::ccc_cache_bilinear;

namespace {

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel in raw SQ16.8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
// A random run draws a new environment after this many items.
constexpr size_t kBatch = 2500;

// Raw SQ16.8 of a real coordinate, rounded to nearest and saturated to the format.
int32_t raw_of(double texels) {
  const double r = std::round(texels * kOne);
  return static_cast<int32_t>(std::clamp(r, double{kCoordMin}, double{kCoordMax}));
}

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions, so
// the stimulus is the same on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

// A side drawn from a seed: 1..80 texels, now and then 81..300, or 1.
uint32_t draw_side(std::mt19937_64& rng) {
  const uint64_t r = rng() % 16;
  if (r == 0) return 1;
  if (r == 1) return static_cast<uint32_t>(uniform(rng, 81, 300));
  return static_cast<uint32_t>(uniform(rng, 1, 80));
}

// The unclamped footprint origin floor(c - 0.5) of a raw coordinate.
int64_t footprint_origin(int32_t raw) { return (int64_t{raw} - kOne / 2) >> kFrac; }

// The golden unit over a run: a configuration item sets the size and lookahead and names the
// texture (the cache and the statistics stay, as in the RTL); every block fetched is a memory
// request, in the order the unit makes them.
class Golden : public Model {
 public:
  explicit Golden(std::shared_ptr<const CccCacheBilinearBlock> block) : block_(std::move(block)) {}
  void configure(const Txn& cfg) override {
    texture_ = block_->texture_of(cfg);
    const auto w = static_cast<uint32_t>(cfg.f[D::cfg_width]);
    const auto h = static_cast<uint32_t>(cfg.f[D::cfg_height]);
    const bool lookahead = cfg.f[D::cfg_lookahead] != 0;
    if (!unit_) {
      unit_.emplace(w, h, lookahead, [this](uint32_t address) { return fetch(address); });
    } else {
      resized_ = resized_ || w != width_ || h != height_;
      unit_->configure(w, h, lookahead);
    }
    width_ = w;
    height_ = h;
  }
  void step(const Txn& item, Sink& sink) override {
    if (!unit_) throw std::runtime_error("ccc_cache_bilinear: an item before the configuration");
    if (item.f[0] == D::op_clut) {
      unit_->write_clut(static_cast<uint8_t>(item.f[D::clut_addr]),
                        static_cast<uint32_t>(item.f[D::clut_rgb]));
      resized_ = false;
      return;
    }
    if (resized_) {
      throw std::runtime_error(
          "ccc_cache_bilinear: a sample after a new texture size without a CLUT write (the "
          "write invalidates the cache, whose tags name blocks of the old size)");
    }
    sink_ = &sink;
    Txn out;
    out.f[D::out_rgb] =
        unit_->sample(bilinear_coord(item.f[D::req_u]), bilinear_coord(item.f[D::req_v]));
    sink.output(out);
  }
  Counters counters() const override {
    const ccc::CacheStats s = unit_ ? unit_->stats() : ccc::CacheStats{};
    // The RTL's counters are 32-bit registers.
    const auto c32 = [](uint64_t v) { return v & 0xFFFF'FFFFu; };
    return {{"hits", c32(s.hits)}, {"misses", c32(s.misses)}, {"prefetches", c32(s.prefetches)}};
  }

 private:
  uint32_t fetch(uint32_t address) {
    Txn request;
    request.f[D::mem_req_addr] = address;
    sink_->request(0, request);
    if (address >= texture_->blocks.size()) {
      throw std::runtime_error(fmt::format("ccc_cache_bilinear: block {} beyond the texture's {}",
                                           address, texture_->blocks.size()));
    }
    return texture_->blocks[address];
  }

  std::shared_ptr<const CccCacheBilinearBlock> block_;
  std::shared_ptr<const ccc::Texture> texture_;
  std::optional<ccc::CacheBilinearUnit> unit_;
  uint32_t width_ = 0, height_ = 0;
  bool resized_ = false;
  Sink* sink_ = nullptr;
};

std::shared_ptr<const ccc::Texture> read_texture(const std::string& path) {
  ccc::Texture tex = ccc::read_ccc(path);
  for (const auto& [field, size] :
       {std::pair<const char*, uint32_t>{"width", tex.width}, {"height", tex.height}}) {
    if (size < 1 || size > static_cast<uint32_t>(fmts::kMaxTexSize)) {
      throw InputError(path, field,
                       fmt::format("{} texels; the unit takes 1..{}", size, fmts::kMaxTexSize));
    }
  }
  return std::make_shared<const ccc::Texture>(std::move(tex));
}

}  // namespace

// ---- Items and textures ------------------------------------------------------------------

int32_t bilinear_coord(uint64_t field) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & ((uint64_t{1} << fmts::kTexCoord.width()) - 1)),
              fmts::kTexCoord, fx::Overflow::kWrap));
}

Txn bilinear_sample_item(int32_t u_raw, int32_t v_raw) {
  return channel_item(D::table(), "req",
                      {static_cast<uint32_t>(u_raw), static_cast<uint32_t>(v_raw)});
}

Txn bilinear_clut_item(uint8_t index, uint32_t rgb) {
  return channel_item(D::table(), "clut", {index, rgb});
}

std::vector<Txn> bilinear_resample_items(const ccc::Texture& tex, uint32_t out_w, uint32_t out_h) {
  std::vector<Txn> items;
  auto coord = [](uint32_t i, uint32_t size,
                  uint32_t out) {  // round((i + 0.5) * size / out), SQ16.8
    return static_cast<int32_t>(((2 * int64_t{i} + 1) * size * kOne + out) / (2 * int64_t{out}));
  };
  for (uint32_t y = 0; y < out_h; ++y) {
    for (uint32_t x = 0; x < out_w; ++x) {
      items.push_back(
          bilinear_sample_item(coord(x, tex.width, out_w), coord(y, tex.height, out_h)));
    }
  }
  return items;
}

ccc::Texture random_bilinear_texture(uint32_t width, uint32_t height, uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0xB11E'7E57'0000'0001ull);
  ccc::Texture tex;
  tex.width = width;
  tex.height = height;
  for (Rgb8& c : tex.clut) c = unpack_rgb(static_cast<uint32_t>(rng()));
  tex.blocks.resize(size_t{tex.blocks_wide()} * tex.blocks_high());
  for (uint32_t& w : tex.blocks) w = static_cast<uint32_t>(rng());
  return tex;
}

// ---- The block ---------------------------------------------------------------------------

CccCacheBilinearBlock::CccCacheBilinearBlock(const BlockOptions& options)
    : CccCacheBilinearBlock(options,
                            options.texture.empty() ? nullptr : read_texture(options.texture)) {}

CccCacheBilinearBlock::CccCacheBilinearBlock(const BlockOptions& options,
                                             std::shared_ptr<const ccc::Texture> texture)
    : DescribedBlockOf(D::table()), options_(options), fixed_(std::move(texture)) {
  if (fixed_) {
    first_ = fixed_;
  } else {
    std::mt19937_64 rng(options.seed ^ 0xB11E'7E57'0000'0002ull);
    const uint32_t w = draw_side(rng), h = draw_side(rng);
    first_seed_ = static_cast<uint32_t>(rng());
    first_ = std::make_shared<const ccc::Texture>(random_bilinear_texture(w, h, first_seed_));
  }
  add_level("hls", hls_level<desc::ccc_cache_bilinear_sc, hls::CccCacheBilinearSc>());
  TMU_ADD_RTL_LEVELS(ccc_cache_bilinear, variant());
}

std::string CccCacheBilinearBlock::repro_options() const {
  std::string out;
  if (!options_.texture.empty()) out += "--texture " + options_.texture;
  if (options_.lookahead == false) out += std::string(out.empty() ? "" : " ") + "--no-lookahead";
  return out;
}

Txn CccCacheBilinearBlock::config_item(const ccc::Texture& texture, bool lookahead,
                                       uint32_t texture_seed) const {
  return channel_item(D::table(), "cfg",
                      {texture.width, texture.height, lookahead ? 1u : 0u, texture_seed});
}

std::vector<Txn> CccCacheBilinearBlock::texture_load(const ccc::Texture& texture, bool lookahead,
                                                     uint32_t texture_seed) const {
  std::vector<Txn> items = {config_item(texture, lookahead, texture_seed)};
  for (size_t i = 0; i < texture.clut.size(); ++i) {
    items.push_back(bilinear_clut_item(static_cast<uint8_t>(i), pack_rgb(texture.clut[i])));
  }
  return items;
}

std::shared_ptr<const ccc::Texture> CccCacheBilinearBlock::texture_of(const Txn& cfg) const {
  const auto w = static_cast<uint32_t>(cfg.f[D::cfg_width]);
  const auto h = static_cast<uint32_t>(cfg.f[D::cfg_height]);
  const auto seed = static_cast<uint32_t>(cfg.f[D::cfg_texture]);
  if (fixed_) return fixed_;
  if (w == first_->width && h == first_->height && seed == first_seed_) return first_;
  if (w < 1 || h < 1 || w > fmts::kMaxTexSize || h > fmts::kMaxTexSize) {
    throw std::invalid_argument(fmt::format(
        "ccc_cache_bilinear: a texture of {} x {} texels (1..{} a side)", w, h, fmts::kMaxTexSize));
  }
  return std::make_shared<const ccc::Texture>(random_bilinear_texture(w, h, seed));
}

std::vector<Txn> CccCacheBilinearBlock::setup_items() const {
  return texture_load(*first_, options_.lookahead.value_or(true), first_seed_);
}

std::vector<Txn> CccCacheBilinearBlock::directed_items() const {
  const ccc::Texture& tex = *first_;
  const double w = tex.width, h = tex.height;
  std::vector<Txn> items;
  auto at = [&items](double u, double v) {
    items.push_back(bilinear_sample_item(raw_of(u), raw_of(v)));
  };
  auto at_raw = [&items](int32_t u, int32_t v) { items.push_back(bilinear_sample_item(u, v)); };

  // Exact texel centres (both weights 0) at the four corners.
  at(0.5, 0.5);
  at(w - 0.5, 0.5);
  at(0.5, h - 0.5);
  at(w - 0.5, h - 0.5);
  // The texture's corners and just beyond: clamped on two sides.
  at(0, 0);
  at(w, 0);
  at(0, h);
  at(w, h);
  at(-0.25, -0.25);
  at(w + 0.25, h + 0.25);
  // Edges: clamped on one side.
  at(w / 2, 0.1);
  at(w / 2, h - 0.1);
  at(0.1, h / 2);
  at(w - 0.1, h / 2);
  at(w / 2, 0);
  at(0, h / 2);
  // Weights 0, 128 and 255 on each axis (u - 0.5 = 1 + f/256 where the texture allows).
  const int32_t cx = tex.width > 1 ? kOne : 0, cy = tex.height > 1 ? kOne : 0;
  for (int32_t fxw : {0, 128, 255}) {
    for (int32_t fyw : {0, 128, 255}) at_raw(cx + kOne / 2 + fxw, cy + kOne / 2 + fyw);
  }
  // Negative coordinates, including the smallest step below zero.
  at(-0.5, 2.5);
  at(2.5, -0.5);
  at_raw(-1, -1);
  at(-1000, 3.3);
  at(3.3, -1000);
  // Far outside: the ends of SQ16.8 (-32768.0 and 32767.996), and mixes.
  at_raw(kCoordMin, kCoordMin);
  at_raw(kCoordMax, kCoordMax);
  at_raw(kCoordMin, kCoordMax);
  at_raw(kCoordMax, kCoordMin);
  at_raw(kCoordMax - 127, 100);
  at_raw(100, kCoordMin + 129);
  // Block boundaries: u = 4k puts x0 = 4k - 1 and x1 = 4k in two blocks; one LSB either side.
  for (int32_t k = 1; k <= 4 && 4 * k < static_cast<int32_t>(tex.width); ++k) {
    for (int32_t d : {-1, 0, 1}) at_raw(4 * k * kOne + d, 2 * kOne);
  }
  for (int32_t k = 1; k <= 4 && 4 * k < static_cast<int32_t>(tex.height); ++k) {
    for (int32_t d : {-1, 0, 1}) at_raw(2 * kOne, 4 * k * kOne + d);
  }
  // Footprints of 1, 2 (across, down) and 4 blocks, each twice: a miss, then a hit.
  for (int rep = 0; rep < 2; ++rep) {
    at(2.0, 2.0);
    at(4.0, 2.0);
    at(2.0, 4.0);
    at(4.0, 4.0);
  }
  // A short walk back and forth over a block boundary (hits, then prefetched blocks).
  for (int i = 0; i < 12; ++i) at(2.6 + 0.4 * i, 6.3);
  for (int i = 12; i >= 0; --i) at(2.6 + 0.4 * i, 6.7);
  // A CLUT write between samples: the cached colours are stale and must be refetched.
  const uint32_t word = tex.block_word(0, 0);
  const uint8_t index = ccc::texel_index(word, 0);
  const uint32_t colour = pack_rgb(tex.clut[index]);
  at(0.5, 0.5);
  items.push_back(bilinear_clut_item(index, ~colour & 0xFFFFFFu));
  at(0.5, 0.5);
  at(1.0, 1.0);
  items.push_back(bilinear_clut_item(index, colour));
  items.push_back(bilinear_clut_item(index, colour));  // back to back
  at(1.0, 1.0);
  // The lookahead switched off and on again between batches (same texture, cache kept).
  const bool lookahead = options_.lookahead.value_or(true);
  items.push_back(config_item(tex, !lookahead, first_seed_));
  for (int i = 0; i < 8; ++i) at(1.3 + 0.9 * i, 1.7);
  items.push_back(config_item(tex, lookahead, first_seed_));
  for (int i = 0; i < 8; ++i) at(1.3 + 0.9 * i, 2.9);
  return items;
}

std::vector<Txn> CccCacheBilinearBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  std::shared_ptr<const ccc::Texture> tex = first_;
  int64_t w = tex->width, h = tex->height;
  auto push = [&](int64_t u, int64_t v) {
    items.push_back(
        bilinear_sample_item(static_cast<int32_t>(std::clamp<int64_t>(u, kCoordMin, kCoordMax)),
                             static_cast<int32_t>(std::clamp<int64_t>(v, kCoordMin, kCoordMax))));
  };
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new environment, as a driver between batches
      next_batch += kBatch;
      const bool lookahead = options_.lookahead.value_or(rng() % 4 != 0);
      uint32_t seed = first_seed_;
      if (!fixed_) {
        const uint32_t nw = draw_side(rng), nh = draw_side(rng);
        seed = static_cast<uint32_t>(rng());
        tex = std::make_shared<const ccc::Texture>(random_bilinear_texture(nw, nh, seed));
      }
      for (const Txn& t : texture_load(*tex, lookahead, seed)) items.push_back(t);
      w = tex->width;
      h = tex->height;
      continue;
    }
    const uint64_t r = rng() % 1000;
    if (r == 0) {  // rarely, a CLUT rewrite
      const uint64_t x = rng();
      items.push_back(bilinear_clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
    } else if (r < 10) {  // anywhere in SQ16.8
      push(uniform(rng, kCoordMin, kCoordMax), uniform(rng, kCoordMin, kCoordMax));
    } else if (r < 400) {  // uniform over the texture and 3 texels around it
      push(uniform(rng, -3 * kOne, (w + 3) * kOne), uniform(rng, -3 * kOne, (h + 3) * kOne));
    } else {
      // A rasterizer's scanline walk: rows of small steps in u (either direction), each row
      // a step in v from the last, from magnification (steps of 1/16 texel) to minification
      // (steps of 1.5 texels).
      const int64_t du = uniform(rng, kOne / 16, 3 * kOne / 2) * (rng() % 4 == 0 ? -1 : 1);
      const int64_t dv = uniform(rng, kOne / 16, 3 * kOne / 2);
      const int64_t rows = uniform(rng, 1, 8), per_row = uniform(rng, 4, 48);
      const int64_t u0 = uniform(rng, -2 * kOne, (w + 2) * kOne);
      int64_t v = uniform(rng, -2 * kOne, (h + 2) * kOne);
      for (int64_t row = 0; row < rows && items.size() < count; ++row, v += dv) {
        int64_t u = u0 + uniform(rng, -kOne / 2, kOne / 2);  // spans start a little apart
        for (int64_t i = 0; i < per_row && items.size() < count; ++i, u += du) push(u, v);
      }
    }
  }
  return items;
}

std::unique_ptr<Model> CccCacheBilinearBlock::golden() const {
  return std::make_unique<Golden>(std::static_pointer_cast<const CccCacheBilinearBlock>(share()));
}

std::unique_ptr<Environment> CccCacheBilinearBlock::environment(uint64_t seed) const {
  const auto block = std::static_pointer_cast<const CccCacheBilinearBlock>(share());
  return std::make_unique<TextureMemory>([block](const Txn& cfg) { return block->texture_of(cfg); },
                                         seed);
}

std::vector<std::string> CccCacheBilinearBlock::coverage_cases() const {
  return {"footprint in 1 block",
          "footprint spans 2 blocks",
          "footprint spans 4 blocks",
          "clamp at left",
          "clamp at right",
          "clamp at top",
          "clamp at bottom",
          "fx == 0",
          "fx == 255",
          "fy == 0",
          "fy == 255",
          "sample right after a CLUT write",
          "sample right after a configuration",
          "negative coordinate",
          "coordinate beyond the texture"};
}

void CccCacheBilinearBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                                  Coverage& cov) const {
  // The texture size in effect: the last configuration item before this one.
  if (index < cover_next_) cover_next_ = 0;
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (!D::table().is_cfg(t)) continue;
    cover_w_ = static_cast<uint32_t>(t.f[D::cfg_width]);
    cover_h_ = static_cast<uint32_t>(t.f[D::cfg_height]);
  }
  const Txn& t = items[index];
  const uint32_t w = cover_w_, h = cover_h_;
  const int32_t u = bilinear_coord(t.f[D::req_u]), v = bilinear_coord(t.f[D::req_v]);
  const ccc::Footprint fp = ccc::footprint(u, v, w, h);
  const uint32_t blocks = ccc::footprint_blocks(fp).count;
  ++cov[blocks == 1   ? "footprint in 1 block"
        : blocks == 2 ? "footprint spans 2 blocks"
                      : "footprint spans 4 blocks"];
  const int64_t x0 = footprint_origin(u), y0 = footprint_origin(v);
  if (x0 < 0) ++cov["clamp at left"];
  if (x0 + 1 > int64_t{w} - 1) ++cov["clamp at right"];
  if (y0 < 0) ++cov["clamp at top"];
  if (y0 + 1 > int64_t{h} - 1) ++cov["clamp at bottom"];
  if (fp.fx == 0) ++cov["fx == 0"];
  if (fp.fx == 255) ++cov["fx == 255"];
  if (fp.fy == 0) ++cov["fy == 0"];
  if (fp.fy == 255) ++cov["fy == 255"];
  if (index > 0 && items[index - 1].f[0] == D::op_clut) ++cov["sample right after a CLUT write"];
  if (index > 0 && items[index - 1].f[0] == D::op_cfg) ++cov["sample right after a configuration"];
  if (u < 0 || v < 0) ++cov["negative coordinate"];
  if (int64_t{u} >= int64_t{w} * kOne || int64_t{v} >= int64_t{h} * kOne) {
    ++cov["coordinate beyond the texture"];
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(ccc_cache_bilinear, CccCacheBilinearBlock)
