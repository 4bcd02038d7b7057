#include "blocks/ccc_bilinear_block.hpp"

#include <Vtmu_ccc_cache_bilinear.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ccc/ccc_cache_bilinear.hpp"
#include "ccc/ccc_decoder.hpp"
#include "common/error.hpp"
#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/ccc/ccc_cache_bilinear_sc.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;

namespace {

const Schema kInputs({{"op", fx::UQ(1, 0)},
                      {"u", fmts::kTexCoord},
                      {"v", fmts::kTexCoord},
                      {"clut_addr", fmts::kClutIndex},
                      {"clut_rgb", fmts::kRgb888}});
const Schema kOutputs({{"rgb", fmts::kRgb888}});

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel in raw SQ16.8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());

size_t count_samples(const std::vector<Txn>& items) {
  size_t n = 0;
  for (const Txn& t : items) n += t.f[kBilOp] == kBilOpSample;
  return n;
}

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

Counters counters_of(const ccc::CacheStats& s) {
  return {{"hits", s.hits}, {"misses", s.misses}, {"prefetches", s.prefetches}};
}

class GoldenEngine : public Engine {
 public:
  GoldenEngine(std::shared_ptr<const ccc::Texture> texture, bool lookahead)
      : texture_(std::move(texture)), lookahead_(lookahead) {}
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(count_samples(items));
    const auto start = std::chrono::steady_clock::now();
    const ccc::Texture& tex = *texture_;
    ccc::CacheBilinearUnit unit(tex.width, tex.height, lookahead_,
                                [&tex](uint32_t address) { return tex.blocks.at(address); });
    try {
      for (const Txn& t : items) {
        if (t.f[kBilOp] == kBilOpClutWrite) {
          unit.write_clut(static_cast<uint8_t>(t.f[kBilClutAddr]),
                          static_cast<uint32_t>(t.f[kBilClutRgb]));
        } else {
          Txn out;
          out.f[0] = unit.sample(bilinear_coord(t.f[kBilU]), bilinear_coord(t.f[kBilV]));
          r.outputs.push_back(out);
        }
      }
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    r.counters = counters_of(unit.stats());
    return r;
  }

 private:
  std::shared_ptr<const ccc::Texture> texture_;
  bool lookahead_;
};

// The hls module with its signals and the texture memory, driven by the harness's ScDriver.
class HlsBench : public sc_core::sc_module, public ScAdapter {
 public:
  HlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
           std::shared_ptr<const ccc::Texture> texture, bool lookahead, uint64_t memory_seed)
      : sc_module(name),
        dut_("dut"),
        width_(texture->width),
        height_(texture->height),
        lookahead_(lookahead),
        memory_(std::move(texture), memory_seed) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.cfg_width_i(cfg_width_);
    dut_.cfg_height_i(cfg_height_);
    dut_.cfg_lookahead_i(cfg_lookahead_);
    dut_.clut_valid_i(clut_valid_);
    dut_.clut_ready_o(clut_ready_);
    dut_.clut_addr_i(clut_addr_);
    dut_.clut_rgb_i(clut_rgb_);
    dut_.req_valid_i(req_valid_);
    dut_.req_ready_o(req_ready_);
    dut_.req_u_i(req_u_);
    dut_.req_v_i(req_v_);
    dut_.mem_req_valid_o(mem_req_valid_);
    dut_.mem_req_ready_i(mem_req_ready_);
    dut_.mem_req_addr_o(mem_req_addr_);
    dut_.mem_resp_valid_i(mem_resp_valid_);
    dut_.mem_resp_block_i(mem_resp_block_);
    dut_.out_valid_o(out_valid_);
    dut_.out_ready_i(out_ready_);
    dut_.out_rgb_o(out_rgb_);
    dut_.stat_hits_o(stat_hits_);
    dut_.stat_misses_o(stat_misses_);
    dut_.stat_prefetches_o(stat_prefetches_);
  }
  void drive(const Txn* item) override {
    const bool write = item && item->f[kBilOp] == kBilOpClutWrite;
    const bool sample = item && item->f[kBilOp] == kBilOpSample;
    clut_valid_.write(write);
    clut_addr_.write(write ? item->f[kBilClutAddr] : 0);
    clut_rgb_.write(write ? item->f[kBilClutRgb] : 0);
    req_valid_.write(sample);
    req_u_.write(sample ? bilinear_coord(item->f[kBilU]) : 0);
    req_v_.write(sample ? bilinear_coord(item->f[kBilV]) : 0);
  }
  bool accepts(const Txn& item) const override {
    return item.f[kBilOp] == kBilOpClutWrite ? clut_ready_.read() : req_ready_.read();
  }
  void set_out_ready(bool ready) override { out_ready_.write(ready); }
  bool out_valid() const override { return out_valid_.read(); }
  Txn out() const override {
    Txn t;
    t.f[0] = out_rgb_.read();
    return t;
  }
  void env_drive() override {
    cfg_width_.write(width_);
    cfg_height_.write(height_);
    cfg_lookahead_.write(lookahead_);
    const TextureMemory::Inputs in = memory_.drive();
    mem_req_ready_.write(in.req_ready);
    mem_resp_valid_.write(in.resp_valid);
    mem_resp_block_.write(in.resp_block);
  }
  void env_sample() override {
    memory_.sample(mem_req_valid_.read(), static_cast<uint32_t>(mem_req_addr_.read()));
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters() const override {
    return {{"hits", stat_hits_.read()},
            {"misses", stat_misses_.read()},
            {"prefetches", stat_prefetches_.read()}};
  }

 private:
  template <int W>
  using sig = sc_core::sc_signal<sc_dt::sc_uint<W>>;
  using coord_sig = sc_core::sc_signal<sc_dt::sc_int<fmts::kTexCoord.width()>>;
  using Dut = hls::CccCacheBilinearSc;

  Dut dut_;
  uint32_t width_, height_;
  bool lookahead_;
  TextureMemory memory_;
  sig<fmts::kTexSize.width()> cfg_width_{"cfg_width"}, cfg_height_{"cfg_height"};
  sc_core::sc_signal<bool> cfg_lookahead_{"cfg_lookahead"};
  sc_core::sc_signal<bool> clut_valid_{"clut_valid"}, clut_ready_{"clut_ready"};
  sig<fmts::kClutIndex.width()> clut_addr_{"clut_addr"};
  sig<fmts::kRgb888.width()> clut_rgb_{"clut_rgb"};
  sc_core::sc_signal<bool> req_valid_{"req_valid"}, req_ready_{"req_ready"};
  coord_sig req_u_{"req_u"}, req_v_{"req_v"};
  sc_core::sc_signal<bool> mem_req_valid_{"mem_req_valid"}, mem_req_ready_{"mem_req_ready"};
  sig<fmts::kCccBlockAddr.width()> mem_req_addr_{"mem_req_addr"};
  sc_core::sc_signal<bool> mem_resp_valid_{"mem_resp_valid"};
  sig<fmts::kCccBlock.width()> mem_resp_block_{"mem_resp_block"};
  sc_core::sc_signal<bool> out_valid_{"out_valid"}, out_ready_{"out_ready"};
  sig<fmts::kRgb888.width()> out_rgb_{"out_rgb"};
  sig<Dut::kStatWidth> stat_hits_{"stat_hits"}, stat_misses_{"stat_misses"},
      stat_prefetches_{"stat_prefetches"};
};

class HlsEngine : public Engine {
 public:
  HlsEngine(std::shared_ptr<const ccc::Texture> texture, bool lookahead)
      : texture_(std::move(texture)), lookahead_(lookahead) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<HlsBench>(
        [&](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<HlsBench>("bench", clk, rst_n, texture_, lookahead_,
                                            options.stalls.seed ^ kTextureMemorySeedSalt);
        },
        items, count_samples(items), options);
  }

 private:
  std::shared_ptr<const ccc::Texture> texture_;
  bool lookahead_;
};

// The unclamped footprint origin floor(c - 0.5) of a raw coordinate.
int64_t footprint_origin(int32_t raw) { return (int64_t{raw} - kOne / 2) >> kFrac; }

}  // namespace

// ---- Items and textures ------------------------------------------------------------------

int32_t bilinear_coord(uint64_t field) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & ((uint64_t{1} << fmts::kTexCoord.width()) - 1)),
              fmts::kTexCoord, fx::Overflow::kWrap));
}

Txn bilinear_sample_item(int32_t u_raw, int32_t v_raw) {
  Txn t;
  t.f[kBilOp] = kBilOpSample;
  t.f[kBilU] = static_cast<uint32_t>(u_raw);
  t.f[kBilV] = static_cast<uint32_t>(v_raw);
  return kInputs.masked(t);
}

Txn bilinear_clut_item(uint8_t index, uint32_t rgb) {
  Txn t;
  t.f[kBilOp] = kBilOpClutWrite;
  t.f[kBilClutAddr] = index;
  t.f[kBilClutRgb] = rgb & 0xFFFFFFu;
  return t;
}

std::vector<Txn> bilinear_clut_load(const ccc::Texture& tex) {
  std::vector<Txn> items;
  for (size_t i = 0; i < tex.clut.size(); ++i) {
    items.push_back(bilinear_clut_item(static_cast<uint8_t>(i), pack_rgb(tex.clut[i])));
  }
  return items;
}

std::vector<Txn> bilinear_resample_items(const ccc::Texture& tex, uint32_t out_w, uint32_t out_h) {
  std::vector<Txn> items = bilinear_clut_load(tex);
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

ccc::Texture random_bilinear_texture(uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0xB11E'7E57'0000'0001ull);
  auto side = [&rng]() -> uint32_t {
    const uint64_t r = rng() % 16;
    if (r == 0) return 1;                                             // a one-texel side
    if (r == 1) return static_cast<uint32_t>(uniform(rng, 81, 300));  // now and then bigger
    return static_cast<uint32_t>(uniform(rng, 1, 80));
  };
  ccc::Texture tex;
  tex.width = side();
  tex.height = side();
  for (Rgb8& c : tex.clut) c = unpack_rgb(static_cast<uint32_t>(rng()));
  tex.blocks.resize(size_t{tex.blocks_wide()} * tex.blocks_high());
  for (uint32_t& w : tex.blocks) w = static_cast<uint32_t>(rng());
  return tex;
}

// ---- The texture memory ------------------------------------------------------------------

TextureMemory::TextureMemory(std::shared_ptr<const ccc::Texture> texture, uint64_t seed)
    : texture_(std::move(texture)), rng_(seed) {}

TextureMemory::Inputs TextureMemory::drive() {
  if (!drawn_) {
    const uint64_t r = draw();
    now_.req_ready = r % 100 < 80;
    now_.resp_valid = pending_ && due_cycle_ == cycle_;
    // Garbage while not valid: a unit that samples the bus at the wrong time fails.
    now_.resp_block = now_.resp_valid ? pending_word_ : static_cast<uint32_t>(r >> 32);
    drawn_ = true;
  }
  return now_;
}

void TextureMemory::sample(bool req_valid, uint32_t address) {
  drive();  // this cycle's values, if nobody asked yet
  if (now_.resp_valid) pending_ = false;
  if (req_valid && now_.req_ready) {
    if (pending_ && error_.empty()) {
      error_ =
          fmt::format("texture memory: request for block {} at cycle {} while one is outstanding",
                      address, cycle_);
    }
    ++reads_;
    pending_ = true;
    due_cycle_ = cycle_ + 1 + draw() % 6;
    if (address < texture_->blocks.size()) {
      pending_word_ = texture_->blocks[address];
    } else {
      pending_word_ = kPoison;
      if (error_.empty()) {
        error_ = fmt::format(
            "texture memory: read of block {} at cycle {}, beyond the texture's {} blocks", address,
            cycle_, texture_->blocks.size());
      }
    }
  }
  ++cycle_;
  drawn_ = false;
}

// ---- The block ---------------------------------------------------------------------------

CccBilinearBlock::CccBilinearBlock(const BlockOptions& options)
    : options_(options), lookahead_(options.lookahead) {
  if (options.texture.empty()) {
    texture_ = std::make_shared<const ccc::Texture>(random_bilinear_texture(options.seed));
  } else {
    ccc::Texture tex = ccc::read_ccc(options.texture);
    for (const auto& [field, size] :
         {std::pair<const char*, uint32_t>{"width", tex.width}, {"height", tex.height}}) {
      if (size < 1 || size > static_cast<uint32_t>(fmts::kMaxTexSize)) {
        throw InputError(options.texture, field,
                         fmt::format("{} texels; the unit takes 1..{}", size, fmts::kMaxTexSize));
      }
    }
    texture_ = std::make_shared<const ccc::Texture>(std::move(tex));
  }
}

CccBilinearBlock::CccBilinearBlock(const BlockOptions& options,
                                   std::shared_ptr<const ccc::Texture> texture)
    : options_(options), texture_(std::move(texture)), lookahead_(options.lookahead) {}

const Schema& CccBilinearBlock::inputs() const { return kInputs; }
const Schema& CccBilinearBlock::outputs() const { return kOutputs; }

std::string CccBilinearBlock::repro_options() const {
  std::string out;
  if (!options_.texture.empty()) out += "--texture " + options_.texture;
  if (!lookahead_) out += std::string(out.empty() ? "" : " ") + "--no-lookahead";
  return out;
}

std::vector<Txn> CccBilinearBlock::setup_items() const { return bilinear_clut_load(*texture_); }

std::vector<Txn> CccBilinearBlock::directed_items() const {
  const ccc::Texture& tex = *texture_;
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
  items.push_back(bilinear_clut_item(index, ~colour));
  at(0.5, 0.5);
  at(1.0, 1.0);
  items.push_back(bilinear_clut_item(index, colour));
  items.push_back(bilinear_clut_item(index, colour));  // back to back
  at(1.0, 1.0);
  return items;
}

std::vector<Txn> CccBilinearBlock::random_items(std::mt19937_64& rng, size_t count) const {
  const int64_t w = texture_->width, h = texture_->height;
  std::vector<Txn> items;
  items.reserve(count);
  auto push = [&](int64_t u, int64_t v) {
    items.push_back(
        bilinear_sample_item(static_cast<int32_t>(std::clamp<int64_t>(u, kCoordMin, kCoordMax)),
                             static_cast<int32_t>(std::clamp<int64_t>(v, kCoordMin, kCoordMax))));
  };
  while (items.size() < count) {
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

std::unique_ptr<Engine> CccBilinearBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<GoldenEngine>(texture_, lookahead_);
  if (level == "hls") return std::make_unique<HlsEngine>(texture_, lookahead_);
  if (level == "rtl")
    return make_ccc_bilinear_rtl_engine<Vtmu_ccc_cache_bilinear>("rtl", texture_, lookahead_);
  throw std::invalid_argument("ccc-bilinear: no engine '" + level + "' (golden, hls, rtl)");
}

std::vector<std::string> CccBilinearBlock::coverage_cases() const {
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
          "negative coordinate",
          "coordinate beyond the texture"};
}

void CccBilinearBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                             Coverage& cov) const {
  const Txn& t = items[index];
  const uint32_t w = texture_->width, h = texture_->height;
  const int32_t u = bilinear_coord(t.f[kBilU]), v = bilinear_coord(t.f[kBilV]);
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
  if (index > 0 && items[index - 1].f[kBilOp] == kBilOpClutWrite)
    ++cov["sample right after a CLUT write"];
  if (u < 0 || v < 0) ++cov["negative coordinate"];
  if (int64_t{u} >= int64_t{w} * kOne || int64_t{v} >= int64_t{h} * kOne) {
    ++cov["coordinate beyond the texture"];
  }
}

std::vector<Port> CccBilinearBlock::ports() const {
  return {{"clk_i"},
          {"rst_ni"},
          {"cfg_width_i", fmts::kTexSize.width()},
          {"cfg_height_i", fmts::kTexSize.width()},
          {"cfg_lookahead_i"},
          {"clut_valid_i"},
          {"clut_ready_o"},
          {"clut_addr_i", fmts::kClutIndex.width()},
          {"clut_rgb_i", fmts::kRgb888.width()},
          {"req_valid_i"},
          {"req_ready_o"},
          {"req_u_i", fmts::kTexCoord.width(), true},
          {"req_v_i", fmts::kTexCoord.width(), true},
          {"mem_req_valid_o"},
          {"mem_req_ready_i"},
          {"mem_req_addr_o", fmts::kCccBlockAddr.width()},
          {"mem_resp_valid_i"},
          {"mem_resp_block_i", fmts::kCccBlock.width()},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_rgb_o", fmts::kRgb888.width()},
          {"stat_hits_o", 32},
          {"stat_misses_o", 32},
          {"stat_prefetches_o", 32}};
}

}  // namespace tmu::tb
