// The clocked thread of a module that turns each item of its `in` channel into one item of its
// `out` channel (the noise unit, the specular combine, the cube address unit, the normal
// encoder): the golden arithmetic in the cycle the input is taken, a registered ready and a
// two-entry output FIFO, so that it sustains one item per clock like the RTL (with a latency of
// one cycle instead of the RTL pipeline's).
#pragma once

#include <systemc>

#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

// Runs forever in module m's SC_CTHREAD (ports in_valid_i, in_ready_o, out_valid_o,
// out_ready_i). show(item) writes the out channel's data ports from *item, or 0 when item is
// null (nothing to give); compute() reads the in channel's data ports and returns the item.
template <class Item, class Module, class Show, class Compute>
void run_one_per_clock(Module& m, Show show, Compute compute) {
  SmallFifo<Item, 2> out;
  // Not ready in reset: a ready port promises the next edge will take the input, and the edge
  // that leaves reset is spent here.
  m.in_ready_o.write(false);
  m.out_valid_o.write(false);
  show(nullptr);
  sc_core::wait();
  while (true) {
    m.in_ready_o.write(out.size() <= 1);  // room for one more whatever the output does
    m.out_valid_o.write(!out.empty());
    show(out.empty() ? nullptr : &out.front());
    sc_core::wait();
    // Everything below sees the values from before this edge.
    if (m.out_valid_o.read() && m.out_ready_i.read()) out.pop();
    if (m.in_ready_o.read() && m.in_valid_i.read()) out.push(compute());
  }
}

}  // namespace tmu::hls
