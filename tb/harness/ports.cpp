#include "harness/ports.hpp"

#include <fmt/format.h>

#include <bit>
#include <stdexcept>

namespace tmu::tb {
namespace {

bool is_request(ChannelKind k) {
  return k == ChannelKind::kMemRequest || k == ChannelKind::kMemRequestNoReady;
}

// The field kinds each channel kind takes.
bool fits(ChannelKind c, FieldKind f) {
  switch (f) {
    case FieldKind::kIn:
      return is_stimulus(c);
    case FieldKind::kOut:
      return c == ChannelKind::kResult || c == ChannelKind::kCombOut;
    case FieldKind::kReq:
      return is_request(c);
    case FieldKind::kResp:
      return c == ChannelKind::kMemResponse;
    case FieldKind::kCfg:
    case FieldKind::kEnv:
      return c == ChannelKind::kCfg;
    case FieldKind::kStat:
      return c == ChannelKind::kStat;
  }
  return false;
}

}  // namespace

bool is_port(FieldKind k) { return k != FieldKind::kEnv; }

bool is_input_port(FieldKind k) {
  return k == FieldKind::kIn || k == FieldKind::kResp || k == FieldKind::kCfg;
}

void BlockPorts::channel(ChannelKind kind, const std::string& name) {
  if (channel_index(name) >= 0) {
    throw std::logic_error(fmt::format("{}: channel {} declared twice", block_, name));
  }
  PortChannel c;
  c.kind = kind;
  c.name = name;
  const auto port = [&](const char* what, bool input) {
    return fmt::format("{}_{}_{}", name, what, input ? "i" : "o");
  };
  switch (kind) {
    case ChannelKind::kSample:
    case ChannelKind::kWrite:
    case ChannelKind::kStream:
      c.valid_port = port("valid", true);
      c.ready_port = port("ready", false);
      break;
    case ChannelKind::kResult:
    case ChannelKind::kMemRequest:
      c.valid_port = port("valid", false);
      c.ready_port = port("ready", true);
      break;
    case ChannelKind::kMemRequestNoReady:
      c.valid_port = port("valid", false);
      break;
    case ChannelKind::kMemResponse:
      c.valid_port = port("valid", true);
      break;
    default:
      break;
  }
  rows_.push_back({true, static_cast<int>(channels_.size())});
  channels_.push_back(std::move(c));
}

void BlockPorts::field(FieldKind kind, const std::string& channel, const std::string& name,
                       const fx::Format& format, int count) {
  const int c = channel_index(channel);
  if (c < 0 || rows_.empty() ||
      (rows_.back().is_channel ? rows_.back().index
                               : fields_[size_t(rows_.back().index)].channel) != c) {
    throw std::logic_error(
        fmt::format("{}: field {} does not follow its channel {} or the channel's other fields",
                    block_, name, channel));
  }
  if (!fits(channels_[size_t(c)].kind, kind)) {
    throw std::logic_error(
        fmt::format("{}: field {} does not fit the kind of channel {}", block_, name, channel));
  }
  if (count < 1) throw std::logic_error(fmt::format("{}: field {}: count < 1", block_, name));
  PortField f{kind, name, format, count, c, 0, ""};
  if (is_port(kind)) {
    f.port = fmt::format("{}_{}_{}", channel, name, is_input_port(kind) ? "i" : "o");
  }
  channels_[size_t(c)].fields.push_back(static_cast<int>(fields_.size()));
  rows_.push_back({false, static_cast<int>(fields_.size())});
  fields_.push_back(std::move(f));
}

void BlockPorts::finish() {
  int results = 0;
  for (size_t c = 0; c < channels_.size(); ++c) {
    PortChannel& ch = channels_[c];
    if (takes_op(ch.kind)) ch.op = stimulus_channels_++;
    if (ch.kind == ChannelKind::kCfg) {
      if (cfg_ >= 0) throw std::logic_error(block_ + ": more than one Cfg channel");
      cfg_ = static_cast<int>(c);
      cfg_op_ = ch.op;
    }
    if (ch.kind == ChannelKind::kResult || ch.kind == ChannelKind::kCombOut) {
      result_ = static_cast<int>(c);
      ++results;
    }
  }
  if (results != 1) throw std::logic_error(block_ + ": a block has exactly one result channel");
  if (stimulus_channels_ == 0) throw std::logic_error(block_ + ": no stimulus channel");
  has_op_ = stimulus_channels_ > 1;

  // Inputs: op, then each stimulus channel's fields from the first free slot; the first
  // channel's fields keep their names, the others' carry the channel's name.
  std::vector<Field> in;
  const int first_slot = has_op_ ? 1 : 0;
  if (has_op_) {
    const int bits =
        std::max(1, static_cast<int>(std::bit_width(unsigned(stimulus_channels_ - 1))));
    in.push_back({"op", fx::UQ(bits, 0), 0, -1});
  }
  bool first = true;
  for (PortChannel& ch : channels_) {
    if (ch.op < 0) continue;
    const bool cfg = ch.kind == ChannelKind::kCfg;
    int slot = first_slot;
    for (const int fi : ch.fields) {
      PortField& f = fields_[size_t(fi)];
      f.slot = slot;
      for (int e = 0; e < f.count; ++e) {
        std::string n = first && !cfg ? f.name : ch.name + "_" + f.name;
        if (f.count > 1) n += fmt::format("{}", e);
        in.push_back({n, f.format, slot++, has_op_ ? ch.op : -1});
      }
    }
    first = first && cfg;
  }
  inputs_ = Schema(std::move(in));

  // Outputs and requests: their fields in order from slot 0.
  const auto schema_of = [this](PortChannel& ch) {
    std::vector<Field> out;
    int slot = 0;
    for (const int fi : ch.fields) {
      PortField& f = fields_[size_t(fi)];
      f.slot = slot;
      for (int e = 0; e < f.count; ++e) {
        out.push_back({f.count > 1 ? fmt::format("{}{}", f.name, e) : f.name, f.format, slot++});
      }
    }
    return Schema(std::move(out));
  };
  outputs_ = schema_of(channels_[size_t(result_)]);
  for (const int r : request_channels()) requests_.push_back(schema_of(channels_[size_t(r)]));
  for (const int r : response_channels()) schema_of(channels_[size_t(r)]);  // assigns slots
  int stat_slot = 0;
  for (PortField& f : fields_) {
    if (f.kind == FieldKind::kStat) f.slot = stat_slot++;
  }
}

const PortChannel& BlockPorts::channel(const std::string& name) const {
  const int c = channel_index(name);
  if (c < 0) throw std::logic_error(block_ + ": no channel " + name);
  return channels_[size_t(c)];
}

int BlockPorts::channel_index(const std::string& name) const {
  for (size_t c = 0; c < channels_.size(); ++c) {
    if (channels_[c].name == name) return static_cast<int>(c);
  }
  return -1;
}

int BlockPorts::channel_of(const Txn& item) const {
  const uint64_t op = has_op_ ? item.f[0] : 0;
  for (size_t c = 0; c < channels_.size(); ++c) {
    if (channels_[c].op >= 0 && uint64_t(channels_[c].op) == op) return static_cast<int>(c);
  }
  throw std::invalid_argument(fmt::format("{}: an item with op {}, not a channel", block_, op));
}

std::vector<int> BlockPorts::request_channels() const {
  std::vector<int> out;
  for (size_t c = 0; c < channels_.size(); ++c) {
    if (is_request(channels_[c].kind)) out.push_back(static_cast<int>(c));
  }
  return out;
}

std::vector<int> BlockPorts::response_channels() const {
  std::vector<int> out;
  for (size_t c = 0; c < channels_.size(); ++c) {
    if (channels_[c].kind == ChannelKind::kMemResponse) out.push_back(static_cast<int>(c));
  }
  return out;
}

bool BlockPorts::combinational() const {
  return channels_[size_t(result_)].kind == ChannelKind::kCombOut;
}

std::vector<std::string> BlockPorts::stats() const {
  std::vector<std::string> out;
  for (const PortField& f : fields_) {
    if (f.kind == FieldKind::kStat) out.push_back(f.name);
  }
  return out;
}

std::vector<BlockPorts::Port> BlockPorts::ports() const {
  std::vector<Port> out;
  if (!combinational()) out = {{"clk_i", 1, false, true}, {"rst_ni", 1, false, true}};
  for (const PortChannel& ch : channels_) {
    const bool valid_in = ch.valid_port.ends_with("_i");
    if (!ch.valid_port.empty()) out.push_back({ch.valid_port, 1, false, valid_in});
    if (!ch.ready_port.empty()) out.push_back({ch.ready_port, 1, false, !valid_in});
    for (const int fi : ch.fields) {
      const PortField& f = fields_[size_t(fi)];
      if (!is_port(f.kind)) continue;
      out.push_back({f.port, f.width(), f.count == 1 && f.format.is_signed, is_input_port(f.kind)});
    }
  }
  return out;
}

Txn channel_item(const BlockPorts& ports, const std::string& channel,
                 std::initializer_list<uint64_t> values) {
  const PortChannel& ch = ports.channel(channel);
  Txn t;
  if (ports.has_op()) t.f[0] = static_cast<uint64_t>(ch.op);
  size_t slot = ports.has_op() ? 1 : 0;
  for (const uint64_t v : values) t.f[slot++] = v;
  return ports.inputs().masked(t);
}

}  // namespace tmu::tb
