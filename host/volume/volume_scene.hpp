// A volume scene (000 §13; scenes/README.md, "Volume scenes"): a "volume" section (the data,
// its format, the transfer function, the ray step, the unit's weight bits, early termination,
// the chips) beside the camera, background and lights of every scene. load_volume_scene() checks
// every key and reports the first problem with the file, the field path and the reason.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "volume/sources.hpp"
#include "volume/transfer_function.hpp"
#include "volume/unit.hpp"

namespace tmu::host {

enum class VolumeFormat {
  kRaw,   // 8-bit values: the unit's raw mode (value and gradient), classified by the host
  kRgba,  // pre-classified: four 8-bit components, opacity-weighted colour, each in value mode
};

// Where the voxels come from.
struct VolumeData {
  enum class Field { kMarschnerLobb, kSphere, kEngine, kFile };
  Field field = Field::kMarschnerLobb;
  std::array<uint32_t, 3> size{64, 64, 64};
  volume::MarschnerLobb marschner_lobb;  // f_m, alpha
  double radius = 24, slope = 8;         // sphere: voxels, voxel values per voxel
  uint32_t seed = 1;                     // engine: the scan noise's
  std::string file;                      // file: the path, resolved against the scene's folder
};

// Early termination: a ray stops once its accumulated opacity reaches `alpha`; the unit then
// resamples it `segment` locations at a time (the host can only stop what it has not issued).
struct Termination {
  double alpha = 255.0 / 256.0;
  uint32_t segment = 16;
};

struct VolumeScene {
  std::string path;
  VolumeData data;
  VolumeFormat format = VolumeFormat::kRaw;
  TransferFunction transfer;  // raw data, and a generated field pre-classified for rgba
  Camera camera;              // near and far are not used: rays start at the eye
  glm::dvec3 background{0};
  std::vector<Light> lights;  // shading from the gradient (raw only); none: unshaded
  double step = 1;            // voxels between resample locations
  int weight_bits = 8;        // W of the unit's trilinear weights
  std::optional<Termination> termination = Termination{};  // nullopt: every location
  int chips = 1;                                           // slabs of the volume, one a chip
  int slab_axis = 0;                                       // 0 x, 1 y, 2 z
};

// The unit's mode for the scene's format: raw data in raw mode, each RGBA component in value mode.
volume::Mode volume_mode(const VolumeScene& scene);

VolumeScene load_volume_scene(const std::string& path);
VolumeScene parse_volume_scene(const std::string& text, const std::string& name,
                               const std::string& folder);

// Whether the scene file has a "volume" section (a volume scene).
bool is_volume_scene(const std::string& path);

// The step's range: at least 1/64 voxel (so that the longest ray, the diagonal of 512^3, has at
// most 65535 locations: VoxelCount) and at most 4 (a step component stays within VoxelStep's 8).
inline constexpr double kMinStep = 1.0 / 64, kMaxStep = 4;

}  // namespace tmu::host
