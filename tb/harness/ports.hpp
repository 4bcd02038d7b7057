// A block's port list, written once, and what the harness derives from it.
//
// Each block describes its top-level ports in its description, tb/blocks/<block>/<block>.json
// (docs/harness.md, "The block description"), which scripts/gen_block_descriptions.py turns at
// configure time into the X-macro TMU_PORTS_<block>(C, F) of blocks/<block>/<block>_ports.hpp
// (in build/generated/descriptions): a C row per channel, an F row per field. For the noise
// unit (rtl/perlin/tmu_noise.sv), the description's
//
//   "channels": [{"channel": "in", "kind": "Sample", "fields": {"u": "SolidCoord", ...}},
//                {"channel": "out", "kind": "Result", "fields": {"p": "NoiseValue"}}]
// gives
//   #define TMU_PORTS_noise(C, F)
//     C(Sample, in)                   in_valid_i, in_ready_o; one output per item
//     F(In, in, u, SolidCoord, 1)     in_u_i, format SolidCoord of formats.def
//     F(In, in, v, SolidCoord, 1)
//     F(In, in, w, SolidCoord, 1)
//     C(Result, out)                  out_valid_o, out_ready_i
//     F(Out, out, p, NoiseValue, 1)
// (each row ends in a backslash, as a macro's lines do).
//
// Channels (C rows), with the handshake ports they imply:
//   Sample   stimulus, <ch>_valid_i / <ch>_ready_o; each item gives one output transaction
//   Write    stimulus, the same ports; its items give no output (a CLUT or register write)
//   Stream   stimulus, the same ports; the block says how many outputs its items give
//   Result   the block's output transactions, <ch>_valid_o / <ch>_ready_i (exactly one)
//   MemRequest         requests to the environment, <ch>_valid_o / <ch>_ready_i
//   MemRequestNoReady  requests to the environment, <ch>_valid_o (always taken)
//   MemResponse        answers of the environment, <ch>_valid_i
//   CombIn, CombOut    the stimulus and result of a combinational block: no handshake ports
//   Cfg      the quasi-static configuration: its items are written between batches
//   Stat     the statistics counters, read when the run ends
// A channel's F rows follow its C row.
// Fields (F rows): F(kind, channel, name, Format, count) is the port <channel>_<name>_i for
// kinds In, Resp, Cfg and <channel>_<name>_o for Out, Req, Stat; count > 1 packs that many
// elements of the format into one port, element e in bits [e W, (e + 1) W). Kinds:
//   In, Out      fields of a stimulus channel and of the result
//   Req, Resp    fields of a memory request and response channel
//   Cfg          a field of the Cfg channel: a configuration input, e.g. cfg_<name>_i
//   Env          a field of the Cfg channel that is not a port (e.g. the seed of the texture
//                the environment holds)
//   Stat         a field of the Stat channel: a counter, e.g. stat_<name>_o
//
// The harness numbers the stimulus channels and the Cfg channel in row order (the op). Input items
// are Txn with the channel in field 0 (`op`) when there is more than one, and the channel's fields
// from the next slot on: the channels share the slots. Outputs are the Result fields in order; the
// requests of each memory request channel are its Req fields.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/formats.hpp"
#include "harness/txn.hpp"

namespace tmu::tb {

enum class ChannelKind {
  kSample,
  kWrite,
  kStream,
  kResult,
  kMemRequest,
  kMemRequestNoReady,
  kMemResponse,
  kCombIn,
  kCombOut,
  kCfg,   // the configuration: no handshake, written between batches
  kStat,  // the statistics counters
};

enum class FieldKind { kIn, kOut, kReq, kResp, kCfg, kEnv, kStat };

// Sample, Write, Stream, CombIn.
constexpr bool is_stimulus(ChannelKind k) {
  return k == ChannelKind::kSample || k == ChannelKind::kWrite || k == ChannelKind::kStream ||
         k == ChannelKind::kCombIn;
}
// The channels numbered by the op field: the stimulus kinds and Cfg.
constexpr bool takes_op(ChannelKind k) { return is_stimulus(k) || k == ChannelKind::kCfg; }
bool is_port(FieldKind k);        // every kind but Env
bool is_input_port(FieldKind k);  // In, Resp, Cfg

struct PortField {
  FieldKind kind;
  std::string name;  // as written in the row
  fx::Format format;
  int count = 1;     // elements packed in the port
  int channel = 0;   // index into BlockPorts::channels()
  int slot = 0;      // Txn field of its first element
  std::string port;  // the RTL port name, e.g. in_u_i ("" for Env)
  int width() const { return format.width() * count; }
};

struct PortChannel {
  ChannelKind kind = ChannelKind::kSample;
  std::string name;
  int op = -1;              // stimulus and cfg: the value of the op field; else -1
  std::vector<int> fields;  // indices into BlockPorts::fields()
  // The handshake ports ("" where the kind has none).
  std::string valid_port, ready_port;
};

class BlockPorts {
 public:
  // Built by TMU_DESCRIBE_PORTS from the rows, in order.
  explicit BlockPorts(std::string block) : block_(std::move(block)) {}
  void channel(ChannelKind kind, const std::string& name);
  void field(FieldKind kind, const std::string& channel, const std::string& name,
             const fx::Format& format, int count);
  // Checks the rows (one result, fields after their channel, ...) and derives the schemas;
  // throws std::logic_error naming the block and the row.
  void finish();

  const std::string& block() const { return block_; }
  const std::vector<PortChannel>& channels() const { return channels_; }
  const std::vector<PortField>& fields() const { return fields_; }
  // The rows in the order written: a C row names a channel, an F row a field.
  struct Row {
    bool is_channel;
    int index;  // into channels() or fields()
  };
  const std::vector<Row>& rows() const { return rows_; }
  // The channel of a name; throws std::logic_error when absent.
  const PortChannel& channel(const std::string& name) const;
  int channel_index(const std::string& name) const;  // -1 when absent

  bool has_op() const { return has_op_; }
  int stimulus_channels() const { return stimulus_channels_; }  // cfg included
  // The channel index of an input item (its op, or the one stimulus channel).
  int channel_of(const Txn& item) const;
  int cfg_op() const { return cfg_op_; }    // -1 without a Cfg channel
  int cfg_channel() const { return cfg_; }  // -1 without a Cfg channel
  bool is_cfg(const Txn& item) const {
    return cfg_op_ >= 0 && has_op_ && item.f[0] == uint64_t(cfg_op_);
  }
  int result_channel() const { return result_; }
  std::vector<int> request_channels() const;   // MemRequest and MemRequestNoReady, in order
  std::vector<int> response_channels() const;  // MemResponse
  bool combinational() const;

  // Input items: op (when there is one) and every stimulus and cfg field, each with the op it
  // belongs to; outputs: the result fields; requests: one schema per request channel.
  const Schema& inputs() const { return inputs_; }
  const Schema& outputs() const { return outputs_; }
  const Schema& requests(int request_index) const { return requests_.at(size_t(request_index)); }
  // The stat counters' names, in row order.
  std::vector<std::string> stats() const;
  // Every port with its width: clk_i, rst_ni, then the rows' ports in order (GTKWave, tests).
  struct Port {
    std::string name;
    int width = 1;
    bool is_signed = false;
    bool input = true;
  };
  std::vector<Port> ports() const;

 private:
  std::string block_;
  std::vector<PortChannel> channels_;
  std::vector<PortField> fields_;
  std::vector<Row> rows_;
  bool has_op_ = false;
  int stimulus_channels_ = 0;
  int cfg_op_ = -1;
  int cfg_ = -1;
  int result_ = -1;
  Schema inputs_{{}}, outputs_{{}};
  std::vector<Schema> requests_;
};

// An item of stimulus channel `channel` (its op set when the block has one) with the given
// values of its fields in row order (an element of a packed field each); masked to the ports.
Txn channel_item(const BlockPorts& ports, const std::string& channel,
                 std::initializer_list<uint64_t> values);

}  // namespace tmu::tb

// The rows as BlockPorts calls, for TMU_DESCRIBE (harness/describe.hpp).
#define TMU_PORTS_BUILD_C(kind, ch) b.channel(::tmu::tb::ChannelKind::k##kind, #ch);
#define TMU_PORTS_BUILD_F(kind, ch, name, fmt, n) \
  b.field(::tmu::tb::FieldKind::k##kind, #ch, #name, ::tmu::formats::k##fmt, n);
