#include "volume/volume_data.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "common/error.hpp"
#include "volume/ct_scan.hpp"
#include "volume/sources.hpp"

namespace tmu::host {
namespace {

std::vector<uint8_t> read_volume_bytes(const std::string& path, size_t size) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes(size);
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    throw InputError(path, "", "cannot read the volume file");
  return bytes;
}

uint8_t opacity_byte(double v) {
  return static_cast<uint8_t>(std::clamp(std::floor(255 * v + 0.5), 0.0, 255.0));
}

}  // namespace

std::array<uint8_t, 4> preclassify(const TransferFunction& transfer, uint8_t value) {
  const Classified c = transfer(value);
  return {opacity_byte(c.colour.r * c.opacity), opacity_byte(c.colour.g * c.opacity),
          opacity_byte(c.colour.b * c.opacity), opacity_byte(c.opacity)};
}

volume::VoxelGrid field_values(const VolumeData& d) {
  const auto [nx, ny, nz] = d.size;
  switch (d.field) {
    case VolumeData::Field::kMarschnerLobb:
      return volume::marschner_lobb_grid(nx, ny, nz, d.marschner_lobb);
    case VolumeData::Field::kSphere:
      return volume::sphere_grid(nx, ny, nz, d.radius, d.slope);
    case VolumeData::Field::kEngine:
      return engine_scan(nx, ny, nz, d.seed);
    case VolumeData::Field::kFile: {
      volume::VoxelGrid g(nx, ny, nz);
      g.voxels = read_volume_bytes(d.file, g.voxels.size());
      return g;
    }
  }
  throw std::logic_error("volume data: unknown field");
}

std::vector<volume::VoxelGrid> volume_grids(const VolumeScene& scene) {
  const VolumeData& d = scene.data;
  if (scene.format == VolumeFormat::kRaw) return {field_values(d)};
  const auto [nx, ny, nz] = d.size;
  std::vector<volume::VoxelGrid> rgba(4, volume::VoxelGrid(nx, ny, nz));
  if (d.field == VolumeData::Field::kFile) {
    const std::vector<uint8_t> bytes = read_volume_bytes(d.file, size_t{4} * nx * ny * nz);
    for (size_t i = 0; i < rgba[0].voxels.size(); ++i) {
      for (size_t c = 0; c < 4; ++c) rgba[c].voxels[i] = bytes[4 * i + c];
    }
    return rgba;
  }
  const volume::VoxelGrid values = field_values(d);
  // The classification of each of the 256 values, once.
  std::array<std::array<uint8_t, 4>, 256> table{};
  for (int v = 0; v < 256; ++v)
    table[static_cast<size_t>(v)] = preclassify(scene.transfer, static_cast<uint8_t>(v));
  for (size_t i = 0; i < values.voxels.size(); ++i) {
    for (size_t c = 0; c < 4; ++c) rgba[c].voxels[i] = table[values.voxels[i]][c];
  }
  return rgba;
}

}  // namespace tmu::host
