#include "blocks/video_port/video_port_block.hpp"

#include <algorithm>
#include <utility>

#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/video_port_sc.hpp"
#include "rtl_models_video_port.hpp"

TMU_DESCRIBE_SC(video_port)

namespace tmu::tb {
namespace fmts = tmu::formats;
namespace video = texram::video;
using D = desc::video_port;

namespace {

int uniform(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

video::VideoFormat format_of(const Txn& cfg) {
  video::VideoFormat f;
  f.log2_w = static_cast<int>(cfg.f[D::cfg_log2_w]);
  f.log2_h = static_cast<int>(cfg.f[D::cfg_log2_h]);
  f.interlaced = cfg.f[D::cfg_interlaced] != 0;
  f.planes = cfg.f[D::cfg_four_planes] != 0 ? fmts::kPlanes : 1;
  return f;
}

video::VideoItem item_of(const Txn& t) {
  return video::video_item(static_cast<uint8_t>(t.f[D::in_flags]),
                           static_cast<uint32_t>(t.f[D::in_texel]));
}

// The receiver as the hardware has it: reset to a 1 x 1 progressive one-plane format; a
// configuration that changes the format drops a frame under way (set_format).
class Golden : public Model {
 public:
  void configure(const Txn& cfg) override {
    const video::VideoFormat f = format_of(cfg);
    if (!(f == rx_.format())) rx_.set_format(f);
  }
  void step(const Txn& item, Sink& sink) override {
    const video::Received r = rx_.step(item_of(item));
    Txn out;
    out.f[D::out_accepted] = r.accepted;
    out.f[D::out_x] = r.x;
    out.f[D::out_y] = r.y;
    out.f[D::out_frame_start] = r.frame_start;
    out.f[D::out_frame_end] = r.frame_end;
    out.f[D::out_dropped] = r.dropped;
    out.f[D::out_error] = static_cast<uint64_t>(r.error);
    const uint64_t texel = item.f[D::in_texel];
    out.f[D::out_texel] = rx_.format().planes == 1 ? texel & 0xFF00'0000u : texel;
    sink.output(out);
  }
  Counters counters() const override {
    const video::ReceiverStats& s = rx_.stats();
    const auto c32 = [](uint64_t v) { return v & 0xFFFF'FFFFu; };  // the RTL's 32-bit registers
    return {{"items", c32(s.items)},
            {"frames_complete", c32(s.frames_complete)},
            {"frames_dropped", c32(s.frames_dropped)},
            {"items_discarded", c32(s.items_discarded)},
            {"field_order_errors", c32(s.field_order_errors)}};
  }

 private:
  video::VideoReceiver rx_{video::VideoFormat{}};
};

// A defect of one frame's items (or none).
enum class Defect { kNone, kShortLine, kLongLine, kCutShort, kFieldsSwapped, kNoise };

std::vector<Txn> with_defect(const video::VideoFormat& f, std::vector<Txn> items, Defect d,
                             std::mt19937_64& rng) {
  if (items.empty()) return items;
  const size_t n = items.size();
  const size_t at = static_cast<size_t>(rng() % n);
  switch (d) {
    case Defect::kNone:
      break;
    case Defect::kShortLine:  // a texel missing
      items.erase(items.begin() + static_cast<std::ptrdiff_t>(at));
      break;
    case Defect::kLongLine: {  // a texel repeated (its flags: 0 unless it starts a line)
      Txn extra = items[at];
      extra.f[D::in_flags] = 0;
      items.insert(items.begin() + static_cast<std::ptrdiff_t>(at) + 1, extra);
      break;
    }
    case Defect::kCutShort:  // the frame ends early
      items.resize(std::max<size_t>(1, at));
      break;
    case Defect::kFieldsSwapped: {  // field 2 sent first, flagged first of frame
      if (!f.fields()) break;
      const size_t half = n / 2;
      std::rotate(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(half), items.end());
      items[0].f[D::in_flags] |= video::kFrameStart;
      break;
    }
    case Defect::kNoise:  // one item with random flags
      items[at].f[D::in_flags] = rng() & 0xFu;
      break;
  }
  return items;
}

// Mostly small frames (up to 16 x 16), one texel wide or high, 1 x 1, now and then a
// 1024-texel line or column: a few thousand items see many formats.
video::VideoFormat draw_format(std::mt19937_64& rng) {
  video::VideoFormat f;
  const uint64_t r = rng() % 16;
  if (r < 2) {
    f.log2_w = 0;
    f.log2_h = uniform(rng, 0, 5);
  } else if (r < 4) {
    f.log2_w = uniform(rng, 0, 5);
    f.log2_h = 0;
  } else if (r == 4) {
    f.log2_w = fmts::kMaxMipLog2;
    f.log2_h = uniform(rng, 0, 1);
  } else if (r == 5) {
    f.log2_w = 0;
    f.log2_h = fmts::kMaxMipLog2;
  } else {
    f.log2_w = uniform(rng, 0, 4);
    f.log2_h = uniform(rng, 0, 4);
  }
  f.interlaced = (rng() & 1) != 0;
  f.planes = (rng() & 1) ? fmts::kPlanes : 1;
  return f;
}

constexpr const char* kAccepted = "texel accepted";
constexpr const char* kStart = "frame start";
constexpr const char* kEnd = "frame end";
constexpr const char* kOneTexel = "1 x 1 frame (start and end)";
constexpr const char* kField2 = "field-2 texel accepted";
constexpr const char* kDropped = "frame dropped (bad flags)";
constexpr const char* kDroppedStarts = "a dropping item starts the next frame (cut short)";
constexpr const char* kFieldOrder = "field-order error";
constexpr const char* kDiscarded = "item discarded outside a frame";
constexpr const char* kChangeInFrame = "new format in the middle of a frame (dropped)";
constexpr const char* kFourPlanes = "four-plane texel";
constexpr const char* kLastColumn = "x = 1023";
constexpr const char* kLastRow = "y = 1023";

}  // namespace

Txn video_port_config_item(const video::VideoFormat& f) {
  return channel_item(D::table(), "cfg",
                      {static_cast<uint64_t>(f.log2_w), static_cast<uint64_t>(f.log2_h),
                       f.interlaced ? 1u : 0u, f.planes == fmts::kPlanes ? 1u : 0u});
}

Txn video_port_item(const video::VideoItem& it) {
  return channel_item(D::table(), "in", {it.flags, video::texel_word(it)});
}

std::vector<Txn> video_port_frame(const video::VideoFormat& format, uint32_t k) {
  std::vector<Txn> items;
  for (const video::VideoItem& it : video::frame_items(format, video::test_frame(format, k))) {
    items.push_back(video_port_item(it));
  }
  return items;
}

VideoPortBlock::VideoPortBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  add_level("hls", hls_level<desc::video_port_sc, hls::VideoPortSc>());
  TMU_ADD_RTL_LEVELS(video_port, variant());
}

std::vector<Txn> VideoPortBlock::setup_items() const {
  return {video_port_config_item({2, 2, true, 1})};
}

std::vector<Txn> VideoPortBlock::directed_items() const {
  std::mt19937_64 rng(options_.seed ^ 0x71DE'0000'0000'0001ull);
  std::vector<Txn> items;
  const auto add = [&items](const std::vector<Txn>& more) {
    items.insert(items.end(), more.begin(), more.end());
  };
  const auto use = [&items](const video::VideoFormat& f) {
    items.push_back(video_port_config_item(f));
  };
  // docs/video.md's 2 x 4 interlaced frame, three back to back.
  use({1, 2, true, 1});
  for (uint32_t k = 0; k < 3; ++k) add(video_port_frame({1, 2, true, 1}, k));
  // The worked malformed cases of docs/video.md on a 4 x 4 progressive frame: a short line 1,
  // a long line 0, a frame cut after 10 items; each followed by a good frame.
  const video::VideoFormat f44{2, 2, false, 1};
  use(f44);
  std::vector<Txn> frame = video_port_frame(f44, 1);
  std::vector<Txn> shorter = frame;
  shorter.erase(shorter.begin() + 7);  // (3, 1) missing
  add(shorter);
  add(video_port_frame(f44, 2));
  std::vector<Txn> longer = frame;
  Txn extra = frame[3];
  extra.f[D::in_flags] = 0;
  longer.insert(longer.begin() + 4, extra);  // a fifth texel on line 0
  add(longer);
  add(video_port_frame(f44, 3));
  add(std::vector<Txn>(frame.begin(), frame.begin() + 10));  // cut short
  add(video_port_frame(f44, 4));
  // Field 2 before field 1 on a 4 x 4 interlaced frame, then a good frame.
  const video::VideoFormat f44i{2, 2, true, 1};
  use(f44i);
  add(with_defect(f44i, video_port_frame(f44i, 5), Defect::kFieldsSwapped, rng));
  add(video_port_frame(f44i, 6));
  // Items before any frame start, then 1 x 1 frames, one-line and one-column frames, a
  // 1 x 2 interlaced frame (field 2 right after field 1's one texel).
  add({video_port_item({0, {}}), video_port_item({4, {}}), video_port_item({8, {}})});
  for (const video::VideoFormat& f :
       {video::VideoFormat{0, 0, false, 4}, video::VideoFormat{0, 0, true, 1},
        video::VideoFormat{4, 0, true, 4}, video::VideoFormat{0, 4, true, 1},
        video::VideoFormat{0, 1, true, 4}, video::VideoFormat{3, 1, true, 1}}) {
    use(f);
    for (uint32_t k = 0; k < 2; ++k) add(video_port_frame(f, k));
  }
  // The largest places: a 1024-texel line, a 1024-line column interlaced.
  use({fmts::kMaxMipLog2, 0, false, 1});
  add(video_port_frame({fmts::kMaxMipLog2, 0, false, 1}, 0));
  use({0, fmts::kMaxMipLog2, true, 4});
  add(video_port_frame({0, fmts::kMaxMipLog2, true, 4}, 0));
  // A new format in the middle of a frame: the frame is dropped, the next one taken.
  use({2, 1, false, 1});
  frame = video_port_frame({2, 1, false, 1}, 7);
  add(std::vector<Txn>(frame.begin(), frame.begin() + 3));
  use({2, 1, true, 1});
  add(video_port_frame({2, 1, true, 1}, 8));
  items.push_back(setup_items().front());
  return items;
}

std::vector<Txn> VideoPortBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  video::VideoFormat f{2, 2, true, 1};  // the setup item's
  uint32_t k = 0;
  while (items.size() < count) {
    if (rng() % 4 == 0) {  // a new format, now and then in the middle of a frame
      f = draw_format(rng);
      items.push_back(video_port_config_item(f));
    }
    const uint64_t r = rng() % 16;
    const Defect d = r < 9    ? Defect::kNone
                     : r < 11 ? Defect::kShortLine
                     : r < 12 ? Defect::kLongLine
                     : r < 13 ? Defect::kCutShort
                     : r < 14 ? Defect::kFieldsSwapped
                              : Defect::kNoise;
    for (const Txn& t : with_defect(f, video_port_frame(f, k++), d, rng)) items.push_back(t);
  }
  return items;
}

std::unique_ptr<Model> VideoPortBlock::golden() const { return std::make_unique<Golden>(); }

std::vector<std::string> VideoPortBlock::coverage_cases() const {
  return {kAccepted,   kStart,         kEnd,        kOneTexel,  kField2,
          kDropped,    kDroppedStarts, kFieldOrder, kDiscarded, kChangeInFrame,
          kFourPlanes, kLastColumn,    kLastRow};
}

void VideoPortBlock::cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                           Coverage& cov) const {
  // The harness calls this for the items that give outputs, in order; any other order replays.
  if (index < cover_.next) cover_ = CoverState{};
  for (; cover_.next < index; ++cover_.next) {
    const Txn& t = items[cover_.next];
    if (D::table().is_cfg(t)) {
      const video::VideoFormat f = format_of(t);
      if (!(f == cover_.rx.format())) {
        if (cover_.rx.in_frame()) ++cov[kChangeInFrame];
        cover_.rx.set_format(f);
      }
    } else {
      cover_.rx.step(item_of(t));
    }
  }
  const video::Received r = cover_.rx.step(item_of(items[index]));
  ++cover_.next;
  if (r.accepted) ++cov[kAccepted];
  if (r.frame_start) ++cov[kStart];
  if (r.frame_end) ++cov[kEnd];
  if (r.frame_start && r.frame_end) ++cov[kOneTexel];
  if (r.accepted && cover_.rx.format().fields() && (r.y & 1u) != 0) ++cov[kField2];
  if (r.dropped) ++cov[kDropped];
  if (r.dropped && r.frame_start) ++cov[kDroppedStarts];
  if (r.error == video::VideoError::kFieldOrder) ++cov[kFieldOrder];
  if (!r.accepted && !r.dropped && r.error == video::VideoError::kNone) ++cov[kDiscarded];
  if (r.accepted && cover_.rx.format().planes == fmts::kPlanes) ++cov[kFourPlanes];
  if (r.accepted && r.x == 1023) ++cov[kLastColumn];
  if (r.accepted && r.y == 1023) ++cov[kLastRow];
  (void)output;
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(video_port, VideoPortBlock)
