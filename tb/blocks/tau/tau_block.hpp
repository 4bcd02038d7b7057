// The tau unit as a co-simulation block, `texsim cosim tau`: (s, t) PcCoord and their screen
// derivatives -> (u, v), r1, r2, lambda through a grid of (u, v) nodes, linear or Catmull-Rom
// (004: EP0637814 claims 4-6, 15; golden/tau/tau_unit.hpp, rtl/tau/tmu_tau.sv,
// hls/tau/tau_sc.hpp).
//
// Channels (tau.json): in (a fragment) gives one result; node writes a node of the memory and
// gives none; cfg is the grid's cells and interpolation. The stimulus starts with a grid's
// configuration and the writes of all its nodes (the memory is a RAM without reset); a random
// run draws a new grid (random, smooth, affine, folded or extreme nodes; 1..16 cells a side;
// either interpolation) every few thousand items and writes it, as a driver between batches.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/tau/tau_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "tau/tau_unit.hpp"

TMU_DESCRIBE(tau)

namespace tmu::tb {

// A grid as a driver writes it: its configuration and its nodes, raw SQ16.8, node (i, j) at
// i + (cells_s + 1) j.
struct TauGrid {
  tau::Config config;
  std::vector<int32_t> u, v;
};

enum class TauGridKind : uint8_t { kRandom, kSmooth, kAffine, kFolded, kExtreme };
// A grid of the given kind drawn from rng. Affine grids have integer node steps, so the map
// they sample is affine exactly; folded ones reverse s's direction inside the grid (the
// Jacobian's determinant changes sign); extreme ones put nodes at the ends of SQ16.8.
TauGrid draw_tau_grid(std::mt19937_64& rng, TauGridKind kind, int cells_s, int cells_t,
                      tau::Interp interp);

class TauBlock : public DescribedBlockOf<TauBlock> {
 public:
  explicit TauBlock(const BlockOptions& options = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;

  const TauGrid& first_grid() const { return first_; }

 private:
  TauGrid first_;
  // cover() sees the items in order: a unit replaying them, for the traces.
  mutable size_t cover_next_ = 0;
  mutable tau::TauUnit cover_unit_;
  mutable bool cover_clamped_ = false;  // the configuration in effect had cells 0 or > 16
};

// Item constructors, for tests and tools.
Txn tau_config_item(const tau::Config& config);
Txn tau_node_item(uint32_t addr, int32_t u, int32_t v);
Txn tau_sample_item(const tau::Request& request);
// The configuration item and the writes of every node of a grid.
std::vector<Txn> tau_load_items(const TauGrid& grid);
// A sample item's request and a result's fields, sign-extended.
tau::Request tau_request_of(const Txn& item);
tau::Result tau_result_of(const Txn& output);

}  // namespace tmu::tb
