#include "blocks/registry.hpp"

#include <block_list.hpp>
#include <stdexcept>

namespace tmu::tb {

#define TMU_DECLARE_BLOCK(block)  \
  BlockInfo block_info_##block(); \
  std::unique_ptr<Block> make_block_##block(const BlockOptions& o);
TMU_BLOCKS(TMU_DECLARE_BLOCK)
#undef TMU_DECLARE_BLOCK

namespace {

struct Entry {
  BlockInfo (*info)();
  std::unique_ptr<Block> (*make)(const BlockOptions&);
};
#define TMU_BLOCK_ENTRY(block) {block_info_##block, make_block_##block},
const Entry kEntries[] = {TMU_BLOCKS(TMU_BLOCK_ENTRY)};
#undef TMU_BLOCK_ENTRY

std::string underscores(std::string s) {
  for (char& c : s) c = c == '-' ? '_' : c;
  return s;
}

}  // namespace

std::vector<BlockVariant> block_variants() {
#define TMU_VARIANT_ROW(block, key, top, options) {#block, key, top, options},
  return {TMU_BLOCK_VARIANTS(TMU_VARIANT_ROW)};
#undef TMU_VARIANT_ROW
}

std::vector<BlockInfo> block_list() {
  std::vector<BlockInfo> out;
  for (const Entry& e : kEntries) out.push_back(e.info());
  return out;
}

std::string block_name(const std::string& name) {
  const std::string n = underscores(name);
  for (const BlockInfo& b : block_list()) {
    if (b.name == n || underscores(b.name) == n) return b.name;
    for (const std::string& a : b.aliases) {
      if (a == name) return b.name;
    }
  }
  return "";
}

std::unique_ptr<Block> make_block(const std::string& name_or_alias, const BlockOptions& options) {
  const std::string name = block_name(name_or_alias);
  for (const Entry& e : kEntries) {
    if (e.info().name == name) return e.make(options);
  }
  std::string known;
  for (const BlockInfo& b : block_list()) known += (known.empty() ? "" : ", ") + b.name;
  throw std::invalid_argument("unknown block '" + name_or_alias + "' (blocks: " + known + ")");
}

}  // namespace tmu::tb
