// The fractal sums of four octaves as a co-simulation block, `texsim cosim fractal` (alias
// turbulence): (u, v, w) SolidCoord -> sum and turbulence (FractalValue SQ2.14) = golden
// fractal_sums(NoiseConfig{}, u, v, w) (002 §4.1.1; golden/perlin/noise.hpp). Two RTL
// configurations with the same ports: pipelined (rtl/perlin/tmu_fractal_pipelined.sv, four
// noise units, one sample per clock) and shared (tmu_fractal_shared.sv, the thesis's one noise
// unit for the four octaves, one sample per 4 clocks), chosen by BlockOptions::fractal_shared
// (`--fractal pipelined|shared`); the hls model (hls/perlin/fractal_sc.hpp) follows it.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/fractal/fractal_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(fractal)

namespace tmu::tb {

class FractalBlock : public DescribedBlockOf<FractalBlock> {
 public:
  explicit FractalBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;
  std::unique_ptr<Model> ideal() const override;
  std::string variant() const override;

  bool shared() const { return shared_; }

 private:
  bool shared_;
};

}  // namespace tmu::tb
