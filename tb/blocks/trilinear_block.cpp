#include "blocks/trilinear_block.hpp"

#if TMU_RTL_THREADS
#include <Vtmu_trilinear_threads.h>
#endif
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <trilinear_variants.hpp>

#include "common/error.hpp"
#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/texram/trilinear_sc.hpp"
#include "texram/trilinear.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;

namespace {

const Schema kInputs({{"op", fx::UQ(1, 0)},
                      {"u", fmts::kTexCoord},
                      {"v", fmts::kTexCoord},
                      {"lambda", fmts::kLod},
                      {"shade", fmts::kRgba8888},
                      {"clut_addr", fmts::kClutIndex},
                      {"clut_rgba", fmts::kRgba8888}});
const Schema kOutputs({{"rgba", fmts::kRgba8888}});

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel (or one level) in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kLodMin = static_cast<int32_t>(fmts::kLod.min_raw());
constexpr int32_t kLodMax = static_cast<int32_t>(fmts::kLod.max_raw());
static_assert(fmts::kLod.frac_bits == kFrac);

size_t count_samples(const std::vector<Txn>& items) {
  size_t n = 0;
  for (const Txn& t : items) n += t.f[kTriOp] == kTriOpSample;
  return n;
}

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions, so
// the stimulus is the same on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

int32_t clamp_coord(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kCoordMin, kCoordMax));
}
int32_t clamp_lod(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kLodMin, kLodMax));
}

bool four_planes(texram::TexelKind k) {
  return k == texram::TexelKind::kTrueColour || k == texram::TexelKind::kCcc;
}

bool any_read(const std::array<std::optional<uint32_t>, 8>& a) {
  return std::any_of(a.begin(), a.end(), [](const auto& x) { return x.has_value(); });
}

// The accesses of a sample: one per byte plane at address + plane; none if nothing is read.
template <class Access>
void for_each_access(const std::array<std::optional<uint32_t>, 8>& addresses, int planes,
                     Access&& access) {
  if (!any_read(addresses)) return;
  for (int p = 0; p < planes; ++p) {
    std::array<std::optional<uint32_t>, 8> a;
    for (size_t b = 0; b < 8; ++b) {
      if (addresses[b]) a[b] = *addresses[b] + static_cast<uint32_t>(p);
    }
    access(a);
  }
}

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }

// ---- Environment -------------------------------------------------------------------------

texram::Pyramid8 random_pyramid(std::mt19937_64& rng, uint32_t w, uint32_t h) {
  texram::Pyramid8 p;
  const int levels = std::max(std::countr_zero(w), std::countr_zero(h)) + 1;
  for (int l = 0; l < levels; ++l) {
    texram::Level8 level(std::max(w >> l, 1u), std::max(h >> l, 1u));
    for (uint8_t& t : level.texels) t = static_cast<uint8_t>(rng() >> 56);
    p.push_back(std::move(level));
  }
  return p;
}

// Random bytes everywhere: every level independent, a random CLUT (random alpha too).
texram::TexramTexture random_texture(texram::TexelKind kind, int log2_w, int log2_h,
                                     uint64_t seed) {
  std::mt19937_64 rng(seed);
  const uint32_t w = 1u << log2_w, h = 1u << log2_h;
  if (kind == texram::TexelKind::kCcc) {
    ccc::Clut clut{};
    for (Rgb8& c : clut) c = unpack_rgb(static_cast<uint32_t>(rng()));
    std::vector<ccc::Texture> levels;
    for (int l = 0; l <= std::max(log2_w, log2_h); ++l) {
      ccc::Texture t;
      t.width = std::max(w >> l, 1u);
      t.height = std::max(h >> l, 1u);
      t.clut = clut;
      t.blocks.resize(size_t{t.blocks_wide()} * t.blocks_high());
      for (uint32_t& b : t.blocks) b = static_cast<uint32_t>(rng());
      levels.push_back(std::move(t));
    }
    return texram::texture_from_ccc(levels);
  }
  std::vector<texram::Pyramid8> planes;
  for (int p = 0; p < (four_planes(kind) ? fmts::kPlanes : 1); ++p) {
    planes.push_back(random_pyramid(rng, w, h));
  }
  texram::Clut32 clut{};
  for (uint32_t& c : clut) c = static_cast<uint32_t>(rng());
  return texram::texture_from_planes(kind, planes, clut);
}

ImageRgb8 pattern_image(const std::string& pattern, int w, int h, uint32_t seed) {
  if (pattern == "gradient") return patterns::gradient(w, h);
  if (pattern == "checker") {
    return patterns::checker(w, h, std::max(1, std::min(w, h) / 4), {250, 20, 30}, {10, 40, 220});
  }
  if (pattern == "noise") return patterns::noise(w, h, seed);
  if (pattern == "smooth") return patterns::smooth_field(w, h, seed);
  throw std::invalid_argument("trilinear: unknown pattern '" + pattern +
                              "' (gradient, checker, noise, smooth, random)");
}

// log2 of a side drawn from the seed: 0 (a one-texel side) now and then, else 1..8.
int draw_log2_side(std::mt19937_64& rng) {
  return rng() % 8 == 0 ? 0 : static_cast<int>(uniform(rng, 1, 8));
}

constexpr const char* kPatterns[] = {"gradient", "checker", "noise", "smooth", "random", "random"};

}  // namespace

TrilinearEnv make_trilinear_env(const BlockOptions& o) {
  // Every draw is made whether or not it is overridden, so an override changes nothing else.
  std::mt19937_64 rng(o.seed ^ 0x7E1A'B10C'0000'0001ull);
  texram::SamplerConfig c;
  c.kind = static_cast<texram::TexelKind>(rng() % 5);
  const int log2_w = draw_log2_side(rng);
  const int log2_h = rng() % 3 == 0 ? log2_w : draw_log2_side(rng);
  std::string pattern = kPatterns[rng() % 6];
  c.single_channel = static_cast<int>(rng() % 4);
  c.filter = static_cast<texram::Filter>(rng() % 3);
  c.border_u = static_cast<texram::Border>(rng() % 4);
  c.border_v = rng() % 3 == 0 ? c.border_u : static_cast<texram::Border>(rng() % 4);
  c.border_rgba = static_cast<uint32_t>(rng());
  c.combine = static_cast<texram::Combine>(rng() % 3);
  c.constant_rgba = static_cast<uint32_t>(rng());
  const uint64_t content_seed = rng();

  if (o.tri_kind) c.kind = *o.tri_kind;
  if (o.tri_single_channel) c.single_channel = *o.tri_single_channel;
  if (o.tri_filter) c.filter = *o.tri_filter;
  if (o.tri_border_u) c.border_u = *o.tri_border_u;
  if (o.tri_border_v) c.border_v = *o.tri_border_v;
  if (o.tri_border_rgba) c.border_rgba = *o.tri_border_rgba;
  if (o.tri_combine) c.combine = *o.tri_combine;
  if (o.tri_constant_rgba) c.constant_rgba = *o.tri_constant_rgba;
  if (!o.tri_pattern.empty()) pattern = o.tri_pattern;
  c.widths = o.tri_widths;
  for (int b : {c.widths.sub_texel, c.widths.weight, c.widths.lod_frac}) {
    if (b < 1 || b > 8) throw std::invalid_argument("trilinear: widths must be 1..8 bits");
  }
  if (c.single_channel < 0 || c.single_channel > 3) {
    throw std::invalid_argument("trilinear: the single channel must be 0..3");
  }
  auto side = [](const std::optional<int>& set, int drawn) {
    const int v = set.value_or(drawn);
    if (v < 0 || v > fmts::kMaxMipLog2) {
      throw std::invalid_argument(
          fmt::format("trilinear: log2 of a side must be 0..{}", fmts::kMaxMipLog2));
    }
    return v;
  };

  TrilinearEnv env;
  env.config = c;
  if (!o.tri_image.empty()) {
    const ImageRgb8 image = read_image(o.tri_image);
    try {
      env.texture = std::make_shared<const texram::TexramTexture>(
          texram::import_image(image, c.kind, c.single_channel));
    } catch (const std::invalid_argument& e) {
      throw InputError(o.tri_image, "size", e.what());
    }
    env.content = o.tri_image;
    return env;
  }
  const int lw = side(o.tri_log2_w, log2_w), lh = side(o.tri_log2_h, log2_h);
  if (pattern == "random") {
    env.texture =
        std::make_shared<const texram::TexramTexture>(random_texture(c.kind, lw, lh, content_seed));
    env.content = "random bytes";
  } else {
    const ImageRgb8 image =
        pattern_image(pattern, 1 << lw, 1 << lh, static_cast<uint32_t>(content_seed));
    env.texture = std::make_shared<const texram::TexramTexture>(
        texram::import_image(image, c.kind, c.single_channel));
    env.content = pattern;
  }
  return env;
}

// ---- Items -------------------------------------------------------------------------------

int32_t trilinear_coord(uint64_t field) {
  return static_cast<int32_t>(fx::fit(static_cast<int64_t>(field & low_bits(fmts::kTexCoord)),
                                      fmts::kTexCoord, fx::Overflow::kWrap));
}

int32_t trilinear_lambda(uint64_t field) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & low_bits(fmts::kLod)), fmts::kLod, fx::Overflow::kWrap));
}

texram::Request trilinear_request(const Txn& t) {
  return {trilinear_coord(t.f[kTriU]), trilinear_coord(t.f[kTriV]),
          trilinear_lambda(t.f[kTriLambda]), static_cast<uint32_t>(t.f[kTriShade])};
}

Txn trilinear_sample_item(int32_t u_raw, int32_t v_raw, int32_t lambda_raw, uint32_t shade) {
  Txn t;
  t.f[kTriOp] = kTriOpSample;
  t.f[kTriU] = static_cast<uint32_t>(u_raw);
  t.f[kTriV] = static_cast<uint32_t>(v_raw);
  t.f[kTriLambda] = static_cast<uint32_t>(lambda_raw);
  t.f[kTriShade] = shade;
  return kInputs.masked(t);
}

Txn trilinear_clut_item(uint8_t index, uint32_t rgba) {
  Txn t;
  t.f[kTriOp] = kTriOpClutWrite;
  t.f[kTriClutAddr] = index;
  t.f[kTriClutRgba] = rgba;
  return t;
}

std::vector<Txn> trilinear_clut_load(const texram::TexramTexture& texture) {
  std::vector<Txn> items;
  for (size_t i = 0; i < texture.clut.size(); ++i) {
    items.push_back(trilinear_clut_item(static_cast<uint8_t>(i), texture.clut[i]));
  }
  return items;
}

// ---- Memory ------------------------------------------------------------------------------

int TexramAccessLog::access(const std::array<std::optional<uint32_t>, 8>& addresses) {
  constexpr uint64_t kPrime = 0x0000'0100'0000'01B3ull;  // FNV-1a
  for (uint64_t b = 0; b < 8; ++b) {
    if (!addresses[b]) continue;
    hash_ = (hash_ ^ ((b << 32) | *addresses[b])) * kPrime;
  }
  hash_ = (hash_ ^ 0xFFFF'FFFF'FFFF'FFFFull) * kPrime;  // end of the access
  return pages_.access(addresses);
}

void TexramAccessLog::sample(const std::array<std::optional<uint32_t>, 8>& addresses, int planes) {
  for_each_access(addresses, planes, [this](const auto& a) { access(a); });
}

Counters TexramAccessLog::counters() const {
  const texram::PageStats& s = pages_.stats();
  return {{"accesses", s.accesses},
          {"bank_reads", s.bank_reads},
          {"page_faults", s.page_faults},
          {"slow_accesses", s.slow_accesses},
          {"address_hash", hash_}};
}

TexramMemory::TexramMemory(std::shared_ptr<const texram::TexramTexture> texture, uint64_t seed)
    : texture_(std::move(texture)), rng_(seed) {}

TexramMemory::Inputs TexramMemory::drive() {
  if (!drawn_) {
    now_.req_ready = cycle_ >= busy_until_;
    now_.resp_valid = !responses_.empty() && responses_.front().due_cycle == cycle_;
    // Garbage while not valid: a unit that samples the bus at the wrong time fails.
    now_.resp_data = now_.resp_valid ? responses_.front().data : rng_();
    drawn_ = true;
  }
  return now_;
}

void TexramMemory::sample(bool req_valid, uint32_t enables,
                          const std::array<uint32_t, 8>& addresses) {
  drive();  // this cycle's values, if nobody asked yet
  if (now_.resp_valid) responses_.pop_front();
  if (req_valid && now_.req_ready) {
    if ((enables & 0xFFu) == 0 && error_.empty()) {
      error_ = fmt::format("texram memory: the access at cycle {} reads no bank", cycle_);
    }
    std::array<std::optional<uint32_t>, 8> read;
    uint64_t data = rng_();  // banks not read deliver garbage
    for (size_t b = 0; b < 8; ++b) {
      if (((enables >> b) & 1u) == 0) continue;
      read[b] = addresses[b];
      const std::vector<uint8_t>& bank = texture_->banks[b];
      uint8_t byte = kPoison;
      if (addresses[b] < bank.size()) {
        byte = bank[addresses[b]];
      } else if (error_.empty()) {
        error_ =
            fmt::format("texram memory: read of bank {} cell {} at cycle {}, beyond its {} cells",
                        b, addresses[b], cycle_, bank.size());
      }
      data = (data & ~(uint64_t{0xFF} << (8 * b))) | (uint64_t{byte} << (8 * b));
    }
    const int periods = log_.access(read);
    busy_until_ = cycle_ + static_cast<uint64_t>(periods);
    responses_.push_back({cycle_ + static_cast<uint64_t>(periods), data});
  }
  ++cycle_;
  drawn_ = false;
}

namespace {

// ---- Engines -----------------------------------------------------------------------------

class GoldenEngine : public Engine {
 public:
  explicit GoldenEngine(TrilinearEnv env) : env_(std::move(env)) {}
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(count_samples(items));
    texram::TexramTexture texture = *env_.texture;  // CLUT writes change its CLUT
    TexramAccessLog log;
    const auto start = std::chrono::steady_clock::now();
    try {
      for (const Txn& t : items) {
        if (t.f[kTriOp] == kTriOpClutWrite) {
          texture.clut[static_cast<uint8_t>(t.f[kTriClutAddr])] =
              static_cast<uint32_t>(t.f[kTriClutRgba]);
          continue;
        }
        texram::SamplePlan plan;
        Txn out;
        out.f[0] = texram::sample(texture, env_.config, trilinear_request(t), &plan);
        r.outputs.push_back(out);
        log.sample(plan.bank_address, plan.planes);
      }
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    r.counters = log.counters();
    return r;
  }

 private:
  TrilinearEnv env_;
};

// The hls module with its signals and the memory, driven by the harness's ScDriver.
class HlsBench : public sc_core::sc_module, public ScAdapter {
 public:
  HlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
           TrilinearEnv env, uint64_t memory_seed)
      : sc_module(name),
        dut_("dut", env.config.widths),
        env_(env),
        memory_(env.texture, memory_seed) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.cfg_log2_w_i(cfg_log2_w_);
    dut_.cfg_log2_h_i(cfg_log2_h_);
    dut_.cfg_kind_i(cfg_kind_);
    dut_.cfg_single_channel_i(cfg_single_channel_);
    dut_.cfg_filter_i(cfg_filter_);
    dut_.cfg_border_u_i(cfg_border_u_);
    dut_.cfg_border_v_i(cfg_border_v_);
    dut_.cfg_border_rgba_i(cfg_border_rgba_);
    dut_.cfg_combine_i(cfg_combine_);
    dut_.cfg_constant_rgba_i(cfg_constant_rgba_);
    dut_.clut_valid_i(clut_valid_);
    dut_.clut_ready_o(clut_ready_);
    dut_.clut_addr_i(clut_addr_);
    dut_.clut_rgba_i(clut_rgba_);
    dut_.req_valid_i(req_valid_);
    dut_.req_ready_o(req_ready_);
    dut_.req_u_i(req_u_);
    dut_.req_v_i(req_v_);
    dut_.req_lambda_i(req_lambda_);
    dut_.req_shade_i(req_shade_);
    dut_.mem_req_valid_o(mem_req_valid_);
    dut_.mem_req_ready_i(mem_req_ready_);
    dut_.mem_req_en_o(mem_req_en_);
    dut_.mem_req_addr_o(mem_req_addr_);
    dut_.mem_resp_valid_i(mem_resp_valid_);
    dut_.mem_resp_data_i(mem_resp_data_);
    dut_.out_valid_o(out_valid_);
    dut_.out_ready_i(out_ready_);
    dut_.out_rgba_o(out_rgba_);
  }
  void drive(const Txn* item) override {
    const bool write = item && item->f[kTriOp] == kTriOpClutWrite;
    const bool sample = item && item->f[kTriOp] == kTriOpSample;
    clut_valid_.write(write);
    clut_addr_.write(write ? item->f[kTriClutAddr] : 0);
    clut_rgba_.write(write ? item->f[kTriClutRgba] : 0);
    req_valid_.write(sample);
    req_u_.write(sample ? trilinear_coord(item->f[kTriU]) : 0);
    req_v_.write(sample ? trilinear_coord(item->f[kTriV]) : 0);
    req_lambda_.write(sample ? trilinear_lambda(item->f[kTriLambda]) : 0);
    req_shade_.write(sample ? item->f[kTriShade] : 0);
  }
  bool accepts(const Txn& item) const override {
    return item.f[kTriOp] == kTriOpClutWrite ? clut_ready_.read() : req_ready_.read();
  }
  void set_out_ready(bool ready) override { out_ready_.write(ready); }
  bool out_valid() const override { return out_valid_.read(); }
  Txn out() const override {
    Txn t;
    t.f[0] = out_rgba_.read();
    return t;
  }
  void env_drive() override {
    const texram::SamplerConfig& c = env_.config;
    const texram::Geometry& g = env_.texture->geometry;
    cfg_log2_w_.write(static_cast<unsigned>(g.log2_width()));
    cfg_log2_h_.write(static_cast<unsigned>(g.log2_height()));
    cfg_kind_.write(static_cast<unsigned>(c.kind));
    cfg_single_channel_.write(static_cast<unsigned>(c.single_channel));
    cfg_filter_.write(static_cast<unsigned>(c.filter));
    cfg_border_u_.write(static_cast<unsigned>(c.border_u));
    cfg_border_v_.write(static_cast<unsigned>(c.border_v));
    cfg_border_rgba_.write(c.border_rgba);
    cfg_combine_.write(static_cast<unsigned>(c.combine));
    cfg_constant_rgba_.write(c.constant_rgba);
    const TexramMemory::Inputs in = memory_.drive();
    mem_req_ready_.write(in.req_ready);
    mem_resp_valid_.write(in.resp_valid);
    mem_resp_data_.write(in.resp_data);
  }
  void env_sample() override {
    constexpr int kW = Dut::kAddrWidth;
    std::array<uint32_t, 8> addresses{};
    const auto bus = mem_req_addr_.read();
    for (int b = 0; b < 8; ++b) {
      addresses[static_cast<size_t>(b)] =
          static_cast<uint32_t>(bus.range((b + 1) * kW - 1, b * kW).to_uint());
    }
    memory_.sample(mem_req_valid_.read(), static_cast<uint32_t>(mem_req_en_.read()), addresses);
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters() const override { return memory_.counters(); }

 private:
  template <int W>
  using sig = sc_core::sc_signal<sc_dt::sc_uint<W>>;
  template <int W>
  using ssig = sc_core::sc_signal<sc_dt::sc_int<W>>;
  using Dut = hls::TrilinearSc;

  Dut dut_;
  TrilinearEnv env_;
  TexramMemory memory_;
  sig<fmts::kMipLog2.width()> cfg_log2_w_{"cfg_log2_w"}, cfg_log2_h_{"cfg_log2_h"};
  sig<fmts::kTexKind.width()> cfg_kind_{"cfg_kind"};
  sig<fmts::kBytePlane.width()> cfg_single_channel_{"cfg_single_channel"};
  sig<fmts::kTexFilter.width()> cfg_filter_{"cfg_filter"};
  sig<fmts::kTexBorder.width()> cfg_border_u_{"cfg_border_u"}, cfg_border_v_{"cfg_border_v"};
  sig<fmts::kRgba8888.width()> cfg_border_rgba_{"cfg_border_rgba"};
  sig<fmts::kTexCombine.width()> cfg_combine_{"cfg_combine"};
  sig<fmts::kRgba8888.width()> cfg_constant_rgba_{"cfg_constant_rgba"};
  sc_core::sc_signal<bool> clut_valid_{"clut_valid"}, clut_ready_{"clut_ready"};
  sig<fmts::kClutIndex.width()> clut_addr_{"clut_addr"};
  sig<fmts::kRgba8888.width()> clut_rgba_{"clut_rgba"};
  sc_core::sc_signal<bool> req_valid_{"req_valid"}, req_ready_{"req_ready"};
  ssig<fmts::kTexCoord.width()> req_u_{"req_u"}, req_v_{"req_v"};
  ssig<fmts::kLod.width()> req_lambda_{"req_lambda"};
  sig<fmts::kRgba8888.width()> req_shade_{"req_shade"};
  sc_core::sc_signal<bool> mem_req_valid_{"mem_req_valid"}, mem_req_ready_{"mem_req_ready"};
  sig<Dut::kBanks> mem_req_en_{"mem_req_en"};
  sc_core::sc_signal<sc_dt::sc_biguint<Dut::kAddrBusWidth>> mem_req_addr_{"mem_req_addr"};
  sc_core::sc_signal<bool> mem_resp_valid_{"mem_resp_valid"};
  sig<Dut::kDataWidth> mem_resp_data_{"mem_resp_data"};
  sc_core::sc_signal<bool> out_valid_{"out_valid"}, out_ready_{"out_ready"};
  sig<fmts::kRgba8888.width()> out_rgba_{"out_rgba"};
};

// The ideal (double precision) sampler on the same requests, rounded to RGBA8888 only so that
// the run has outputs: `texsim levels` times it, nothing compares it.
class IdealEngine : public Engine {
 public:
  explicit IdealEngine(TrilinearEnv env) : env_(std::move(env)) {}
  std::string name() const override { return "ideal"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    texram::TexramTexture texture = *env_.texture;
    const double unit = std::ldexp(1.0, kFrac);
    const auto start = std::chrono::steady_clock::now();
    for (const Txn& t : items) {
      if (t.f[kTriOp] == kTriOpClutWrite) {
        texture.clut[static_cast<uint8_t>(t.f[kTriClutAddr])] =
            static_cast<uint32_t>(t.f[kTriClutRgba]);
        continue;
      }
      const texram::Request q = trilinear_request(t);
      const auto c = texram::ideal_sample(texture, env_.config, q.u / unit, q.v / unit,
                                          q.lambda / unit, q.shade);
      uint64_t rgba = 0;
      for (double channel : c) rgba = rgba << 8 | static_cast<uint64_t>(std::lround(channel));
      Txn out;
      out.f[0] = rgba;
      r.outputs.push_back(out);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }

 private:
  TrilinearEnv env_;
};

class HlsEngine : public Engine {
 public:
  explicit HlsEngine(TrilinearEnv env) : env_(std::move(env)) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<HlsBench>(
        [&](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<HlsBench>("bench", clk, rst_n, env_,
                                            options.stalls.seed ^ kTexramMemorySeedSalt);
        },
        items, count_samples(items), options);
  }

 private:
  TrilinearEnv env_;
};

std::string rgba_text(uint32_t v) { return fmt::format("0x{:08X}", v); }

}  // namespace

// ---- The block ---------------------------------------------------------------------------

TrilinearBlock::TrilinearBlock(const BlockOptions& options)
    : TrilinearBlock(options, make_trilinear_env(options)) {}

TrilinearBlock::TrilinearBlock(const BlockOptions& options, TrilinearEnv env)
    : options_(options), env_(std::move(env)) {}

const Schema& TrilinearBlock::inputs() const { return kInputs; }
const Schema& TrilinearBlock::outputs() const { return kOutputs; }

std::string TrilinearBlock::describe() const {
  const texram::SamplerConfig& c = env_.config;
  const texram::Geometry& g = env_.texture->geometry;
  std::string kind(texram::name(c.kind));
  if (c.kind == texram::TexelKind::kSingle)
    kind += fmt::format(" (channel {})", "RGBA"[c.single_channel]);
  return fmt::format(
      "{} {} x {} ({}), {}, border u {} v {} ({}), combine {}{}, widths {},{},{}", kind,
      g.texel_width(0), g.texel_height(0), env_.content, texram::name(c.filter),
      texram::name(c.border_u), texram::name(c.border_v), rgba_text(c.border_rgba),
      texram::name(c.combine),
      c.combine == texram::Combine::kConstant ? " " + rgba_text(c.constant_rgba) : "",
      c.widths.sub_texel, c.widths.weight, c.widths.lod_frac);
}

std::string TrilinearBlock::repro_options() const {
  const BlockOptions& o = options_;
  std::vector<std::string> parts;
  if (o.tri_kind) parts.push_back(fmt::format("--config {}", texram::name(*o.tri_kind)));
  if (o.tri_single_channel) {
    parts.push_back(fmt::format("--channel {}", "rgba"[*o.tri_single_channel & 3]));
  }
  if (o.tri_filter) parts.push_back(fmt::format("--filter {}", texram::name(*o.tri_filter)));
  if (o.tri_border_u) parts.push_back(fmt::format("--border-u {}", texram::name(*o.tri_border_u)));
  if (o.tri_border_v) parts.push_back(fmt::format("--border-v {}", texram::name(*o.tri_border_v)));
  if (o.tri_border_rgba) parts.push_back("--border-colour " + rgba_text(*o.tri_border_rgba));
  if (o.tri_combine) parts.push_back(fmt::format("--combine {}", texram::name(*o.tri_combine)));
  if (o.tri_constant_rgba) parts.push_back("--constant " + rgba_text(*o.tri_constant_rgba));
  if (o.tri_log2_w) parts.push_back(fmt::format("--log2-w {}", *o.tri_log2_w));
  if (o.tri_log2_h) parts.push_back(fmt::format("--log2-h {}", *o.tri_log2_h));
  if (!o.tri_pattern.empty()) parts.push_back("--pattern " + o.tri_pattern);
  if (!o.tri_image.empty()) parts.push_back("--image " + o.tri_image);
  if (!(o.tri_widths == texram::Widths{})) {
    parts.push_back(fmt::format("--widths {},{},{}", o.tri_widths.sub_texel, o.tri_widths.weight,
                                o.tri_widths.lod_frac));
  }
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : " ") + p;
  return out;
}

std::vector<Txn> TrilinearBlock::setup_items() const { return trilinear_clut_load(*env_.texture); }

std::vector<Txn> TrilinearBlock::directed_items() const {
  const texram::Geometry& g = env_.texture->geometry;
  const int32_t w = static_cast<int32_t>(g.texel_width(0)) * kOne;
  const int32_t h = static_cast<int32_t>(g.texel_height(0)) * kOne;
  const int32_t top = (g.levels() - 1) * kOne;
  std::vector<Txn> items;
  uint32_t shade = 0x80FF'40C0u;
  auto at = [&](int64_t u, int64_t v, int64_t lambda) {
    items.push_back(
        trilinear_sample_item(clamp_coord(u), clamp_coord(v), clamp_lod(lambda), shade));
    shade = shade * 0x9E37'79B1u + 0x7F4A'7C15u;  // a different I_d each time
  };

  // lambda at and beyond both ends, on a texel centre and between texels.
  for (int64_t lambda : std::initializer_list<int64_t>{
           kLodMin, -16 * kOne, -kOne, -1, 0, 1, kOne / 2 - 1, kOne / 2, kOne - 1, kOne,
           top - kOne / 2 - 1, top - kOne / 2, top - 1, top, top + 1, top + kOne / 2, top + kOne,
           top + 5 * kOne, kLodMax}) {
    at(kOne / 2, kOne / 2, lambda);
    at(w / 2 + 77, h / 3 + 201, lambda);
  }
  // Level weights 0, half and max between every pair of levels, and the whole levels.
  for (int64_t l = 0; l <= top; l += kOne) {
    for (int64_t f : {0, 1, kOne / 2, kOne - 1}) at(w / 3 + 13, h / 2 + 99, l + f);
  }
  // Coordinates at the ends of the port format, alone and mixed.
  for (int64_t lambda : {int64_t{0}, int64_t{top / 2}, int64_t{top}}) {
    for (int64_t u : {int64_t{kCoordMin}, int64_t{kCoordMax}, int64_t{0}}) {
      for (int64_t v : {int64_t{kCoordMin}, int64_t{kCoordMax}, int64_t{0}}) at(u, v, lambda);
    }
    at(kCoordMin + 1, kCoordMax - 1, lambda);
    at(kCoordMin + 127, kCoordMin + 129, lambda);
  }
  // Far outside in every direction, and whole periods away (wrap and mirror repeat).
  for (int64_t lambda : {int64_t{-kOne}, int64_t{kOne + 64}}) {
    at(-1000 * kOne - 77, h / 2, lambda);
    at(w + 1000 * kOne + 177, h / 2, lambda);
    at(w / 2, -777 * kOne - 3, lambda);
    at(w / 2, h + 555 * kOne + 200, lambda);
    for (int64_t k : {-3, -2, -1, 1, 2, 3}) {
      at(k * w + kOne / 2 + 40, h / 2 + 30, lambda);
      at(w / 2 + 30, k * h + kOne / 2 + 40, lambda);
      at(k * w + w - kOne / 4, k * h + kOne / 4, lambda);
    }
  }
  // Texel centres at the corners, the edges and one LSB either side of them, at level 0.
  for (int64_t lambda : {int64_t{-kOne}, int64_t{0}}) {
    for (int64_t u : {int64_t{kOne / 2}, int64_t{w - kOne / 2}}) {
      for (int64_t v : {int64_t{kOne / 2}, int64_t{h - kOne / 2}}) at(u, v, lambda);
    }
    for (int64_t d : {-1, 0, 1}) {
      at(d, h / 2 + 5, lambda);
      at(w + d, h / 2 + 5, lambda);
      at(w / 2 + 5, d, lambda);
      at(w / 2 + 5, h + d, lambda);
      at(d, d, lambda);
      at(w + d, h + d, lambda);
    }
  }
  // Sub-texel fractions 0, 1 LSB, half and max after the half-texel offset, per axis and
  // together, at levels 0 and 1.
  for (int64_t level : {0, 1}) {
    const int64_t scale = int64_t{1} << level;
    for (int64_t fx : {0, 1, kOne / 2, kOne - 1}) {
      for (int64_t fy : {0, kOne - 1}) {
        at(scale * (kOne + kOne / 2 + fx), scale * (kOne + kOne / 2 + fy), level * kOne);
      }
    }
  }
  // A CLUT write between samples (index and CCC textures change colour).
  const texram::TexramTexture& tex = *env_.texture;
  for (uint8_t i : {uint8_t{0}, tex.banks[0].empty() ? uint8_t{0} : tex.banks[0][0]}) {
    at(kOne / 2, kOne / 2, 0);
    items.push_back(trilinear_clut_item(i, ~tex.clut[i]));
    at(kOne / 2, kOne / 2, 0);
    at(kOne, kOne, kOne / 2);
    items.push_back(trilinear_clut_item(i, tex.clut[i]));
    items.push_back(trilinear_clut_item(i, tex.clut[i]));  // back to back
    at(kOne / 2, kOne / 2, 0);
  }
  return items;
}

std::vector<Txn> TrilinearBlock::random_items(std::mt19937_64& rng, size_t count) const {
  const texram::Geometry& g = env_.texture->geometry;
  const int64_t w = int64_t{g.texel_width(0)} * kOne, h = int64_t{g.texel_height(0)} * kOne;
  const int64_t top = int64_t{g.levels() - 1} * kOne;
  std::vector<Txn> items;
  items.reserve(count);
  auto push = [&](int64_t u, int64_t v, int64_t lambda, uint32_t shade) {
    items.push_back(
        trilinear_sample_item(clamp_coord(u), clamp_coord(v), clamp_lod(lambda), shade));
  };
  while (items.size() < count) {
    const uint64_t r = rng() % 1000;
    if (r == 0) {  // rarely, a CLUT rewrite
      const uint64_t x = rng();
      items.push_back(trilinear_clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
    } else if (r < 20) {  // anywhere in the port formats
      push(uniform(rng, kCoordMin, kCoordMax), uniform(rng, kCoordMin, kCoordMax),
           uniform(rng, kLodMin, kLodMax), static_cast<uint32_t>(rng()));
    } else if (r < 400) {  // uniform over the texture and around it, lambda around the levels
      const bool near = rng() % 4 != 0;
      push(near ? uniform(rng, -w / 4, w + w / 4) : uniform(rng, -2 * w, 3 * w),
           near ? uniform(rng, -h / 4, h + h / 4) : uniform(rng, -2 * h, 3 * h),
           uniform(rng, -2 * kOne, top + 2 * kOne), static_cast<uint32_t>(rng()));
    } else {
      // A rasterized textured span: rows of steps in u (either direction) of about the
      // footprint 2^lambda, lambda changing slowly along the row, v stepping by about the
      // footprint from row to row, the shade changing slowly: mostly page hits. A row covers
      // about one and a half texture widths at most.
      int64_t lambda = uniform(rng, -kOne, top + kOne / 2);
      const int64_t dlambda = uniform(rng, -3, 3);
      const auto footprint = [&lambda] {  // 2^lambda texels, raw
        return std::max<int64_t>(
            1, static_cast<int64_t>(std::exp2(static_cast<double>(lambda) / kOne) * kOne));
      };
      const int64_t rows = uniform(rng, 1, 4);
      const int64_t per_row = std::clamp<int64_t>((3 * w / 2) / footprint(), 4, 64);
      const int64_t u0 = uniform(rng, 0, w);
      const int64_t sign = rng() % 4 == 0 ? -1 : 1;
      int64_t v = uniform(rng, 0, h);
      uint32_t shade = static_cast<uint32_t>(rng());
      for (int64_t row = 0; row < rows && items.size() < count; ++row) {
        int64_t u = u0 + uniform(rng, -kOne / 2, kOne / 2);
        for (int64_t i = 0; i < per_row && items.size() < count; ++i) {
          push(u, v, lambda, shade);
          u += sign * std::max<int64_t>(footprint() * uniform(rng, 128, 384) / kOne, 1);
          lambda = std::clamp<int64_t>(lambda + dlambda, kLodMin, kLodMax);
          shade += 0x0101'0101u;
        }
        v += footprint();
      }
    }
  }
  return items;
}

std::unique_ptr<Engine> TrilinearBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<GoldenEngine>(env_);
  if (level == "hls") return std::make_unique<HlsEngine>(env_);
  if (level == "rtl") {
    // The Verilated model of these widths (rtl/CMakeLists.txt: TMU_TRILINEAR_VARIANTS).
#define TMU_VARIANT(S, W, L, MODEL)                  \
  if (env_.config.widths == texram::Widths{S, W, L}) \
    return make_trilinear_rtl_engine<MODEL>("rtl", env_);
    TMU_TRILINEAR_VARIANTS(TMU_VARIANT)
#undef TMU_VARIANT
    std::string built;
#define TMU_VARIANT(S, W, L, MODEL) \
  built += (built.empty() ? "" : "; ") + std::string(#S "," #W "," #L);
    TMU_TRILINEAR_VARIANTS(TMU_VARIANT)
#undef TMU_VARIANT
    throw std::invalid_argument(
        "trilinear: no rtl model was verilated at these widths (built: " + built +
        "; add them to TMU_TRILINEAR_VARIANTS in rtl/CMakeLists.txt)");
  }
  if (level == "ideal") return std::make_unique<IdealEngine>(env_);
  if (level == "icarus") {  // docs/harness.md, "Icarus Verilog"
    throw std::invalid_argument(
        "trilinear: not accepted by Icarus 11 (it aborts on a function returning a package "
        "typedef, tmu_pkg::channel_t mul255 in tmu_trilinear_blend.sv)");
  }
#if TMU_RTL_THREADS
  if (level == "rtl-threads" && env_.config.widths == texram::Widths{}) {
    return make_trilinear_rtl_engine<Vtmu_trilinear_threads>("rtl-threads", env_);
  }
#endif
  throw std::invalid_argument("trilinear: no engine '" + level +
                              "' (golden, hls, rtl; ideal; rtl-threads at the default widths)");
}

namespace {

bool has_border(const texram::SamplerConfig& c, texram::Border b) {
  return c.border_u == b || c.border_v == b;
}

bool shares_cells(const texram::SamplerConfig& c) {
  return c.filter != texram::Filter::kNearest &&
         (c.kind == texram::TexelKind::kCcc || has_border(c, texram::Border::kClamp) ||
          has_border(c, texram::Border::kMirror));
}

}  // namespace

std::vector<std::string> TrilinearBlock::coverage_cases() const {
  const texram::SamplerConfig& c = env_.config;
  const texram::Geometry& g = env_.texture->geometry;
  std::vector<std::string> cases = {
      fmt::format("kind {}", texram::name(c.kind)),
      fmt::format("filter {}", texram::name(c.filter)),
      fmt::format("border u {}", texram::name(c.border_u)),
      fmt::format("border v {}", texram::name(c.border_v)),
      fmt::format("combine {}", texram::name(c.combine)),
      fmt::format("texture {} x {}", g.texel_width(0), g.texel_height(0)),
      "lambda < 0 (magnification)",
      "lambda beyond the top level",
      "coordinate outside the texture",
      "access with a page fault",
      "accesses all page hits"};
  if (c.filter == texram::Filter::kTrilinear) {
    cases.push_back("two levels read");
    cases.push_back("between levels, level weight 0");
  }
  if (c.filter != texram::Filter::kNearest) {
    cases.push_back("tap weight 0");
    cases.push_back("tap weight max");
  }
  if (has_border(c, texram::Border::kBorder)) {
    cases.push_back("tap outside (border colour)");
    cases.push_back("every tap outside (no access)");
  }
  if (shares_cells(c)) cases.push_back("taps share a cell");
  if (c.kind == texram::TexelKind::kIndex || c.kind == texram::TexelKind::kCcc) {
    cases.push_back("sample right after a CLUT write");
  }
  return cases;
}

void TrilinearBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                           Coverage& cov) const {
  const texram::SamplerConfig& c = env_.config;
  const texram::Geometry& g = env_.texture->geometry;
  for (const std::string& name :
       {fmt::format("kind {}", texram::name(c.kind)),
        fmt::format("filter {}", texram::name(c.filter)),
        fmt::format("border u {}", texram::name(c.border_u)),
        fmt::format("border v {}", texram::name(c.border_v)),
        fmt::format("combine {}", texram::name(c.combine)),
        fmt::format("texture {} x {}", g.texel_width(0), g.texel_height(0))}) {
    ++cov[name];
  }
  const texram::Request req = trilinear_request(items[index]);
  const int64_t top = int64_t{g.levels() - 1} * kOne;
  if (req.lambda < 0) ++cov["lambda < 0 (magnification)"];
  if (req.lambda > top) ++cov["lambda beyond the top level"];
  if (req.u < 0 || req.v < 0 || req.u >= int64_t{g.texel_width(0)} * kOne ||
      req.v >= int64_t{g.texel_height(0)} * kOne) {
    ++cov["coordinate outside the texture"];
  }

  texram::SamplePlan plan;
  try {
    plan = texram::plan_sample(g, c, req);
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  // Page faults: replay the page model over the samples up to this one.
  CoverState& s = cover_state_;
  if (s.items != &items || index < s.next) s = CoverState{&items, 0, {}};
  for (; s.next < index; ++s.next) {
    if (items[s.next].f[kTriOp] != kTriOpSample) continue;
    try {
      const texram::SamplePlan p = texram::plan_sample(g, c, trilinear_request(items[s.next]));
      for_each_access(p.bank_address, p.planes, [&s](const auto& a) { s.pages.access(a); });
    } catch (const std::exception&) {
    }
  }
  const bool reads = any_read(plan.bank_address);
  const uint64_t faults = s.pages.stats().page_faults;
  for_each_access(plan.bank_address, plan.planes, [&s](const auto& a) { s.pages.access(a); });
  if (reads) {
    ++cov[s.pages.stats().page_faults > faults ? "access with a page fault"
                                               : "accesses all page hits"];
  }
  s.next = index + 1;

  const uint32_t wmax = (1u << c.widths.weight) - 1;
  if (plan.levels_read == 2) ++cov["two levels read"];
  if (plan.trilinear && plan.wl == 0 && req.lambda > 0 && int64_t{req.lambda} < top) {
    ++cov["between levels, level weight 0"];
  }
  if (plan.taps_per_level == 4) {
    if (plan.wx[0] == 0 || plan.wy[0] == 0) ++cov["tap weight 0"];
    if (plan.wx[0] == wmax || plan.wy[0] == wmax) ++cov["tap weight max"];
  }
  int taps = 0, outside = 0;
  for (size_t j = 0; j < static_cast<size_t>(plan.levels_read); ++j) {
    for (size_t k = 0; k < static_cast<size_t>(plan.taps_per_level); ++k) {
      ++taps;
      outside += plan.taps[j][k].outside;
    }
  }
  if (outside > 0) ++cov["tap outside (border colour)"];
  if (!reads) ++cov["every tap outside (no access)"];
  const auto banks = std::count_if(plan.bank_address.begin(), plan.bank_address.end(),
                                   [](const auto& a) { return a.has_value(); });
  if (banks < taps - outside) ++cov["taps share a cell"];
  if (index > 0 && items[index - 1].f[kTriOp] == kTriOpClutWrite) {
    ++cov["sample right after a CLUT write"];
  }
}

std::vector<Port> TrilinearBlock::ports() const {
  constexpr int kAddrBus = fmts::kBanks * fmts::kBankAddr.width();
  return {{"clk_i"},
          {"rst_ni"},
          {"cfg_log2_w_i", fmts::kMipLog2.width()},
          {"cfg_log2_h_i", fmts::kMipLog2.width()},
          {"cfg_kind_i", fmts::kTexKind.width()},
          {"cfg_single_channel_i", fmts::kBytePlane.width()},
          {"cfg_filter_i", fmts::kTexFilter.width()},
          {"cfg_border_u_i", fmts::kTexBorder.width()},
          {"cfg_border_v_i", fmts::kTexBorder.width()},
          {"cfg_border_rgba_i", fmts::kRgba8888.width()},
          {"cfg_combine_i", fmts::kTexCombine.width()},
          {"cfg_constant_rgba_i", fmts::kRgba8888.width()},
          {"clut_valid_i"},
          {"clut_ready_o"},
          {"clut_addr_i", fmts::kClutIndex.width()},
          {"clut_rgba_i", fmts::kRgba8888.width()},
          {"req_valid_i"},
          {"req_ready_o"},
          {"req_u_i", fmts::kTexCoord.width(), true},
          {"req_v_i", fmts::kTexCoord.width(), true},
          {"req_lambda_i", fmts::kLod.width(), true},
          {"req_shade_i", fmts::kRgba8888.width()},
          {"mem_req_valid_o"},
          {"mem_req_ready_i"},
          {"mem_req_en_o", fmts::kBanks},
          {"mem_req_addr_o", kAddrBus},
          {"mem_resp_valid_i"},
          {"mem_resp_data_i", fmts::kBanks * 8},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_rgba_o", fmts::kRgba8888.width()}};
}

}  // namespace tmu::tb
