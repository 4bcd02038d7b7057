// SystemVerilog generated from a block's port description (tb/harness/ports.hpp), so that no
// testbench repeats a port list:
//   icarus_testbench  the block's Icarus testbench around the shared cycle loop
//                     (tb/icarus/stream_tb.svh): one item per line of the vector file, every
//                     input field in hex, routed to the channel its op names; one output per
//                     line, "<cycle> <field> ...";
//   port_check        a module with exactly the description's ports around the RTL top;
//                     `verilator --lint-only -Wall` on it fails when a port's name, direction
//                     or width differs (tests/ports_test.cpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "harness/ports.hpp"

namespace tmu::tb {

// Throws std::invalid_argument for a block with a configuration or memory channels (the
// generic testbench drives stream channels only). `params` (NAME, VALUE) become parameters of
// the testbench, passed on to the top: the engine sets them with iverilog -P, which reaches
// the root module only.
std::string icarus_testbench(const BlockPorts& ports, const std::string& top,
                             const std::string& module,
                             const std::vector<std::pair<std::string, std::string>>& params = {});
std::string port_check(const BlockPorts& ports, const std::string& top);

}  // namespace tmu::tb
