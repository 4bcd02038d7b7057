// How the harness drives and samples a block through its port description, written once for
// every timed face: T is what holds the ports (a Verilated model, or the SystemC bench's
// signals), reached through one accessor pair per row of TMU_PORTS_<block>.
#pragma once

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "harness/environment.hpp"
#include "harness/ports.hpp"

namespace tmu::tb {

// The accessors of one row: `set` writes the row's input port (a field, or the channel's input
// handshake bit: valid of a stimulus or response, ready of a result or request), `get` reads
// its output port (a field, or the channel's output handshake bit). Elements of a packed
// field come and go one per uint64_t.
template <class T>
struct PortRow {
  void (*set)(T&, const uint64_t*) = nullptr;
  void (*get)(const T&, uint64_t*) = nullptr;
};

template <class T>
class PortLogic {
 public:
  PortLogic(const BlockPorts& ports, const std::vector<PortRow<T>>& rows,
            std::unique_ptr<Environment> env)
      : p_(ports), env_(std::move(env)) {
    channel_ops_.resize(p_.channels().size());
    field_ops_.resize(p_.fields().size());
    for (size_t r = 0; r < rows.size() && r < p_.rows().size(); ++r) {
      const BlockPorts::Row& row = p_.rows()[r];
      (row.is_channel ? channel_ops_ : field_ops_)[size_t(row.index)] = rows[r];
    }
    for (size_t c = 0; c < p_.channels().size(); ++c) {
      if (is_stimulus(p_.channels()[c].kind)) stimulus_.push_back(static_cast<int>(c));
    }
    cfg_ = p_.cfg_channel();
    requests_ = p_.request_channels();
    responses_ = p_.response_channels();
    env_ports_.requests.resize(requests_.size());
    env_ports_.responses.resize(responses_.size());
    log_.resize(requests_.size());
  }

  // Every input port at zero (the cfg ports until the first configuration item).
  void init(T& t) const {
    for (const PortRow<T>& ops : field_ops_) {
      if (ops.set) ops.set(t, kZeros.data());
    }
    for (const PortRow<T>& ops : channel_ops_) set_bit(t, ops, false);
  }
  void drive(T& t, const Txn* item) {
    presented_ = item != nullptr;
    const int ch = item ? p_.channel_of(*item) : -1;
    for (const int c : stimulus_) {
      const bool valid = c == ch;
      set_bit(t, channel_ops_[size_t(c)], valid);
      set_fields(t, c, valid ? item->f.data() : kZeros.data());
    }
  }
  // A combinational block takes its input in the cycle its output is taken.
  bool accepts(const T& t, const Txn& item) const {
    return get_bit(t, channel_ops_[size_t(p_.channel_of(item))], out_ready_);
  }
  void set_out_ready(T& t, bool ready) {
    out_ready_ = ready;
    set_bit(t, channel_ops_[size_t(p_.result_channel())], ready);
  }
  // A combinational block's output is valid in the cycle its input is presented.
  bool out_valid(const T& t) const {
    return get_bit(t, channel_ops_[size_t(p_.result_channel())], presented_);
  }
  Txn out(const T& t) const { return get_fields(t, p_.result_channel()); }
  void configure(T& t, const Txn& item) {
    if (cfg_ >= 0) set_fields(t, cfg_, item.f.data());
    if (env_) env_->configure(item);
  }
  void env_drive(T& t) {
    if (!env_) return;
    env_->drive(env_ports_);
    for (size_t r = 0; r < requests_.size(); ++r) {
      set_bit(t, channel_ops_[size_t(requests_[r])], env_ports_.requests[r].ready);
    }
    for (size_t r = 0; r < responses_.size(); ++r) {
      const ChannelValue& v = env_ports_.responses[r];
      set_bit(t, channel_ops_[size_t(responses_[r])], v.valid);
      set_fields(t, responses_[r], v.data.f.data());
    }
  }
  // Records every request that fires (valid and ready) in order, then lets the env sample.
  void env_sample(const T& t) {
    for (size_t r = 0; r < requests_.size(); ++r) {
      ChannelValue& v = env_ports_.requests[r];
      v.valid = get_bit(t, channel_ops_[size_t(requests_[r])], false);
      v.data = get_fields(t, requests_[r]);
      if (!env_ || p_.channels()[size_t(requests_[r])].ready_port.empty()) v.ready = true;
      if (v.valid && v.ready) log_[r].push_back(v.data);
    }
    if (env_) env_->sample(env_ports_);
  }
  bool quiet() const {
    for (const ChannelValue& v : env_ports_.requests) {
      if (v.valid) return false;
    }
    return !env_ || env_->idle();
  }
  // The stat ports, the environment's counters and error, and the requests.
  void finish(const T& t, RunResult& result) {
    for (size_t f = 0; f < p_.fields().size(); ++f) {
      const PortField& field = p_.fields()[f];
      if (field.kind != FieldKind::kStat) continue;
      uint64_t v = 0;
      field_ops_[f].get(t, &v);
      result.counters.emplace_back(field.name, v);
    }
    if (env_) {
      for (auto& c : env_->counters()) result.counters.push_back(std::move(c));
      if (const std::string e = env_->error(); !e.empty()) {
        result.error += (result.error.empty() ? "" : "; ") + e;
      }
    }
    result.requests = std::move(log_);
  }

 private:
  static constexpr std::array<uint64_t, kMaxFields> kZeros{};

  static void set_bit(T& t, const PortRow<T>& ops, bool value) {
    const uint64_t v = value;
    if (ops.set) ops.set(t, &v);
  }
  // A channel without that handshake port answers `otherwise`.
  static bool get_bit(const T& t, const PortRow<T>& ops, bool otherwise) {
    if (!ops.get) return otherwise;
    uint64_t v = 0;
    ops.get(t, &v);
    return v != 0;
  }
  // The fields of channel c from (into) the slots of a Txn.
  void set_fields(T& t, int c, const uint64_t* slots) const {
    for (const int fi : p_.channels()[size_t(c)].fields) {
      const PortRow<T>& ops = field_ops_[size_t(fi)];
      if (ops.set) ops.set(t, slots + p_.fields()[size_t(fi)].slot);
    }
  }
  Txn get_fields(const T& t, int c) const {
    Txn out;
    for (const int fi : p_.channels()[size_t(c)].fields) {
      field_ops_[size_t(fi)].get(t, out.f.data() + p_.fields()[size_t(fi)].slot);
    }
    return out;
  }

  const BlockPorts& p_;
  std::unique_ptr<Environment> env_;
  std::vector<PortRow<T>> channel_ops_, field_ops_;
  std::vector<int> stimulus_, requests_, responses_;
  int cfg_ = -1;
  EnvPorts env_ports_;
  std::vector<std::vector<Txn>> log_;  // the requests that fired, per request channel
  bool presented_ = false;
  bool out_ready_ = false;
};

}  // namespace tmu::tb
