#include "texram/video/video_port.hpp"

#include <stdexcept>
#include <string>

#include "formats/formats.hpp"

namespace tmu::texram::video {
namespace {

const VideoFormat& checked(const VideoFormat& f) {
  if (f.log2_w < 0 || f.log2_w > formats::kMaxMipLog2 || f.log2_h < 0 ||
      f.log2_h > formats::kMaxMipLog2) {
    throw std::invalid_argument("video format: log2 sizes must be 0.." +
                                std::to_string(formats::kMaxMipLog2));
  }
  if (f.planes != 1 && f.planes != formats::kPlanes) {
    throw std::invalid_argument("video format: 1 or 4 planes");
  }
  return f;
}

}  // namespace

uint8_t flags_at(const VideoFormat& format, uint32_t x, uint32_t y) {
  uint8_t f = 0;
  if (x == 0) f |= kLineStart;
  if (x == 0 && (y == 0 || (format.fields() && y == 1))) f |= kFieldStart;
  if (x == 0 && y == 0) f |= kFrameStart;
  if (format.fields() && (y & 1u) != 0) f |= kField2;
  return f;
}

std::vector<std::array<uint32_t, 2>> source_order(const VideoFormat& format) {
  std::vector<std::array<uint32_t, 2>> order;
  order.reserve(format.texels());
  auto line = [&](uint32_t y) {
    for (uint32_t x = 0; x < format.width(); ++x) order.push_back({x, y});
  };
  if (!format.fields()) {
    for (uint32_t y = 0; y < format.height(); ++y) line(y);
  } else {
    for (uint32_t y = 0; y < format.height(); y += 2) line(y);
    for (uint32_t y = 1; y < format.height(); y += 2) line(y);
  }
  return order;
}

std::vector<VideoItem> frame_items(const VideoFormat& format, const VideoFrame& frame) {
  checked(format);
  if (frame.size() != static_cast<size_t>(format.planes)) {
    throw std::invalid_argument("frame_items: " + std::to_string(frame.size()) +
                                " planes, the format has " + std::to_string(format.planes));
  }
  for (const Level8& p : frame) {
    if (p.width != format.width() || p.height != format.height() ||
        p.texels.size() != format.texels()) {
      throw std::invalid_argument("frame_items: a plane is not the format's size");
    }
  }
  std::vector<VideoItem> items;
  items.reserve(format.texels());
  for (const auto& [x, y] : source_order(format)) {
    VideoItem it;
    it.flags = flags_at(format, x, y);
    for (size_t p = 0; p < frame.size(); ++p) it.bytes[p] = frame[p].at(x, y);
    items.push_back(it);
  }
  return items;
}

VideoFrame test_frame(const VideoFormat& format, uint32_t k) {
  checked(format);
  VideoFrame frame;
  for (int p = 0; p < format.planes; ++p) {
    Level8 l(format.width(), format.height());
    for (uint32_t y = 0; y < l.height; ++y) {
      for (uint32_t x = 0; x < l.width; ++x) {
        uint32_t h = (x * 0x9E3779B1u) ^ (y * 0x85EBCA77u) ^ (k * 0xC2B2AE3Du) ^
                     (static_cast<uint32_t>(p) * 0x27D4EB2Fu);
        h ^= h >> 15;
        h *= 0x2C1B3C6Du;
        h ^= h >> 12;
        l.at(x, y) =
            static_cast<uint8_t>((x + y + 7 * k + 64 * static_cast<uint32_t>(p)) ^ (h & 0x1Fu));
      }
    }
    frame.push_back(std::move(l));
  }
  return frame;
}

VideoReceiver::VideoReceiver(const VideoFormat& format) : format_(checked(format)) {}

void VideoReceiver::set_format(const VideoFormat& format) {
  format_ = checked(format);
  if (in_frame_) {
    in_frame_ = false;
    ++stats_.frames_dropped;
  }
}

void VideoReceiver::advance() {
  if (++x_ < format_.width()) return;
  x_ = 0;
  if (!format_.fields()) {
    ++y_;
    return;
  }
  y_ += 2;
  if (y_ == format_.height()) y_ = 1;  // field 1 done: field 2 (y = height + 1 ends field 2)
}

Received VideoReceiver::step(const VideoItem& item) {
  ++stats_.items;
  Received r;
  if (in_frame_) {
    if (item.flags == flags_at(format_, x_, y_)) {
      r.accepted = true;
      r.x = x_;
      r.y = y_;
      r.frame_end = x_ + 1 == format_.width() && y_ + 1 == format_.height();
      if (r.frame_end) {
        in_frame_ = false;
        ++stats_.frames_complete;
      } else {
        advance();
      }
      return r;
    }
    in_frame_ = false;  // a malformed frame: dropped; the item may start the next one
    ++stats_.frames_dropped;
    r.dropped = true;
    r.error = VideoError::kBadFlags;
  }
  return start(item, r);
}

Received VideoReceiver::start(const VideoItem& item, Received r) {
  if ((item.flags & kFrameStart) != 0 && (item.flags & kField2) != 0) {
    ++stats_.field_order_errors;
    ++stats_.items_discarded;
    r.error = VideoError::kFieldOrder;
    return r;
  }
  if (item.flags != flags_at(format_, 0, 0)) {
    ++stats_.items_discarded;
    return r;
  }
  r.accepted = true;
  r.frame_start = true;
  r.x = r.y = 0;
  x_ = y_ = 0;
  r.frame_end = format_.texels() == 1;
  if (r.frame_end) {
    ++stats_.frames_complete;
  } else {
    in_frame_ = true;
    advance();
  }
  return r;
}

}  // namespace tmu::texram::video
