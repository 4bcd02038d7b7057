#include "clipmap/tile_manager.hpp"

#include <algorithm>

#include "clipmap/tile_centre.hpp"
#include "common/error.hpp"
#include "texram/texture.hpp"

namespace tmu::clipmap {
namespace {

// File tiles kept in memory before the cache starts over (64 x 64 x 4 bytes each: 64 MB).
constexpr size_t kMaxCachedTiles = 4096;

Region intersect(const Region& a, const Region& b) {
  Region r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
  if (r.x0 >= r.x1 || r.y0 >= r.y1) return {};
  return r;
}

}  // namespace

TileManager::TileManager(const Config& config, const std::string& path)
    : config_(config), path_(path) {
  check(config);
  if (config.sampler.kind == texram::TexelKind::kIndex) {
    throw InputError(path, "kind", "an index clip-map needs a palette: use luminance or rgba");
  }
  std::string why;
  file_ = open_image_file(path, &why);
  if (!file_) throw InputError(path, "", "cannot open: " + (why.empty() ? "no reader" : why));
  channels_ = file_->channels();
  tile_w_ = file_->tile_width();
  tile_h_ = file_->tile_height();
  if (tile_w_ <= 0 || tile_h_ <= 0) {
    throw InputError(path, "", "not a tiled file (make it with maketx)");
  }
  if (channels_ != 1 && channels_ != 3 && channels_ != 4) {
    throw InputError(path, "", std::to_string(channels_) + " channels (1, 3 or 4 expected)");
  }
  const int levels = config.log2_virtual + 1;
  if (file_->mip_levels() < levels) {
    throw InputError(path, "",
                     std::to_string(file_->mip_levels()) + " MIP levels, " +
                         std::to_string(levels) + " expected (make it with maketx)");
  }
  for (int l = 0; l < levels; ++l) {
    const int side = 1 << (config.log2_virtual - l);
    if (file_->level_size(l) != std::make_pair(side, side)) {
      const auto [w, h] = file_->level_size(l);
      throw InputError(path, "",
                       "MIP level " + std::to_string(l) + " is " + std::to_string(w) + " x " +
                           std::to_string(h) + ", " + std::to_string(side) + " x " +
                           std::to_string(side) + " expected");
    }
  }
}

const std::vector<uint8_t>& TileManager::file_tile(int level, int tx, int ty) {
  const auto key = std::make_tuple(level, tx, ty);
  if (auto it = tiles_.find(key); it != tiles_.end()) return it->second;
  if (tiles_.size() >= kMaxCachedTiles) tiles_.clear();
  std::vector<uint8_t> data(static_cast<size_t>(tile_w_) * tile_h_ * channels_);
  if (!file_->read_tile_uint8(level, tx * tile_w_, ty * tile_h_, data.data())) {
    throw InputError(path_, "",
                     "cannot read MIP level " + std::to_string(level) + " tile (" +
                         std::to_string(tx) + ", " + std::to_string(ty) + "): " + file_->error());
  }
  ++tiles_read_;
  return tiles_.emplace(key, std::move(data)).first->second;
}

uint32_t TileManager::texel(int level, uint32_t x, uint32_t y) {
  const std::vector<uint8_t>& tile =
      file_tile(level, static_cast<int>(x) / tile_w_, static_cast<int>(y) / tile_h_);
  const size_t at = (static_cast<size_t>(y % static_cast<uint32_t>(tile_h_)) * tile_w_ +
                     x % static_cast<uint32_t>(tile_w_)) *
                    channels_;
  const uint8_t r = tile[at];
  const uint8_t g = channels_ >= 3 ? tile[at + 1] : r, b = channels_ >= 3 ? tile[at + 2] : r;
  const uint8_t a = channels_ == 4 ? tile[at + 3] : 255;
  switch (config_.sampler.kind) {
    case texram::TexelKind::kTrueColour:
      return texram::rgba(r, g, b, a);
    case texram::TexelKind::kSingle: {
      const uint8_t c[4] = {r, g, b, a};
      return uint32_t{c[config_.sampler.single_channel & 3]} << 24;
    }
    default:  // luminance (check() and the constructor leave nothing else)
      return uint32_t{channels_ >= 3 ? texram::luma({r, g, b}) : r} << 24;
  }
}

void TileManager::load_rect(FrameUpdate& out, int level, const Region& rect) {
  for (uint32_t y = rect.y0; y < rect.y1; ++y) {
    for (uint32_t x = rect.x0; x < rect.x1; ++x)
      out.loads.push_back({level, x, y, texel(level, x, y)});
  }
}

FrameUpdate TileManager::update(double eye_u, double eye_v) {
  FrameUpdate out;
  const uint64_t read_before = tiles_read_;
  const Regions next = centred_regions(config_, eye_u, eye_v);
  const int clipped = config_.clipped_levels();
  if (!current_) {  // the whole levels, once
    for (int l = clipped; l <= config_.log2_virtual; ++l) {
      const uint32_t side = uint32_t{1} << (config_.log2_virtual - l);
      load_rect(out, l, {0, 0, side, side});
      out.rows[static_cast<size_t>(l)] = side;
    }
  }
  for (int l = 0; l < clipped; ++l) {
    const auto ll = static_cast<size_t>(l);
    const Region& n = next[ll];
    const Region kept = current_ ? intersect((*current_)[ll], n) : Region{};
    if (current_ && kept == n) continue;  // the tile did not move
    out.regions.emplace_back(l, kept);    // shrink to what stays valid
    // The new texels: the tile minus what it kept, as two strips: the rows above and below
    // the kept rectangle across the tile, then the columns beside it.
    if (kept.x0 >= kept.x1) {
      load_rect(out, l, n);
      out.rows[ll] = n.y1 - n.y0;
    } else {
      load_rect(out, l, {n.x0, n.y0, n.x1, kept.y0});
      load_rect(out, l, {n.x0, kept.y1, n.x1, n.y1});
      load_rect(out, l, {n.x0, kept.y0, kept.x0, kept.y1});
      load_rect(out, l, {kept.x1, kept.y0, n.x1, kept.y1});
      out.rows[ll] = (n.y1 - n.y0) - (kept.y1 - kept.y0) + (n.x1 - n.x0) - (kept.x1 - kept.x0);
    }
    out.regions.emplace_back(l, n);
  }
  current_ = next;
  out.file_tiles_read = tiles_read_ - read_before;
  return out;
}

}  // namespace tmu::clipmap
