#include "blocks/ccc_decoder_block.hpp"

#include <Vtmu_ccc_decoder.h>

#include <chrono>

#include "ccc/ccc_decoder.hpp"
#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/ccc/ccc_decoder_sc.hpp"
#include "icarus/icarus_engine.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;

namespace {

const Schema kInputs({{"op", fx::UQ(1, 0)},
                      {"block", fmts::kCccBlock},
                      {"texel", fmts::kCccTexel},
                      {"clut_addr", fmts::kClutIndex},
                      {"clut_rgb", fmts::kRgb888}});
const Schema kOutputs({{"rgb", fmts::kRgb888}});

size_t count_decodes(const std::vector<Txn>& items) {
  size_t n = 0;
  for (const Txn& t : items) n += t.f[kDecOp] == kOpDecode;
  return n;
}

class GoldenEngine : public Engine {
 public:
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(count_decodes(items));
    const auto start = std::chrono::steady_clock::now();
    ccc::Clut clut{};
    for (const Txn& t : items) {
      if (t.f[kDecOp] == kOpClutWrite) {
        clut[t.f[kDecClutAddr]] = unpack_rgb(static_cast<uint32_t>(t.f[kDecClutRgb]));
      } else {
        Txn out;
        out.f[0] = ccc::decode_texel(static_cast<uint32_t>(t.f[kDecBlock]),
                                     static_cast<unsigned>(t.f[kDecTexel]), clut);
        r.outputs.push_back(out);
      }
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }
};

// The hls module with its signals, driven by the harness's ScDriver.
class HlsBench : public sc_core::sc_module, public ScAdapter {
 public:
  HlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n)
      : sc_module(name), dut_("dut") {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.clut_valid_i(clut_valid_);
    dut_.clut_ready_o(clut_ready_);
    dut_.clut_addr_i(clut_addr_);
    dut_.clut_rgb_i(clut_rgb_);
    dut_.req_valid_i(req_valid_);
    dut_.req_ready_o(req_ready_);
    dut_.req_block_i(req_block_);
    dut_.req_texel_i(req_texel_);
    dut_.out_valid_o(out_valid_);
    dut_.out_ready_i(out_ready_);
    dut_.out_rgb_o(out_rgb_);
  }
  void drive(const Txn* item) override {
    const bool write = item && item->f[kDecOp] == kOpClutWrite;
    const bool decode = item && item->f[kDecOp] == kOpDecode;
    clut_valid_.write(write);
    clut_addr_.write(write ? item->f[kDecClutAddr] : 0);
    clut_rgb_.write(write ? item->f[kDecClutRgb] : 0);
    req_valid_.write(decode);
    req_block_.write(decode ? item->f[kDecBlock] : 0);
    req_texel_.write(decode ? item->f[kDecTexel] : 0);
  }
  bool accepts(const Txn& item) const override {
    return item.f[kDecOp] == kOpClutWrite ? clut_ready_.read() : req_ready_.read();
  }
  void set_out_ready(bool ready) override { out_ready_.write(ready); }
  bool out_valid() const override { return out_valid_.read(); }
  Txn out() const override {
    Txn t;
    t.f[0] = out_rgb_.read();
    return t;
  }

 private:
  template <int W>
  using sig = sc_core::sc_signal<sc_dt::sc_uint<W>>;
  hls::CccDecoderSc dut_;
  sc_core::sc_signal<bool> clut_valid_{"clut_valid"}, clut_ready_{"clut_ready"};
  sig<fmts::kClutIndex.width()> clut_addr_{"clut_addr"};
  sig<fmts::kRgb888.width()> clut_rgb_{"clut_rgb"};
  sc_core::sc_signal<bool> req_valid_{"req_valid"}, req_ready_{"req_ready"};
  sig<fmts::kCccBlock.width()> req_block_{"req_block"};
  sig<fmts::kCccTexel.width()> req_texel_{"req_texel"};
  sc_core::sc_signal<bool> out_valid_{"out_valid"}, out_ready_{"out_ready"};
  sig<fmts::kRgb888.width()> out_rgb_{"out_rgb"};
};

class HlsEngine : public Engine {
 public:
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<HlsBench>(
        [](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<HlsBench>("bench", clk, rst_n);
        },
        items, count_decodes(items), options);
  }
};

}  // namespace

Txn decode_item(uint32_t block_word, unsigned texel) {
  Txn t;
  t.f[kDecOp] = kOpDecode;
  t.f[kDecBlock] = block_word;
  t.f[kDecTexel] = texel & 15u;
  return t;
}

Txn clut_write_item(uint8_t index, uint32_t rgb) {
  Txn t;
  t.f[kDecOp] = kOpClutWrite;
  t.f[kDecClutAddr] = index;
  t.f[kDecClutRgb] = rgb & 0xFFFFFFu;
  return t;
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
    img.pixels[i] = unpack_rgb(static_cast<uint32_t>(r.outputs[i].f[0]));
  if (run) *run = std::move(r);
  return img;
}

CccDecoderBlock::CccDecoderBlock(uint64_t seed) : seed_(seed) {}

const Schema& CccDecoderBlock::inputs() const { return kInputs; }
const Schema& CccDecoderBlock::outputs() const { return kOutputs; }

std::vector<Txn> CccDecoderBlock::setup_items() const {
  // Load every CLUT entry (the RAM has no reset) with colours drawn from the seed.
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

std::unique_ptr<Engine> CccDecoderBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<GoldenEngine>();
  if (level == "hls") return std::make_unique<HlsEngine>();
  if (level == "rtl") return make_ccc_decoder_rtl_engine<Vtmu_ccc_decoder>("rtl");
  if (level == "icarus") {
    return make_icarus_engine("icarus", {"ccc_decoder_tb", "tmu_ccc_decoder"}, kInputs, kOutputs,
                              [](const Txn& t) { return t.f[kDecOp] == kOpDecode; });
  }
  throw std::invalid_argument("ccc: no engine '" + level + "' (golden, hls, rtl, icarus)");
}

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
  const auto word = static_cast<uint32_t>(t.f[kDecBlock]);
  const auto texel = static_cast<unsigned>(t.f[kDecTexel]);
  const bool bit = (word >> texel) & 1u;
  const uint8_t idx = ccc::texel_index(word, texel);
  ++cov[bit ? "decision bit 1 (colour b)" : "decision bit 0 (colour a)"];
  if ((word >> 24) == ((word >> 16) & 0xFF)) ++cov["index a == index b"];
  if (idx == 0) ++cov["CLUT index 0"];
  if (idx == 255) ++cov["CLUT index 255"];
  if (texel == 0) ++cov["texel 0 (first)"];
  if (texel == 15) ++cov["texel 15 (last)"];
  if (index > 0 && items[index - 1].f[kDecOp] == kOpClutWrite) {
    ++cov["decode right after a CLUT write"];
    if (items[index - 1].f[kDecClutAddr] == idx) ++cov["read of an entry just rewritten"];
  }
}

std::vector<Port> CccDecoderBlock::ports() const {
  return {{"clk_i"},
          {"rst_ni"},
          {"clut_valid_i"},
          {"clut_ready_o"},
          {"clut_addr_i", fmts::kClutIndex.width()},
          {"clut_rgb_i", fmts::kRgb888.width()},
          {"req_valid_i"},
          {"req_ready_o"},
          {"req_block_i", fmts::kCccBlock.width()},
          {"req_texel_i", fmts::kCccTexel.width()},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_rgb_o", fmts::kRgb888.width()}};
}

}  // namespace tmu::tb
