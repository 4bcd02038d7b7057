#include "blocks/mipgen/mipgen_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/mipgen_sc.hpp"
#include "rtl_models_mipgen.hpp"

TMU_DESCRIBE_SC(mipgen)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::mipgen;

namespace {

constexpr int kMaxLog2 = fmts::kMaxMipLog2;

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions, so the
// stimulus is the same on every standard library).
int uniform(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

// The golden generator, item by item: every write is an output of the item that makes it.
class Golden : public Model {
 public:
  void configure(const Txn& cfg) override { frames_.configure(cfg); }
  void step(const Txn& item, Sink& sink) override {
    writes_.clear();
    frames_.step(item, writes_);
    for (const texram::CellWrite& w : writes_) sink.output(mipgen_write_txn(w));
  }

 private:
  MipgenFrames frames_;
  std::vector<texram::CellWrite> writes_;
};

texram::Level8 filled(uint32_t w, uint32_t h, uint8_t v) {
  texram::Level8 l(w, h);
  std::fill(l.texels.begin(), l.texels.end(), v);
  return l;
}

texram::Level8 random_frame(uint32_t w, uint32_t h, std::mt19937_64& rng) {
  texram::Level8 l(w, h);
  for (uint8_t& t : l.texels) t = static_cast<uint8_t>(rng());
  return l;
}

// The directed formats and their frames: 0 zeros (box sums 0), f 255 (the largest sums), a
// alternating 0 / 255, t rounding ties, r random.
struct DirectedFormat {
  texram::MipgenConfig format;
  const char* frames;
};
const DirectedFormat kDirected[] = {
    {{2, 2, false, 1, 0}, "0fat"},  // 4 x 4, four frames of one format
    {{2, 2, true, 4, 3}, "0fat"},   // the same interlaced, the last plane of four
    {{0, 0, false, 1, 0}, "tr"},    // 1 x 1: level 0 is the top, four replicas a texel
    {{0, 0, true, 1, 0}, "tr"},     // 1 x 1 interlaced: one line, no field 2
    {{0, 1, false, 1, 0}, "tr"},    // 1 x 2: one texel wide, two replicas a texel
    {{1, 1, true, 1, 0}, "tr"},     // 2 x 2 interlaced: one field-2 line
    {{6, 0, true, 4, 1}, "a"},      // an interlaced one-line frame is progressive
    {{6, 1, true, 1, 0}, "t"},      // 64 x 2 interlaced: a field-2 line of 64
    {{5, 2, true, 1, 0}, "t"},      // non-square, wider
    {{2, 5, false, 4, 2}, "t"},     // non-square, higher
    {{0, 6, true, 1, 0}, "t"},      // one texel wide, interlaced
    {{4, 4, true, 1, 0}, "tr"},     // 16 x 16 interlaced
    {{10, 1, false, 4, 1}, "r"},    // 1024 x 2: levels up to 10, the 512-entry line FIFO full
    {{0, 10, true, 1, 0}, "t"},     // 1 x 1024 interlaced: level 10 down a column
};

constexpr const char* kReplicas = "replica writes (level < 2 wide/high)";
constexpr const char* kField2 = "interlaced field-2 item (with above)";
constexpr const char* kOneLine = "interlaced one-line frame (progressive)";
constexpr const char* kTie = "rounding tie (a box mean halfway between two values)";
constexpr const char* kSum0 = "box sum 0";
constexpr const char* kSumMax = "box of all 255 (the largest sum)";
constexpr const char* kFourPlanes = "four-plane texture, plane > 0";
constexpr const char* kLaterFrame = "first texel of a later frame";
constexpr const char* kNewFormat = "first texel after a new format";
constexpr const char* kFrameEnd = "last texel of a frame (top level)";
constexpr const char* kRestart = "first texel after a frame cut short (start)";

std::string level_case(int level) { return fmt::format("writes to level {}", level); }

}  // namespace

// ---- The block ---------------------------------------------------------------------------

MipgenBlock::MipgenBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  const auto check = [](int v, int hi, const char* what) {
    if (v < -1 || v > hi) {
      throw std::invalid_argument(fmt::format("mipgen: {} {} is outside 0..{}", what, v, hi));
    }
  };
  check(options.mip_log2_w, kMaxLog2, "log2 width");
  check(options.mip_log2_h, kMaxLog2, "log2 height");
  check(options.mip_interlaced, 1, "interlaced");
  std::mt19937_64 rng(options.seed ^ 0x3109'6E17'0000'0001ull);
  first_ = draw_format(rng);
  add_level("hls", hls_level<desc::mipgen_sc, hls::MipgenSc>());
  TMU_ADD_RTL_LEVELS(mipgen, variant());
}

texram::MipgenConfig MipgenBlock::fixed(texram::MipgenConfig f) const {
  if (options_.mip_log2_w >= 0) f.log2_w = options_.mip_log2_w;
  if (options_.mip_log2_h >= 0) f.log2_h = options_.mip_log2_h;
  if (options_.mip_interlaced >= 0) f.interlaced = options_.mip_interlaced != 0;
  return f;
}

// Mostly small frames (up to 16 x 16), often one texel wide or high, now and then a
// 1024-texel line, a 512- or 1024-texel column pair, or a frame of 512 to 1024 texels: at most
// 1024 texels, so that a run of a few thousand items sees many formats.
texram::MipgenConfig MipgenBlock::draw_format(std::mt19937_64& rng) const {
  texram::MipgenConfig f;
  const uint64_t r = rng() % 16;
  if (r < 2) {  // one texel wide
    f.log2_w = 0;
    f.log2_h = uniform(rng, 0, 6);
  } else if (r < 4) {  // one line
    f.log2_w = uniform(rng, 0, 6);
    f.log2_h = 0;
  } else if (r == 4) {
    f.log2_w = kMaxLog2;
    f.log2_h = 0;
  } else if (r == 5) {
    f.log2_w = uniform(rng, 0, 1);
    f.log2_h = 9;
  } else if (r == 6) {
    f.log2_w = uniform(rng, 2, 7);
    f.log2_h = uniform(rng, 9, 10) - f.log2_w;
  } else {
    f.log2_w = uniform(rng, 0, 4);
    f.log2_h = uniform(rng, 0, 4);
  }
  f.interlaced = (rng() & 1) != 0;
  f.planes = (rng() & 1) ? fmts::kPlanes : 1;
  f.plane = uniform(rng, 0, f.planes - 1);
  return fixed(f);
}

std::string MipgenBlock::repro_options() const {
  std::string out;
  if (options_.mip_log2_w >= 0) out += fmt::format(" --mip-log2-w {}", options_.mip_log2_w);
  if (options_.mip_log2_h >= 0) out += fmt::format(" --mip-log2-h {}", options_.mip_log2_h);
  if (options_.mip_interlaced >= 0)
    out += fmt::format(" --mip-interlaced {}", options_.mip_interlaced);
  return out.empty() ? out : out.substr(1);
}

std::vector<Txn> MipgenBlock::setup_items() const { return {mipgen_config_item(first_)}; }

std::vector<Txn> MipgenBlock::directed_items() const {
  std::mt19937_64 rng(options_.seed ^ 0x3109'6E17'0000'0002ull);
  std::vector<Txn> items;
  std::vector<std::tuple<int, int, bool>> done;  // the sizes and orders run so far
  for (const DirectedFormat& d : kDirected) {
    const texram::MipgenConfig f = fixed(d.format);
    const auto key = std::tuple{f.log2_w, f.log2_h, f.interlaced};
    if (std::find(done.begin(), done.end(), key) != done.end()) continue;
    done.push_back(key);
    items.push_back(mipgen_config_item(f));
    const uint32_t w = 1u << f.log2_w, h = 1u << f.log2_h;
    for (const char* c = d.frames; *c != '\0'; ++c) {
      texram::Level8 frame(w, h);
      switch (*c) {
        case '0':
          frame = filled(w, h, 0);
          break;
        case 'f':
          frame = filled(w, h, 255);
          break;
        case 'a':
          for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) frame.at(x, y) = ((x + y) & 1u) ? 255 : 0;
          }
          break;
        case 't':
          frame = mipgen_tie_frame(f.log2_w, f.log2_h);
          break;
        default:
          frame = random_frame(w, h, rng);
      }
      for (const Txn& t : mipgen_frame_items(frame, f.interlaced)) items.push_back(t);
    }
  }
  // A frame cut short in the middle of a field-1 line (as the video unit drops one), then a whole
  // frame of the same format: its first texel, marked start, restarts the position at (0, 0).
  const texram::MipgenConfig c = fixed({2, 3, true, 1, 0});
  const uint32_t cw = 1u << c.log2_w, ch = 1u << c.log2_h;
  items.push_back(mipgen_config_item(c));
  std::vector<Txn> cut = mipgen_frame_items(random_frame(cw, ch, rng), c.interlaced);
  cut.resize(std::min<size_t>(6, cut.size() - 1));
  items.insert(items.end(), cut.begin(), cut.end());
  for (const Txn& t : mipgen_frame_items(random_frame(cw, ch, rng), c.interlaced)) {
    items.push_back(t);
  }
  items.push_back(mipgen_config_item(first_));  // the random items go on in the setup's format
  return items;
}

std::vector<Txn> MipgenBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  texram::MipgenConfig f = first_;
  int frames_left = uniform(rng, 1, 3);
  bool cut = false;  // the last frame was cut short: a whole frame must follow
  while (items.size() < count || cut) {
    if (frames_left == 0) {  // a new format, as a video driver writes it between frames
      f = draw_format(rng);
      items.push_back(mipgen_config_item(f));
      frames_left = uniform(rng, 1, 3);
    }
    --frames_left;
    const uint32_t w = 1u << f.log2_w, h = 1u << f.log2_h;
    // Now and then a constant frame (box sums 0 and 1020, or of one value), else random bytes.
    const uint64_t kind = rng() % 8;
    const texram::Level8 frame =
        kind == 0 ? filled(w, h, (rng() & 1) ? 255 : static_cast<uint8_t>(rng() % 255))
                  : random_frame(w, h, rng);
    std::vector<Txn> frame_items = mipgen_frame_items(frame, f.interlaced);
    // Now and then a frame cut short (a video unit drops it); the next frame, of the same
    // format (a format is written between frames), restarts.
    cut = frames_left > 0 && frame_items.size() > 1 && rng() % 6 == 0;
    if (cut) frame_items.resize(1 + rng() % (frame_items.size() - 1));
    for (const Txn& t : frame_items) items.push_back(t);
  }
  return items;
}

std::unique_ptr<Model> MipgenBlock::golden() const { return std::make_unique<Golden>(); }

// The cases the options leave possible.
std::vector<std::string> MipgenBlock::coverage_cases() const {
  const bool w_fixed = options_.mip_log2_w >= 0, h_fixed = options_.mip_log2_h >= 0;
  const int top =
      w_fixed && h_fixed ? std::max(options_.mip_log2_w, options_.mip_log2_h) : kMaxLog2;
  std::vector<std::string> cases;
  for (int l = 0; l <= top; ++l) cases.push_back(level_case(l));
  cases.push_back(kReplicas);
  if (options_.mip_interlaced != 0) {
    if (options_.mip_log2_h != 0) cases.push_back(kField2);
    if (options_.mip_log2_h <= 0) cases.push_back(kOneLine);
  }
  if (top > 0) {
    cases.push_back(kTie);
    cases.push_back(kSum0);
    cases.push_back(kSumMax);
  }
  cases.insert(cases.end(), {kFourPlanes, kLaterFrame, kNewFormat, kFrameEnd, kRestart});
  return cases;
}

void MipgenBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                        Coverage& cov) const {
  // The harness calls this for the items that make writes, in order; any other order replays.
  if (index < cover_.next) cover_ = CoverState{};
  for (; cover_.next < index; ++cover_.next) {
    const Txn& t = items[cover_.next];
    if (D::table().is_cfg(t)) {
      cover_.frames.configure(t);
    } else {
      cover_.writes.clear();
      cover_.frames.step(t, cover_.writes);
    }
  }
  const texram::MipgenStream& s = *cover_.frames.stream();
  const bool after_config = cover_.frames.items_since_configuration() == 0;
  if (after_config && cover_.frames.configurations() > 1) ++cov[kNewFormat];
  if (!after_config && s.frame_start()) ++cov[kLaterFrame];
  if (items[index].f[D::in_start] != 0 && !s.frame_start()) ++cov[kRestart];
  if (s.needs_above()) ++cov[kField2];
  if (s.config().interlaced && s.height() == 1) ++cov[kOneLine];
  if (s.config().plane > 0) ++cov[kFourPlanes];
  cover_.writes.clear();
  cover_.frames.step(items[index], cover_.writes);
  ++cover_.next;
  const texram::Geometry& g = s.geometry();
  bool top = false;  // the 1 x 1 level is written by a frame's last texel only
  for (const texram::CellWrite& w : cover_.writes) {
    ++cov[level_case(w.level)];
    if (g.grid_width(w.level) < 2 || g.grid_height(w.level) < 2) ++cov[kReplicas];
    top = top || w.level == g.levels() - 1;
  }
  if (top) ++cov[kFrameEnd];
  for (const texram::BoxSum& b : s.last_box_sums()) {
    const uint32_t unit = uint32_t{4} << b.frac_bits;  // the sum of a box mean of 1
    if (b.sum % unit == unit / 2) ++cov[kTie];
    if (b.sum == 0) ++cov[kSum0];
    if (b.sum == 255 * unit) ++cov[kSumMax];
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(mipgen, MipgenBlock)
