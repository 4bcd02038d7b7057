// The TEXRAM's volume unit as a co-simulation block, `texsim cosim volume` (000 §13, Fig. 15;
// docs/volume.md "The block"; golden/volume/unit.hpp, rtl/volume/tmu_volume.sv,
// hls/volume/volume_sc.hpp).
//
// Channels (volume.json): ray is a ray (start, step per axis, count) and gives its count
// resamples (value, gradient, last on the ray's last); cfg is the unit's mode, W and the
// volume's size, with what the four level-0 banks hold (pattern and seed, not ports); the
// memory rows are the TEXRAM's eight banks (texram.json), answered with the page model's
// timing (tb/blocks/trilinear/texram_memory.hpp), every access of the schedule a request that
// golden predicts, in order, with the page model's counters; stat counts rays and resamples.
//
// The environment: volumes of random bytes, the Marschner-Lobb field, a sphere's distance
// field or a linear ramp, of 2..512 voxels a side. The stimulus starts with a first volume's
// configuration; the directed items tour the hard cases (fractions of exactly 0,
// locations on the volume's faces, edges and corners and outside it, axis-parallel rays,
// negative steps, steps longer than a voxel, 600 steps of drift, rays of 0 and 1 resamples, an
// accumulator that wraps) in both modes, at W = 8, 5 and 1, on odd and minimal sizes, sides of
// 512 and a volume whose addresses reach the top of the 21-bit bank address; a random run
// draws a new volume every few hundred rays. `--volume-mode` fixes the mode of the drawn
// volumes; `--volume-rays z|x|oblique` runs a figure's ray set instead (docs/volume.md).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/volume/volume_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/page_model.hpp"
#include "texram/texture.hpp"
#include "volume/marcher.hpp"
#include "volume/unit.hpp"
#include "volume/voxels.hpp"

TMU_DESCRIBE(volume)

namespace tmu::tb {

// What the four level-0 banks hold (VolumePattern).
enum class VolumePattern : uint8_t { kRandom = 0, kMarschnerLobb = 1, kSphere = 2, kRamp = 3 };

// One configuration of the unit and the volume its banks hold.
struct VolumeSetup {
  volume::Config config;
  std::array<uint32_t, 3> size{2, 2, 2};
  VolumePattern pattern = VolumePattern::kRandom;
  uint32_t content = 0;  // the random bytes' seed
  friend bool operator==(const VolumeSetup&, const VolumeSetup&) = default;
};

// A volume as both faces hold it: the golden unit's banks and the timed runs' eight banks
// (banks 4-7 empty).
struct StoredVolume {
  volume::VolumeMemory memory;
  std::shared_ptr<const texram::TexramTexture> image;
};

// The volumes of a block's setups, built once and shared by its copies and engines.
class VolumeStore {
 public:
  // Throws std::invalid_argument (VolumeGeometry's) for a size the banks cannot hold.
  std::shared_ptr<const StoredVolume> get(const VolumeSetup& setup) const;
  // From now on `setup` names these voxels (of setup.size) instead of its pattern: a render's
  // chip, whose data is the host's (render/volume_engine_block.hpp). Throws as get() does.
  void hold(const VolumeSetup& setup, const volume::VoxelGrid& grid);

 private:
  mutable std::mutex mutex_;
  mutable std::vector<std::pair<VolumeSetup, std::shared_ptr<const StoredVolume>>> cache_;
};

class VolumeBlock : public DescribedBlockOf<VolumeBlock> {
 public:
  explicit VolumeBlock(const BlockOptions& options = {});
  // Over a given store (one that holds a render's voxels).
  VolumeBlock(const BlockOptions& options, std::shared_ptr<const VolumeStore> store);

  // The pages open in the memory (and golden's page model) when a run starts: a run that
  // continues another (a render's pieces) counts as the one long run would. None by default.
  void set_open_pages(const texram::OpenPages& open) { open_pages_ = open; }

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
  std::string repro_options() const override;

  const VolumeSetup& first() const { return first_; }
  const std::shared_ptr<const VolumeStore>& store() const { return store_; }

 private:
  // The rays of one volume, drawn: count of them.
  std::vector<Txn> random_rays(std::mt19937_64& rng, const VolumeSetup& setup, size_t count) const;
  VolumeSetup draw_setup(std::mt19937_64& rng) const;

  BlockOptions options_;
  std::shared_ptr<const VolumeStore> store_;
  texram::OpenPages open_pages_{};
  VolumeSetup first_;
  // cover() sees the items in order: the setup in effect.
  mutable size_t cover_next_ = 0;
  mutable VolumeSetup cover_setup_;
};

// ---- Items, for tests and tools ------------------------------------------------------------

Txn volume_cfg_item(const VolumeSetup& setup);
// The setup of a configuration item; std::invalid_argument naming the field and the reason
// for a mode, W, size or pattern outside what the unit and the environment take.
VolumeSetup volume_setup_of(const Txn& cfg);
Txn volume_ray_item(const volume::Ray& ray);
volume::Ray volume_ray_of(const Txn& item);
// An output's resample (the gradient sign-extended) and the ray's last flag.
volume::Resample volume_resample_of(const Txn& output);
// The output golden gives for a resample (`last` on its ray's last).
Txn volume_output_item(const volume::Resample& resample, bool last);
// The request of one access on the mem_req port: banks 0-3 as the plan reads them (address 0
// where a bank idles, as the RTL drives it), banks 4-7 never.
Txn volume_request_item(const volume::Access& access);

}  // namespace tmu::tb
