// Every co-simulation block by name: what `texsim cosim BLOCK` and the tests instantiate.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "harness/block.hpp"

namespace tmu::tb {

struct BlockOptions {
  uint64_t seed = 1;
  std::string texture;    // ccc-bilinear: a .ccc file instead of a random texture
  bool lookahead = true;  // ccc-bilinear: neighbour prefetch
};

struct BlockInfo {
  std::string name;
  std::string summary;
};

std::vector<BlockInfo> block_list();
// Throws std::invalid_argument naming the known blocks when `name` is not one of them.
std::unique_ptr<Block> make_block(const std::string& name, const BlockOptions& options);

}  // namespace tmu::tb
