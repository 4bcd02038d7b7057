#include "texram/page_model.hpp"

namespace tmu::texram {

int PageModel::access(const std::array<std::optional<uint32_t>, 8>& addresses) {
  ++stats_.accesses;
  bool fault = false;
  for (size_t b = 0; b < 8; ++b) {
    if (!addresses[b]) continue;
    ++stats_.bank_reads;
    const uint32_t page = *addresses[b] >> kPageBits;
    if (open_page_[b] != page) {
      ++stats_.page_faults;
      open_page_[b] = page;
      fault = true;
    }
  }
  stats_.slow_accesses += fault;
  return fault ? 2 : 1;
}

}  // namespace tmu::texram
