// Image files through OpenImageIO, behind an interface without its types. Every image file of
// the project is read and written through these functions; image_file_oiio.cpp implements
// them. Why not OIIO directly: texsim reaches OpenImageIO only through a plugin it loads when a
// command first touches an image (common/oiio_plugin.hpp), because loading OpenImageIO's
// ~250 shared libraries costs ~0.3 s of CPU that short commands such as `texsim formats` need
// not pay. Callers keep their own error messages; these return OpenImageIO's reasons.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tmu {

// An image file open for reading (OIIO::ImageInput): the first subimage's header, its pixels.
class ImageFileReader {
 public:
  virtual ~ImageFileReader() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual int channels() const = 0;
  // A string attribute of the header, "" when there is none (texsim's bands carry their
  // place in the frame as PNG text).
  virtual std::string attribute(const std::string& name) const = 0;
  // Every channel of every pixel as 8 bits, row-major, interleaved: width x height x channels
  // bytes into `data`. False on failure; error() says why.
  virtual bool read_uint8(uint8_t* data) = 0;
  // A mip-mapped, tiled file (maketx's): the first subimage's MIP levels and their sizes, its
  // tile size (0 x 0 when it is not tiled), and one tile of a level, the tile whose first texel
  // is (x, y) (multiples of the tile size), every channel as 8 bits: tile_width x tile_height x
  // channels bytes, row-major (where a tile sticks out of a small level, what the file stores).
  // False on failure; error() says why.
  virtual int mip_levels() = 0;
  virtual std::pair<int, int> level_size(int level) = 0;
  virtual int tile_width() const = 0;
  virtual int tile_height() const = 0;
  virtual bool read_tile_uint8(int level, int x, int y, uint8_t* data) = 0;
  virtual std::string error() = 0;
};

// Opens `path`; nullptr when no reader can, with OpenImageIO's reason (possibly empty) in *why.
std::unique_ptr<ImageFileReader> open_image_file(const std::string& path, std::string* why);

enum class PixelFormat { kUint8, kFloat };

struct ImageFileSpec {
  int width = 0, height = 0, channels = 0;
  PixelFormat format = PixelFormat::kUint8;
  std::vector<std::pair<std::string, std::string>> attributes;  // string attributes to store
};

enum class ImageWrite { kOk, kNoWriter, kFailed };

// Writes `pixels` (spec's format, row-major, interleaved) to `file` in the format that
// `format_path`'s extension names: an atomic write passes the target there and its temporary
// as `file`. kNoWriter: no writer for that extension; kFailed: *error says why.
ImageWrite write_image_file(const std::string& format_path, const std::string& file,
                            const ImageFileSpec& spec, const void* pixels, std::string* error);

// Fills rows [y, y + n) of an image (spec's format, row-major, interleaved) into `rows`.
using ImageRows = std::function<void(int y, int n, void* rows)>;
// As write_image_file, for an image larger than memory: `band` rows at a time, each band filled
// by `fill` just before it is written (scanlines, in order).
ImageWrite write_image_file_rows(const std::string& format_path, const std::string& file,
                                 const ImageFileSpec& spec, int band, const ImageRows& fill,
                                 std::string* error);

}  // namespace tmu
