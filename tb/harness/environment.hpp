// What answers a block's memory channels in a timed run (hls, rtl): a memory model with its
// latency, written once per block and shared by every timed level, because it sees the
// block's ports only as the description's channels.
#pragma once

#include <string>
#include <vector>

#include "harness/engine.hpp"
#include "harness/txn.hpp"

namespace tmu::tb {

// One channel's handshake and fields in a cycle.
struct ChannelValue {
  bool valid = false;
  bool ready = true;
  Txn data;  // the channel's fields, from slot 0 (BlockPorts::fields()[..].slot)
};

// The environment's side of the ports in a cycle, in the order of
// BlockPorts::request_channels() and response_channels().
struct EnvPorts {
  std::vector<ChannelValue> requests;   // the block drives valid and data; the env ready
  std::vector<ChannelValue> responses;  // the env drives valid and data
};

class Environment {
 public:
  virtual ~Environment() = default;
  // A configuration item (e.g. a new texture in the memory), applied while the block is quiet.
  virtual void configure(const Txn&) {}
  // Before the block settles: the env's values for this cycle, each request's ready and each
  // response; the same values until sample().
  virtual void drive(EnvPorts& ports) = 0;
  // Before the edge: the block's requests as it shows them (ports.requests[r].valid and data,
  // ready as drive() set it). Ends the cycle.
  virtual void sample(const EnvPorts& ports) = 0;
  // Nothing outstanding: no response due.
  virtual bool idle() const { return true; }
  // A protocol or address error the environment saw; non-empty fails the run.
  virtual std::string error() const { return {}; }
  // The memory's statistics at the end (page faults, accesses, ...).
  virtual Counters counters() const { return {}; }
};

}  // namespace tmu::tb
