// DRAM page timing of the eight banks (000 §5): each bank keeps one page open; reading a cell
// of the open page is one access (30 ns), a page fault costs one access more (60 ns). The
// eight banks are read in parallel, so an access of the unit takes two periods when any bank
// it reads faults. The golden model predicts these counts exactly; the hls and rtl memory
// models use this class for their latency, so the timing of every run follows from it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "formats/formats.hpp"

namespace tmu::texram {

inline constexpr int kPageBits = formats::kPageLog2;  // 512 cells per DRAM page
inline constexpr uint32_t kPageCells = uint32_t{1} << kPageBits;
// `cells` rounded up to whole pages: where the next page-aligned map may start.
constexpr uint32_t page_up(uint64_t cells) {
  return static_cast<uint32_t>((cells + kPageCells - 1) / kPageCells * kPageCells);
}
inline constexpr double kAccessNs = 30.0;  // page hit (§5); a fault adds as much again
inline constexpr double kUnitClockMhz = 1e3 / kAccessNs;  // one access per clock: 33.3 MHz

struct PageStats {
  uint64_t accesses = 0;       // accesses of the unit (all banks in parallel)
  uint64_t bank_reads = 0;     // bank reads within them
  uint64_t page_faults = 0;    // bank reads that missed the open page
  uint64_t slow_accesses = 0;  // accesses that took two periods
  friend bool operator==(const PageStats&, const PageStats&) = default;
};

// The page open in each bank (none before the bank's first read).
using OpenPages = std::array<std::optional<uint32_t>, 8>;

class PageModel {
 public:
  // `open`: the pages already open, so that a run cut into pieces (a render's batches through
  // the co-simulated volume unit) counts as the one long run would; by default none.
  explicit PageModel(const OpenPages& open = {}) : open_page_(open) {}
  // One access reading the given address in each bank (nothing where empty). Returns the
  // periods it takes: 1, or 2 on a page fault in any bank it reads.
  int access(const std::array<std::optional<uint32_t>, 8>& addresses);
  const PageStats& stats() const { return stats_; }
  const OpenPages& open_pages() const { return open_page_; }

 private:
  OpenPages open_page_{};
  PageStats stats_;
};

}  // namespace tmu::texram
