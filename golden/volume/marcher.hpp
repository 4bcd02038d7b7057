// The 3-D marcher (000 §13: "evenly spaced resample locations along an arbitrarily oriented
// viewing ray"), made in the manner of the footprint marcher (golden/footprint): raw port
// values in, raw positions out.
//
// A ray is a start point (VoxelPos SQ10.16 per axis, voxels, voxel centres at integers), a
// step (VoxelStep SQ4.16 per axis: |step| < 8 voxels, any sign) and a count (VoxelCount,
// 0..65535 resample locations). The hardware keeps one 26-bit accumulator per axis, loads it
// with the start and adds the step after each resample location:
//   p_0 = start, p_(n+1) = p_n + step (26-bit two's complement, wrapping).
// Integer addition is exact, so p_n = start + n step exactly (no drift against exact
// multiplication) while the position stays within the accumulator's -512 .. 512 voxels; a
// ray that would leave that range is rejected by the host (ray_in_range). What remains is the
// host's quantisation of a real start and step to 16 fraction bits (round half up: at most
// 2^-17 voxel each): against the real ray the error of location n is at most
// (1 + n) 2^-17 voxel per axis, 0.0039 voxel after 512 steps, 0.25 voxel after 32767.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace tmu::volume {

inline constexpr int kPosFrac = 16;  // fraction bits of VoxelPos and VoxelStep

struct Ray {
  std::array<int32_t, 3> start{};  // VoxelPos raw
  std::array<int32_t, 3> step{};   // VoxelStep raw
  uint32_t count = 0;              // VoxelCount
};

using Position = std::array<int32_t, 3>;  // VoxelPos raw

// The host's quantisation of a real coordinate (voxels) to 16 fraction bits, half up.
int32_t quantise(double voxels);

// Whether every location of the ray stays within the accumulator's range and the ports fit
// (start in VoxelPos, step in VoxelStep, count in VoxelCount).
bool ray_in_range(const Ray& ray);

// The marcher: one location per call, as the hardware produces them.
class Marcher {
 public:
  explicit Marcher(const Ray& ray) : ray_(ray), p_(ray.start) {}
  bool done() const { return n_ >= ray_.count; }
  const Position& position() const { return p_; }  // location n
  uint32_t index() const { return n_; }
  void advance();  // p += step (26-bit wrap), n += 1

 private:
  Ray ray_;
  Position p_;
  uint32_t n_ = 0;
};

// All locations of a ray, in order.
std::vector<Position> march(const Ray& ray);

// The 26-bit two's complement wrap of the accumulator.
int32_t wrap_pos(int64_t raw);

}  // namespace tmu::volume
