// The host's texture memory manager for a clip-map (003 §I and summary; issue 17): the whole
// mipmap of the virtual texture lives on disk as a tiled, mip-mapped file (OpenImageIO's
// `maketx` makes it), read through OpenImageIO file tile by file tile; each frame the manager
// places the clip-map's tiles around the eye and issues what changed, as the unit's region
// writes and loads (clipmap.hpp).
//
// The update policy (the copy's §VIII-IX are lost; these are the choices):
// - Centre rule: each clipped level's tile is centred on the eye and slid back inside the
//   virtual texture at its edges (tile_centre.hpp). The whole levels are loaded once.
// - What a frame loads: for each clipped level the texels of its new tile that its old tile did
//   not hold, i.e. at most a strip of rows and a strip of columns at the edges the eye moved
//   towards (003: one texel row per texel of eye movement at that level); the rows that fall
//   off the far side are the ones the new rows overwrite in place (toroidal addressing). An eye
//   that jumps by a tile or more reloads the whole tile.
// - No budget that defers rows to a later frame: the clip-map after a frame is then a function
//   of the eye alone (frame k from scratch equals frame k after frames 0..k-1, which is what lets
//   a fly-over be split across machines), and the report gives the rows each frame cost against
//   the tile side, the most any frame can cost.
// - Order within a frame: each level's region first shrinks to the texels that stay valid, then
//   the loads, then the region grows to the new tile. The unit's rule for writes against samples
//   (clipmap.hpp) makes any order safe between frames; this order is also safe with samples in
//   between.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "clipmap/clipmap.hpp"
#include "common/image_file.hpp"

namespace tmu::clipmap {

struct FrameUpdate {
  std::vector<std::pair<int, Region>> regions;  // region writes, in order
  std::vector<Load> loads;
  std::array<uint32_t, kMaxLevels> rows{};  // texel rows and columns loaded per level
  uint64_t file_tiles_read = 0;             // file tiles read from disk for this frame
};

class TileManager {
 public:
  // Opens `path`, a mip-mapped image of 2^V x 2^V texels with every level down to 1 x 1 (1, 3
  // or 4 channels), for a clip-map of `config` (kind luminance, true colour or single).
  // Throws InputError naming the file and the reason.
  TileManager(const Config& config, const std::string& path);

  // The updates that bring the clip-map from where the last update left it (nothing before
  // the first) to the eye (level-0 texels). Throws InputError when the file cannot be read.
  FrameUpdate update(double eye_u, double eye_v);
  // The bytes a load carries for texel (x, y) of a level (the kind's byte planes).
  uint32_t texel(int level, uint32_t x, uint32_t y);

 private:
  const std::vector<uint8_t>& file_tile(int level, int tx, int ty);
  void load_rect(FrameUpdate& out, int level, const Region& rect);

  Config config_;
  std::string path_;
  std::unique_ptr<ImageFileReader> file_;
  int channels_ = 0, tile_w_ = 0, tile_h_ = 0;
  std::optional<Regions> current_;
  std::map<std::tuple<int, int, int>, std::vector<uint8_t>> tiles_;  // bounded: see file_tile
  uint64_t tiles_read_ = 0;
};

}  // namespace tmu::clipmap
