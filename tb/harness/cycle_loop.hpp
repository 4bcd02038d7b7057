// The cycle loop of every timed runner (Verilator, SystemC), written once: reset, then each
// cycle present an item (or write a configuration item), set the output ready, let the
// environment drive, settle, sample both handshakes on the values the edge will see, let the
// environment sample, clock; after the last expected output, kDrainCycles more.
//
// A Sim provides: set_reset(bool active); present(const Txn* item); configure(const Txn&);
// set_out_ready(bool); env_drive(); settle() (Verilator: eval; SystemC: wait for the edge, after
// which a signal still reads its pre-edge value); accepts(const Txn&); out_valid(); out();
// env_sample(); clock() (Verilator: the edge; SystemC: nothing); quiet() (nothing in flight).
#pragma once

#include <vector>

#include "harness/handshake_driver.hpp"

namespace tmu::tb {

// Cycles with rst_ni low before the first item; waveform cycle numbers count from their end.
inline constexpr int kResetCycles = 5;

template <class Sim>
void run_reset(Sim& sim) {
  sim.set_reset(true);
  for (int i = 0; i < kResetCycles; ++i) {
    sim.present(nullptr);
    sim.set_out_ready(false);
    sim.env_drive();
    sim.settle();
    sim.clock();
  }
  sim.set_reset(false);
}

// Runs the items after reset until the driver is done and kDrainCycles more; throws what the
// driver or the model throws (deadlock, duplicate, failed assertion).
template <class Sim>
void run_items(Sim& sim, HandshakeDriver& driver) {
  auto cycle = [&] {
    const Txn* item = driver.begin_cycle(sim.quiet());
    const bool configuring = driver.configuring();
    if (configuring) sim.configure(*item);
    sim.present(configuring ? nullptr : item);
    sim.set_out_ready(driver.out_ready());
    sim.env_drive();
    sim.settle();
    const bool in_fire = item != nullptr && !configuring && sim.accepts(*item);
    const bool out_fire = driver.out_ready() && sim.out_valid();
    const Txn out = out_fire ? sim.out() : Txn{};
    sim.env_sample();
    sim.clock();
    driver.end_cycle(in_fire, out_fire ? &out : nullptr);
  };
  while (!driver.done()) cycle();
  for (int i = 0; i < kDrainCycles; ++i) cycle();
}

}  // namespace tmu::tb
