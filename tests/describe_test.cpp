// The compile-time constants of a description (harness/describe.hpp: field slots, channel
// ops) agree with the table the harness builds from the same rows at run time, and the table
// derives what the rows say (schemas, ports, the op field).
#include <gtest/gtest.h>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_block.hpp"
#include "blocks/noise/noise_block.hpp"

namespace tmu::tb {
namespace {

// The slot of a field in the runtime table.
int slot_of(const BlockPorts& p, const std::string& channel, const std::string& field) {
  for (const PortField& f : p.fields()) {
    if (f.name == field && p.channels()[size_t(f.channel)].name == channel) return f.slot;
  }
  return -1;
}

TEST(DescribeTest, OneChannelBlockHasNoOpField) {
  using D = desc::noise;
  const BlockPorts& p = D::table();
  EXPECT_FALSE(p.has_op());
  EXPECT_EQ(D::in_u, 0);
  EXPECT_EQ(D::in_w, 2);
  EXPECT_EQ(D::out_p, 0);
  EXPECT_EQ(D::op_in, 0u);
  EXPECT_EQ(slot_of(p, "in", "w"), D::in_w);
  ASSERT_EQ(p.inputs().size(), 3u);
  EXPECT_EQ(p.inputs().field(0).name, "u");
  EXPECT_EQ(p.ports().size(), 2u + 2 + 3 + 2 + 1);  // clk, rst, in handshake + 3, out + 1
}

TEST(DescribeTest, ChannelsShareTheSlotsAfterTheOp) {
  using D = desc::ccc_cache_bilinear;
  const BlockPorts& p = D::table();
  EXPECT_TRUE(p.has_op());
  EXPECT_EQ(D::op_req, 0u);
  EXPECT_EQ(D::op_clut, 1u);
  EXPECT_EQ(D::op_cfg, 2u);
  EXPECT_EQ(D::op_out, kNoOp);
  EXPECT_EQ(p.cfg_op(), 2);
  for (const auto& [channel, field, slot] : std::vector<std::tuple<std::string, std::string, int>>{
           {"req", "u", D::req_u},
           {"req", "v", D::req_v},
           {"clut", "addr", D::clut_addr},
           {"clut", "rgb", D::clut_rgb},
           {"cfg", "width", D::cfg_width},
           {"cfg", "texture", D::cfg_texture},
           {"mem_req", "addr", D::mem_req_addr},
           {"mem_resp", "block", D::mem_resp_block},
           {"out", "rgb", D::out_rgb},
           {"stat", "prefetches", D::stat_prefetches}}) {
    EXPECT_EQ(slot_of(p, channel, field), slot) << channel << "." << field;
  }
  EXPECT_EQ(D::req_u, 1);
  EXPECT_EQ(D::clut_addr, 1);
  EXPECT_EQ(D::cfg_texture, 4);
  EXPECT_EQ(D::mem_req_addr, 0);
  // Names: the first channel's fields bare, the others' with their channel.
  EXPECT_GE(p.inputs().index("u"), 0);
  EXPECT_GE(p.inputs().index("clut_rgb"), 0);
  EXPECT_GE(p.inputs().index("cfg_lookahead"), 0);
  // The Env field is an input field but not a port.
  for (const BlockPorts::Port& port : p.ports()) EXPECT_NE(port.name, "cfg_texture_i");
  EXPECT_EQ(p.stats(), (std::vector<std::string>{"hits", "misses", "prefetches"}));
}

// An item masked by the schema keeps its own channel's fields only.
TEST(DescribeTest, MaskingKeepsTheItemsChannel) {
  using D = desc::ccc_cache_bilinear;
  Txn t;
  t.f[0] = D::op_clut;
  t.f[1] = 0x1FF;       // clut addr: 8 bits
  t.f[2] = 0x12345678;  // clut rgb: 24 bits
  t.f[4] = 7;           // no field of clut
  const Txn m = D::table().inputs().masked(t);
  EXPECT_EQ(m.f[1], 0xFFu);
  EXPECT_EQ(m.f[2], 0x345678u);
  EXPECT_EQ(m.f[4], 0u);
}

}  // namespace
}  // namespace tmu::tb
