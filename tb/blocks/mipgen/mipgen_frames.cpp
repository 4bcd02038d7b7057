#include "blocks/mipgen/mipgen_frames.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "blocks/mipgen/mipgen_block.hpp"
#include "formats/formats.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::mipgen;

Txn mipgen_config_item(const texram::MipgenConfig& f) {
  return channel_item(
      D::table(), "cfg",
      {static_cast<uint64_t>(f.log2_w), static_cast<uint64_t>(f.log2_h), f.interlaced ? 1u : 0u,
       f.planes == fmts::kPlanes ? 1u : 0u, static_cast<uint64_t>(f.plane)});
}

texram::MipgenConfig mipgen_format_of(const Txn& cfg) {
  texram::MipgenConfig f;
  f.log2_w = static_cast<int>(cfg.f[D::cfg_log2_w]);
  f.log2_h = static_cast<int>(cfg.f[D::cfg_log2_h]);
  f.interlaced = cfg.f[D::cfg_interlaced] != 0;
  f.planes = cfg.f[D::cfg_four_planes] != 0 ? fmts::kPlanes : 1;
  f.plane = static_cast<int>(cfg.f[D::cfg_plane]);
  return f;
}

std::string mipgen_format_text(const texram::MipgenConfig& f) {
  return fmt::format("{} x {}{}, plane {} of {}", uint64_t{1} << f.log2_w, uint64_t{1} << f.log2_h,
                     f.interlaced ? " interlaced" : "", f.plane, f.planes);
}

std::vector<Txn> mipgen_frame_items(const texram::Level8& level0, bool interlaced) {
  std::vector<Txn> items;
  items.reserve(level0.texels.size());
  for (const texram::MipgenInput& in : texram::mipgen_source(level0, interlaced)) {
    items.push_back(channel_item(D::table(), "in", {in.texel, in.above, items.empty() ? 1u : 0u}));
  }
  return items;
}

std::vector<Txn> mipgen_items(const texram::MipgenConfig& format, const texram::Level8& level0) {
  if (level0.width != uint32_t{1} << format.log2_w || level0.height != uint32_t{1}
                                                                           << format.log2_h) {
    throw std::invalid_argument(fmt::format("mipgen_items: a {} x {} frame for the format {}",
                                            level0.width, level0.height,
                                            mipgen_format_text(format)));
  }
  std::vector<Txn> items = {mipgen_config_item(format)};
  for (const Txn& t : mipgen_frame_items(level0, format.interlaced)) items.push_back(t);
  return items;
}

texram::Level8 mipgen_tie_frame(int log2_w, int log2_h) {
  // A checkerboard of 127 and 128: every box of 2 x 2 texels or more (and every pair of a
  // one-texel-wide or -high level, which repeats it) has the mean 127.5 exactly, a tie at
  // every level under the default (exact) rule; every level above 0 is 128.
  texram::Level8 frame(uint32_t{1} << log2_w, uint32_t{1} << log2_h);
  for (uint32_t y = 0; y < frame.height; ++y) {
    for (uint32_t x = 0; x < frame.width; ++x) frame.at(x, y) = 127 + ((x + y) & 1u);
  }
  return frame;
}

Txn mipgen_write_txn(const texram::CellWrite& w) {
  Txn t;
  t.f[D::wr_level] = static_cast<uint64_t>(w.level);
  t.f[D::wr_x] = w.x;
  t.f[D::wr_y] = w.y;
  t.f[D::wr_value] = w.value;
  t.f[D::wr_bank] = w.cell.bank;
  t.f[D::wr_addr] = w.cell.address;
  return t;
}

texram::CellWrite mipgen_txn_write(const Txn& t) {
  texram::CellWrite w;
  w.level = static_cast<int>(t.f[D::wr_level]);
  w.x = static_cast<uint32_t>(t.f[D::wr_x]);
  w.y = static_cast<uint32_t>(t.f[D::wr_y]);
  w.value = static_cast<uint8_t>(t.f[D::wr_value]);
  w.cell = {static_cast<unsigned>(t.f[D::wr_bank]), static_cast<uint32_t>(t.f[D::wr_addr])};
  return w;
}

// ---- MipgenFrames ---------------------------------------------------------------------------

void MipgenFrames::configure(const Txn& cfg) {
  const texram::MipgenConfig f = mipgen_format_of(cfg);
  if (stream_ && !stream_->frame_start()) {
    throw std::runtime_error(fmt::format(
        "mipgen: the format {} written at texel ({}, {}) of a {} frame (a driver writes the "
        "format between frames)",
        mipgen_format_text(f), stream_->next_x(), stream_->next_y(),
        mipgen_format_text(stream_->config())));
  }
  try {
    stream_.emplace(f);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("mipgen: the format {} is not the unit's: {}",
                                         mipgen_format_text(f), e.what()));
  }
  ++configurations_;
  since_ = 0;
}

void MipgenFrames::step(const Txn& item, std::vector<texram::CellWrite>& out) {
  if (!stream_) throw std::runtime_error("mipgen: a texel before the first configuration item");
  if (item.f[D::in_start] != 0 && !stream_->frame_start()) {
    stream_.emplace(stream_->config());  // a frame cut short: the position restarts
  }
  stream_->step(
      {static_cast<uint8_t>(item.f[D::in_texel]), static_cast<uint8_t>(item.f[D::in_above])}, out);
  ++since_;
}

}  // namespace tmu::tb
