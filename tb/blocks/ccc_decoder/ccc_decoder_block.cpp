#include "blocks/ccc_decoder/ccc_decoder_block.hpp"

#include <fmt/format.h>

#include <bitset>
#include <stdexcept>

#include "ccc/ccc_decoder.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/ccc/ccc_decoder_sc.hpp"
#include "rtl_models_ccc_decoder.hpp"

TMU_DESCRIBE_SC(ccc_decoder)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::ccc_decoder;

namespace {

// The decoder item by item: a write sets its entry, a decode reads the CLUT as the writes
// before it left it. The RTL's CLUT has no reset, so a decode of an entry no write has set has
// no defined colour: golden refuses it rather than guess.
class Golden : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    if (item.f[0] == D::op_clut) {
      const auto addr = static_cast<uint8_t>(item.f[D::clut_addr]);
      clut_[addr] = unpack_rgb(static_cast<uint32_t>(item.f[D::clut_rgb]));
      written_.set(addr);
      return;
    }
    const auto word = static_cast<uint32_t>(item.f[D::req_block]);
    const auto texel = static_cast<unsigned>(item.f[D::req_texel]);
    const uint8_t index = ccc::texel_index(word, texel);
    if (!written_.test(index)) {
      throw std::runtime_error(fmt::format(
          "ccc_decoder: a decode of CLUT entry {} before any write to it (the CLUT is a RAM "
          "without reset: load every entry a decode reads)",
          index));
    }
    Txn out;
    out.f[D::out_rgb] = ccc::decode_texel(word, texel, clut_);
    sink.output(out);
  }

 private:
  ccc::Clut clut_{};
  std::bitset<fmts::kClutEntries> written_;
};

}  // namespace

Txn decode_item(uint32_t block_word, unsigned texel) {
  return channel_item(D::table(), "req", {block_word, texel});
}

Txn clut_write_item(uint8_t index, uint32_t rgb) {
  return channel_item(D::table(), "clut", {index, rgb});
}

ImageRgb8 decode_with_engine(const ccc::Texture& tex, Engine& engine, RunResult* run) {
  std::vector<Txn> items;
  items.reserve(fmts::kClutEntries + size_t{tex.width} * tex.height);
  for (int i = 0; i < fmts::kClutEntries; ++i) {
    items.push_back(
        clut_write_item(static_cast<uint8_t>(i), pack_rgb(tex.clut[static_cast<size_t>(i)])));
  }
  for (uint32_t y = 0; y < tex.height; ++y) {
    for (uint32_t x = 0; x < tex.width; ++x) {
      items.push_back(decode_item(tex.block_word(x / 4, y / 4), 4 * (y % 4) + x % 4));
    }
  }
  RunResult r = engine.run(items, RunOptions{});
  if (!r.error.empty()) throw std::runtime_error(engine.name() + " decoder run failed: " + r.error);
  ImageRgb8 img(static_cast<int>(tex.width), static_cast<int>(tex.height));
  if (r.outputs.size() != img.pixels.size())
    throw std::runtime_error(engine.name() + ": wrong output count");
  for (size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = unpack_rgb(static_cast<uint32_t>(r.outputs[i].f[D::out_rgb]));
  if (run) *run = std::move(r);
  return img;
}

CccDecoderBlock::CccDecoderBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), seed_(options.seed) {
  add_level("hls", hls_level<desc::ccc_decoder_sc, hls::CccDecoderSc>());
  TMU_ADD_RTL_LEVELS(ccc_decoder, variant());
}

std::vector<Txn> CccDecoderBlock::setup_items() const {
  // Every CLUT entry, with colours drawn from the seed.
  std::mt19937_64 rng(seed_ ^ 0xC1u);
  std::vector<Txn> items;
  for (int i = 0; i < fmts::kClutEntries; ++i) {
    items.push_back(clut_write_item(static_cast<uint8_t>(i), static_cast<uint32_t>(rng())));
  }
  return items;
}

std::vector<Txn> CccDecoderBlock::directed_items() const {
  std::vector<Txn> items;
  // Every texel address with only its own decision bit set, and with all others set.
  for (unsigned t = 0; t < 16; ++t) {
    items.push_back(decode_item(0x11220000u | (1u << t), t));
    items.push_back(decode_item(0x3344FFFFu & ~(1u << t), t));
  }
  // The extreme CLUT indices, and a == b.
  items.push_back(decode_item(0x00FF0000u, 0));
  items.push_back(decode_item(0x00FFFFFFu, 15));
  items.push_back(decode_item(0xFF00A5A5u, 0));
  items.push_back(decode_item(0x7777FFFFu, 9));
  // A write followed at once by a read of the same entry, and back-to-back writes.
  items.push_back(clut_write_item(0x42, 0xABCDEF));
  items.push_back(decode_item(0x42000000u, 3));
  items.push_back(clut_write_item(0x42, 0x000000));
  items.push_back(clut_write_item(0x43, 0xFFFFFF));
  items.push_back(decode_item(0x43420001u, 0));
  items.push_back(decode_item(0x43420001u, 1));
  return items;
}

std::vector<Txn> CccDecoderBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t r = rng();
    if ((r & 63) == 0) {  // one item in 64 rewrites a CLUT entry
      items.push_back(
          clut_write_item(static_cast<uint8_t>(r >> 8), static_cast<uint32_t>(r >> 16)));
    } else {
      items.push_back(decode_item(static_cast<uint32_t>(r >> 32), static_cast<unsigned>(r >> 8)));
    }
  }
  return items;
}

std::unique_ptr<Model> CccDecoderBlock::golden() const { return std::make_unique<Golden>(); }

std::vector<std::string> CccDecoderBlock::coverage_cases() const {
  return {"decision bit 0 (colour a)",
          "decision bit 1 (colour b)",
          "index a == index b",
          "CLUT index 0",
          "CLUT index 255",
          "texel 0 (first)",
          "texel 15 (last)",
          "decode right after a CLUT write",
          "read of an entry just rewritten"};
}

void CccDecoderBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                            Coverage& cov) const {
  const Txn& t = items[index];
  const auto word = static_cast<uint32_t>(t.f[D::req_block]);
  const auto texel = static_cast<unsigned>(t.f[D::req_texel]);
  const bool bit = (word >> texel) & 1u;
  const uint8_t idx = ccc::texel_index(word, texel);
  ++cov[bit ? "decision bit 1 (colour b)" : "decision bit 0 (colour a)"];
  if ((word >> 24) == ((word >> 16) & 0xFF)) ++cov["index a == index b"];
  if (idx == 0) ++cov["CLUT index 0"];
  if (idx == 255) ++cov["CLUT index 255"];
  if (texel == 0) ++cov["texel 0 (first)"];
  if (texel == 15) ++cov["texel 15 (last)"];
  if (index > 0 && items[index - 1].f[0] == D::op_clut) {
    ++cov["decode right after a CLUT write"];
    if (items[index - 1].f[D::clut_addr] == idx) ++cov["read of an entry just rewritten"];
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(ccc_decoder, CccDecoderBlock)
