// The engines of the mutants' models: per model only its port accessors and a small wrapper
// (harness/rtl_model.hpp), ~0.2 s of compile each, in a file of their own.
#include "tests/mutant_cases.hpp"

#include <mutants.hpp>

#include "harness/described_engines.hpp"

namespace tmu::tb {

std::vector<MutantCase> mutant_cases() {
#define TMU_MUTANT_CASE(block, name, key, Model, expect, why) \
  {#block, #name, key, expect, why, rtl_level<desc::block, Model>("rtl")},
  return {TMU_MUTANTS(TMU_MUTANT_CASE)};
#undef TMU_MUTANT_CASE
}

}  // namespace tmu::tb
