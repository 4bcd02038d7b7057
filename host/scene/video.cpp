// The "video" key of a material (scenes/README.md "Video maps", docs/video.md): a generated
// sequence or numbered image files, the format the video port is set to (size, interlaced,
// planes), how many frames and at what rate. Every file a video names is checked here (exists,
// readable, the video's size), so a scene with a bad clip fails before anything is written.
#include <fmt/format.h>

#include <bit>
#include <cctype>
#include <filesystem>
#include <optional>

#include "common/image_file.hpp"
#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

// Video sides: powers of two up to 512 (two buffers of a 512 x 512 four-plane video fit a chip's
// bank; docs/video.md "Capacity").
constexpr int kMaxVideoSide = 512;

bool video_side(int s) { return s >= 1 && s <= kMaxVideoSide && std::has_single_bit(unsigned(s)); }

// Where the frame number goes in a file pattern: the one "%d" or "%0Nd" (N 1..9).
struct NumberField {
  size_t at = 0, length = 0;
  int width = 0;
};

std::optional<NumberField> number_field(const std::string& pattern) {
  std::optional<NumberField> found;
  for (size_t i = pattern.find('%'); i != std::string::npos; i = pattern.find('%', i + 1)) {
    NumberField f{i, 1, 0};
    size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') {
      ++j;
      if (j >= pattern.size() || !std::isdigit(static_cast<unsigned char>(pattern[j])))
        return std::nullopt;
      f.width = pattern[j++] - '0';
    }
    if (j >= pattern.size() || pattern[j] != 'd' || found) return std::nullopt;
    f.length = j + 1 - i;
    found = f;
  }
  return found;
}

std::string number_into(const std::string& pattern, int k) {
  const NumberField f = *number_field(pattern);
  return pattern.substr(0, f.at) + fmt::format("{:0{}d}", k, f.width) +
         pattern.substr(f.at + f.length);
}

// The size of frame k's file, or the node fails naming the file and the reason.
glm::ivec2 frame_file_size(const JsonNode& node, const std::string& path, int k) {
  if (!std::filesystem::is_regular_file(path))
    node.fail(fmt::format("frame {}: file not found: {}", k, path));
  std::string why;
  const auto in = open_image_file(path, &why);
  if (!in) node.fail(fmt::format("frame {}: cannot read the image {}: {}", k, path, why));
  return {in->width(), in->height()};
}

}  // namespace

// The number goes in the file's name (its folder may hold any '%').
std::string video_file(const Video& video, int k) {
  const std::filesystem::path p(video.files);
  return (p.parent_path() / number_into(p.filename().string(), k)).string();
}

Video parse_video(const JsonNode& node, const std::string& folder) {
  node.expect_object();
  Video v;
  const bool generated = node.has("source");
  if (generated == node.has("files")) node.fail("needs one of the keys source, files");
  std::optional<JsonNode> size = node.find("size");
  if (generated) {
    node.allow_keys({"source", "pattern", "size", "interlaced", "planes", "frames", "fps"});
    node.at("source").one_of({"generated"});
    v.source = Video::Source::kGenerated;
    v.pattern = node.at("pattern").one_of({"bars", "rings", "noise"});
    if (!size) node.fail("a generated video needs its \"size\" [w, h]");
  } else {
    node.allow_keys({"files", "size", "interlaced", "planes", "frames", "fps"});
    v.source = Video::Source::kFiles;
    const JsonNode files = node.at("files");
    const std::string pattern = files.string();
    if (!number_field(std::filesystem::path(pattern).filename().string())) {
      files.fail(
          "needs one %d or %0Nd (N 1..9) in the file's name where the frame number goes, e.g. "
          "images/clip-%04d.png");
    }
    const std::filesystem::path p(pattern);
    v.files = p.is_absolute() ? pattern : (std::filesystem::path(folder) / p).string();
  }
  if (auto planes = node.find("planes")) {
    v.planes = static_cast<int>(planes->integer(1, 4));
    if (v.planes != 1 && v.planes != 4) planes->fail("must be 1 (luminance) or 4 (R G B A)");
  }
  if (auto interlaced = node.find("interlaced")) {
    if (!interlaced->json().is_boolean()) interlaced->fail("expected true or false");
    v.interlaced = interlaced->json().get<bool>();
  }
  if (auto fps = node.find("fps")) v.fps = static_cast<double>(fps->integer(1, 120));
  if (size) {
    size->expect_array();
    if (size->size() != 2) size->fail("expected a list of 2 integers (width, height)");
    v.width = static_cast<int>((*size)[0].integer(1, kMaxVideoSide));
    v.height = static_cast<int>((*size)[1].integer(1, kMaxVideoSide));
    if (!video_side(v.width) || !video_side(v.height)) {
      size->fail(fmt::format("a video's sides are powers of two up to {} (it is {}x{})",
                             kMaxVideoSide, v.width, v.height));
    }
  }
  if (auto frames = node.find("frames")) {
    v.frames = static_cast<int>(frames->integer(1, 100000));
  } else if (generated) {
    node.fail("a generated video needs its number of \"frames\"");
  } else {  // every consecutive file from frame 0
    v.frames = 0;
    while (std::filesystem::is_regular_file(video_file(v, v.frames))) ++v.frames;
    if (v.frames == 0)
      node.at("files").fail(fmt::format("frame 0: file not found: {}", video_file(v, 0)));
  }
  if (!generated) {
    const JsonNode files = node.at("files");
    for (int k = 0; k < v.frames; ++k) {
      const glm::ivec2 s = frame_file_size(files, video_file(v, k), k);
      if (k == 0 && !size) {
        if (!video_side(s.x) || !video_side(s.y)) {
          files.fail(fmt::format("frame 0: {} is {}x{}: a video's sides are powers of two up to {}",
                                 video_file(v, 0), s.x, s.y, kMaxVideoSide));
        }
        v.width = s.x;
        v.height = s.y;
      }
      if (s.x != v.width || s.y != v.height) {
        files.fail(fmt::format("frame {}: {} is {}x{}, the video {}x{}", k, video_file(v, k), s.x,
                               s.y, v.width, v.height));
      }
    }
  }
  return v;
}

}  // namespace tmu::host
