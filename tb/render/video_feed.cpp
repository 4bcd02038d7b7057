#include "render/video_feed.hpp"

#include <fmt/format.h>

#include <bit>
#include <stdexcept>

#include "common/error.hpp"
#include "common/image.hpp"
#include "render/video_pattern.hpp"

namespace tmu::render {

namespace video = texram::video;

video::VideoFormat video_format(const host::Video& v) {
  video::VideoFormat f;
  f.log2_w = std::countr_zero(static_cast<unsigned>(v.width));
  f.log2_h = std::countr_zero(static_cast<unsigned>(v.height));
  f.interlaced = v.interlaced;
  f.planes = v.planes;
  return f;
}

video::VideoFrame video_frame(const host::Video& v, int k) {
  const video::VideoFormat format = video_format(v);
  if (v.source == host::Video::Source::kGenerated)
    return generated_video_frame(v.pattern, format, static_cast<uint32_t>(k));
  const std::string path = host::video_file(v, k);
  const ImageRgb8 img = read_image(path);
  if (img.width != v.width || img.height != v.height) {  // changed since the scene was read
    throw InputError(path, "",
                     fmt::format("frame {} is {}x{}, the video {}x{}", k, img.width, img.height,
                                 v.width, v.height));
  }
  video::VideoFrame frame(static_cast<size_t>(v.planes),
                          texram::Level8(format.width(), format.height()));
  for (uint32_t y = 0; y < format.height(); ++y) {
    for (uint32_t x = 0; x < format.width(); ++x) {
      const Rgb8 c = img.at(static_cast<int>(x), static_cast<int>(y));
      if (v.planes == 1) {
        frame[0].at(x, y) = texram::luma(c);
      } else {
        frame[0].at(x, y) = c.r;
        frame[1].at(x, y) = c.g;
        frame[2].at(x, y) = c.b;
        frame[3].at(x, y) = 255;
      }
    }
  }
  return frame;
}

namespace {

texram::TexelKind kind_of(int planes) {
  return planes == 1 ? texram::TexelKind::kLuminance : texram::TexelKind::kTrueColour;
}

// Buffer b's cells of `memory` as one map of the video's layout.
std::shared_ptr<const texram::TexramTexture> buffer_texture(const video::VideoMap& map, int b) {
  auto t = std::make_shared<texram::TexramTexture>();
  t->kind = kind_of(map.config().format.planes);
  t->geometry = map.geometry();
  const uint32_t base = map.buffer_base(b), cells = map.geometry().bank_cells();
  for (size_t bank = 0; bank < t->banks.size(); ++bank) {
    const std::vector<uint8_t>& from = map.memory()[bank];
    t->banks[bank].assign(from.begin() + base, from.begin() + base + cells);
  }
  return t;
}

}  // namespace

std::shared_ptr<const VideoBuffers> empty_video_buffers(const host::Video& v) {
  const video::VideoFormat f = video_format(v);
  auto t = std::make_shared<texram::TexramTexture>();
  t->kind = kind_of(v.planes);
  t->geometry = texram::Geometry(f.log2_w, f.log2_h, f.planes);
  for (auto& bank : t->banks) bank.assign(t->geometry.bank_cells(), 0);
  auto b = std::make_shared<VideoBuffers>();
  b->buffers = {t, t};
  return b;
}

VideoFeed::VideoFeed(const host::Video& v, uint32_t base, int drf)
    : video_(v), map_(video::VideoMapConfig{video_format(v), base, drf, {}}) {}

VideoFrameFeed VideoFeed::feed(int k) {
  const video::VideoFormat format = video_format(video_);
  const std::vector<video::VideoItem> items = video::frame_items(format, video_frame(video_, k));
  const video::ArbiterStats before = map_.row_buffers().stats();
  video::RunOptions run;
  run.rate = video::video_rate(format.width(), format.height(), static_cast<uint64_t>(video_.fps));
  run.sampler = video::SamplerPattern::kFull;
  VideoFrameFeed r;
  r.frame = k;
  r.cycles = video::run(map_, items, run);
  const video::ArbiterStats& s = map_.row_buffers().stats();
  r.sampler_wanted = s.sampler_wanted - before.sampler_wanted;
  r.sampler_lost = s.sampler_lost - before.sampler_lost;
  r.write_accesses = s.write_accesses - before.write_accesses;
  r.write_cycles = s.write_cycles - before.write_cycles;
  r.page_faults = s.page_faults - before.page_faults;
  r.read_accesses = s.read_accesses - before.read_accesses;
  r.read_cycles = s.read_cycles - before.read_cycles;
  r.lost_writes = s.lost_writes - before.lost_writes;
  r.max_latency = s.max_latency;
  const video::FrameRecord& f = map_.frames().back();
  r.tag = f.tag;
  r.buffer = f.buffer;
  r.complete = f.complete;
  r.begin_cycle = f.begin_cycle;
  r.end_cycle = f.end_cycle;
  if (!f.complete || !f.swap_cycle || map_.front_tag() != f.tag)
    throw std::logic_error("VideoFeed: frame " + std::to_string(k) + " was not swapped in");
  r.swap_cycle = *f.swap_cycle;
  frame_of_tag_.resize(f.tag + 1, -1);
  frame_of_tag_[f.tag] = k;
  return r;
}

std::shared_ptr<const VideoBuffers> VideoFeed::buffers() const {
  auto b = std::make_shared<VideoBuffers>();
  b->buffers = {buffer_texture(map_, 0), buffer_texture(map_, 1)};
  b->front = map_.front_buffer();
  b->shown = frame_of_tag_.at(map_.front_tag());
  return b;
}

}  // namespace tmu::render
