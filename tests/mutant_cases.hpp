// Every mutant of rtl/blocks.cmake, with the factory of an rtl engine that runs its model, for
// the conformance suite (tests/conformance_test.cpp).
#pragma once

#include <string>
#include <vector>

#include "harness/described_block.hpp"

namespace tmu::tb {

struct MutantCase {
  std::string block, name, key, expect, why;
  DescribedBlock::EngineFactory rtl;
};

std::vector<MutantCase> mutant_cases();

}  // namespace tmu::tb
