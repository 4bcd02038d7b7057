// The heap of every program of the project (texsim, the tests, the benchmarks) keeps large
// blocks it frees instead of returning them to the kernel.
//
// Why: a run records every transaction and memory request of a block (tb/harness/txn.hpp, 256
// bytes each), and a render's runs grow vectors of hundreds of megabytes, freed and grown again
// pass after pass. By default glibc maps every block above 32 MiB afresh and unmaps it when
// freed, so each pass faults in (and the kernel zeroes) every page again: a third of the test
// suite's CPU time was the kernel's (`/usr/bin/time` on `ctest`). With the thresholds at 1 GiB
// the freed space is reused: RenderChipTest.EveryBundledChainGivesTheSameColoursOnTheChip 11.2
// -> 5.6 s and `tests/sweep_clipmap_test.sh` 28.9 -> 15.6 s, their peak memory 0.96 -> 1.22 GB
// and 1.79 -> 1.85 GB; the default ctest's summed test time 711 -> 618 s (measured 2026-12-04).
//
// An object library's static initialiser, so that it runs before main in every program that
// links it, tests whose main is GoogleTest's included. Under AddressSanitizer (its own
// allocator) mallopt does nothing, which is harmless.
#include <malloc.h>

namespace {

constexpr int kKeep = 1 << 30;  // bytes: blocks up to this size come from (and stay in) the heap

[[maybe_unused]] const bool heap_tuned = [] {
  mallopt(M_MMAP_THRESHOLD, kKeep);
  mallopt(M_TRIM_THRESHOLD, kKeep);
  return true;
}();

}  // namespace
