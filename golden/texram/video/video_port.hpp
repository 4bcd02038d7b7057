// The TEXRAM's serial video port (000 §11, Fig. 8 808; docs/video.md): the stream of level-0
// texels a video source delivers, one item per texel, and the checks the receiver makes.
//
// An item is the texel's bytes (VideoTexel: one plane, or four planes R G B A) and four flags
// (VideoFlags): first of frame, first of field, first of line, field 2. Order, as
// mipgen_stream.hpp's source order: progressive frames line by line; interlaced frames field 1
// (lines 0, 2, 4, ...) then field 2 (lines 1, 3, ...), every field-2 item flagged field 2. A
// one-line frame is one field whatever the mode. The format (size, mode, planes) is
// quasi-static: a driver sets it between frames (VideoFormat), the stream carries no header.
//
// The receiver (VideoReceiver) knows where the next item must fall and what its flags must be
// there. An item whose flags differ is a malformed frame (a line too short or too long, a frame
// cut short by the next frame's start, field 2 before field 1): the frame being received is
// dropped and counted, and items are discarded until a first-of-frame item with field 1 (which
// may be the offending item itself: a cut-short frame loses only itself). The hardware cannot
// stall the source and never waits: the mapper writes a dropped frame's texels to the back
// buffer like any other, but never shows it (video_map.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "texram/level8.hpp"

namespace tmu::texram::video {

struct VideoFormat {
  int log2_w = 0, log2_h = 0;  // level-0 size, each 0..MaxMipLog2
  bool interlaced = false;
  int planes = 1;  // 1 or 4
  uint32_t width() const { return uint32_t{1} << log2_w; }
  uint32_t height() const { return uint32_t{1} << log2_h; }
  size_t texels() const { return size_t{width()} * height(); }
  // Interlaced source order in effect: interlaced and more than one line.
  bool fields() const { return interlaced && log2_h > 0; }
  friend bool operator==(const VideoFormat&, const VideoFormat&) = default;
};

// VideoFlags bits.
inline constexpr uint8_t kFrameStart = 1u << 0;
inline constexpr uint8_t kFieldStart = 1u << 1;
inline constexpr uint8_t kLineStart = 1u << 2;
inline constexpr uint8_t kField2 = 1u << 3;

struct VideoItem {
  uint8_t flags = 0;               // VideoFlags
  std::array<uint8_t, 4> bytes{};  // plane p's byte; planes beyond the format's are 0
  friend bool operator==(const VideoItem&, const VideoItem&) = default;
};

// The item's bytes as the port's texel word (VideoTexel: plane p in bits 31 - 8p .. 24 - 8p),
// and back.
constexpr uint32_t texel_word(const VideoItem& item) {
  uint32_t w = 0;
  for (size_t p = 0; p < 4; ++p) w |= uint32_t{item.bytes[p]} << (24 - 8 * p);
  return w;
}
constexpr VideoItem video_item(uint8_t flags, uint32_t texel_word) {
  VideoItem it;
  it.flags = flags;
  for (size_t p = 0; p < 4; ++p) it.bytes[p] = static_cast<uint8_t>(texel_word >> (24 - 8 * p));
  return it;
}

// One frame: one Level8 per plane, all of the format's size.
using VideoFrame = std::vector<Level8>;

// The flags the item at level-0 position (x, y) of a frame of `format` carries.
uint8_t flags_at(const VideoFormat& format, uint32_t x, uint32_t y);

// The positions of a frame's items in source order.
std::vector<std::array<uint32_t, 2>> source_order(const VideoFormat& format);

// The items of one frame, in source order. Throws std::invalid_argument when the frame's
// planes are not the format's count and size.
std::vector<VideoItem> frame_items(const VideoFormat& format, const VideoFrame& frame);

// Test frame number `k` of a video of `format`: every plane a pattern that moves with k
// (a diagonal ramp shifted by 7 k, xor'd with plane-dependent hash noise), so every frame and
// every plane differs from the others at nearly every texel.
VideoFrame test_frame(const VideoFormat& format, uint32_t k);

enum class VideoError : uint8_t {
  kNone = 0,
  kBadFlags,    // an item's flags are not those of its place: a short or long line, a frame
                // cut short (first of frame early)
  kFieldOrder,  // a first-of-frame item flagged field 2: field 2 before field 1
};

struct ReceiverStats {
  uint64_t items = 0;            // every item seen
  uint64_t frames_complete = 0;  // frames received whole
  uint64_t frames_dropped = 0;   // frames begun and dropped (kBadFlags)
  uint64_t items_discarded = 0;  // items outside any frame (waiting for a frame's start)
  uint64_t field_order_errors = 0;
  friend bool operator==(const ReceiverStats&, const ReceiverStats&) = default;
};

// What the receiver makes of one item.
struct Received {
  bool accepted = false;  // the item is texel (x, y) of the current frame
  uint32_t x = 0, y = 0;
  bool frame_start = false;  // the first texel of a frame (the mapper starts a new frame)
  bool frame_end = false;    // the last texel: the frame is complete
  bool dropped = false;      // the frame under way was dropped before this item
  VideoError error = VideoError::kNone;
};

class VideoReceiver {
 public:
  // Throws std::invalid_argument for sizes beyond 0..MaxMipLog2 or planes other than 1 or 4.
  explicit VideoReceiver(const VideoFormat& format);

  const VideoFormat& format() const { return format_; }
  // A new format, written between frames (the format is quasi-static). A frame under way is
  // dropped and counted (its place has no meaning in the new format); the counters stay.
  // Throws std::invalid_argument like the constructor.
  void set_format(const VideoFormat& format);
  Received step(const VideoItem& item);
  const ReceiverStats& stats() const { return stats_; }
  bool in_frame() const { return in_frame_; }

 private:
  Received start(const VideoItem& item, Received r);
  void advance();

  VideoFormat format_;
  bool in_frame_ = false;
  uint32_t x_ = 0, y_ = 0;
  ReceiverStats stats_;
};

}  // namespace tmu::texram::video
