// The procedural noise hardware as two co-simulation blocks (002 §4.1; golden/perlin/noise.hpp):
//
// - `texsim cosim perlin`: the noise unit (rtl/perlin/tmu_noise.sv). Input items: u, v, w
//   (SolidCoord SQ12.12). Output: p (NoiseValue SQ0.11) = golden noise(NoiseConfig{}, u, v, w).
// - `texsim cosim turbulence`: the fractal sums of four octaves. The same inputs; outputs
//   fractal_sum and turbulence (FractalValue SQ2.14) = golden fractal_sums(NoiseConfig{}, ...).
//   Two RTL configurations with the same ports: pipelined (rtl/perlin/tmu_fractal_pipelined.sv,
//   four noise units, one sample per clock) and shared (tmu_fractal_shared.sv, the thesis's
//   one noise unit for the four octaves, one sample per 4 clocks), chosen by
//   BlockOptions::fractal_shared (`--fractal pipelined|shared`); the hls model follows it.
//
// Both run at the golden default widths (F = S = B = 8, X = 4), the ports' formats.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"
#include "perlin/noise.hpp"

namespace tmu::tb {

enum SolidCoordField { kSolidU, kSolidV, kSolidW };
enum PerlinOutField { kPerlinP };
enum TurbulenceOutField { kTurbSum, kTurbTurbulence };

// An item from raw SQ12.12 coordinates (each -2^23 .. 2^23 - 1); the coordinates of an item,
// sign-extended.
Txn solid_item(int32_t u, int32_t v, int32_t w);
std::array<int32_t, 3> solid_coords(const Txn& item);

// The golden noise's intermediate values at the default widths, for coverage and tests:
// per axis the lattice index (mod 2^12), the raw 12-bit fraction, the fade index and weight;
// the eight corners' lattice values (index du + 2 dv + 4 dw), the lerps' results, and
// whether a lerp rounded a tie (c (b - a) = 2^(B-1) mod 2^B) or stepped down (b < a).
struct NoiseTrace {
  std::array<uint32_t, 3> index{}, frac{}, fade_index{}, fade{};
  std::array<int32_t, 8> corner{};
  std::array<int32_t, 4> x{};
  std::array<int32_t, 2> y{};
  int32_t p = 0;
  bool tie = false;
  bool step_down = false;
};
NoiseTrace trace_noise(int64_t u, int64_t v, int64_t w);

// Directed coordinates shared by both blocks: lattice points (among them ones whose lattice
// value is -1.0 and +127/128), cell boundaries (raw fractions ..FFF, ..000, ..001, the fade
// index's edges), every fade index on every axis, negative coordinates, the SolidCoord
// extremes, coordinates whose octave shifts leave 24 bits, u = v = w.
std::vector<Txn> noise_directed_items();
// Random coordinates: uniform, near the origin, lattice points, cell boundaries, u = v = w,
// large (octave overflow), mixed per axis.
std::vector<Txn> noise_random_items(std::mt19937_64& rng, size_t count);

class PerlinBlock : public Block {
 public:
  std::string name() const override { return "perlin"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn&) const override { return true; }
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;

 private:
  // cover() sees every item in order; the fade indices seen so far per axis.
  mutable size_t cover_next_ = 0;
  mutable std::array<std::bitset<256>, 3> seen_fade_;
};

class TurbulenceBlock : public Block {
 public:
  explicit TurbulenceBlock(const BlockOptions& options = {});

  std::string name() const override { return "turbulence"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn&) const override { return true; }
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;
  std::string repro_options() const override;

  bool shared() const { return shared_; }

 private:
  bool shared_;
};

// The rtl engines for any Verilated model with the blocks' ports (tests use the mutants).
template <class Model>
std::unique_ptr<Engine> make_perlin_rtl_engine(const std::string& name);
template <class Model>
std::unique_ptr<Engine> make_turbulence_rtl_engine(const std::string& name);

}  // namespace tmu::tb

#include "blocks/perlin_rtl.inl"
