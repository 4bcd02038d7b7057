// The SystemC face of a block's port description (tb/harness/ports.hpp): TMU_SC_PORTS(block),
// written in a module's body, declares clk_i, rst_ni and every port of TMU_PORTS_<block> with
// the RTL's names, each as sc_port_t<width> (handshakes bool), so that the module, its RTL and
// the harness's bench (tb/harness/sc_ports.hpp) cannot disagree on a port.
#pragma once

#include <systemc>
#include <type_traits>

#include "fixed/fixed.hpp"
#include "formats/formats.hpp"
#include "harness/row_classes.hpp"

namespace tmu::hls {

// The raw bits of a W-bit port: a field's value is its two's complement pattern.
template <int W>
using sc_port_t = std::conditional_t<(W <= 64), sc_dt::sc_uint<W>, sc_dt::sc_biguint<W>>;

// A signed field's value from its port's raw bits.
template <class Port>
int64_t signed_value(const Port& bits, const fx::Format& f) {
  return fx::fit(static_cast<int64_t>(bits.to_uint64()), f, fx::Overflow::kWrap);
}

}  // namespace tmu::hls

// clang-format off
#define TMU_SC_IN(port, w) sc_core::sc_in<::tmu::hls::sc_port_t<(w)>> port{#port};
#define TMU_SC_OUT(port, w) sc_core::sc_out<::tmu::hls::sc_port_t<(w)>> port{#port};
#define TMU_SC_IN_BIT(port) sc_core::sc_in<bool> port{#port};
#define TMU_SC_OUT_BIT(port) sc_core::sc_out<bool> port{#port};
#define TMU_SC_Handshake(ch) TMU_SC_IN_BIT(ch##_valid_i) TMU_SC_OUT_BIT(ch##_ready_o)
#define TMU_SC_Result(ch) TMU_SC_OUT_BIT(ch##_valid_o) TMU_SC_IN_BIT(ch##_ready_i)
#define TMU_SC_ValidOut(ch) TMU_SC_OUT_BIT(ch##_valid_o)
#define TMU_SC_ValidIn(ch) TMU_SC_IN_BIT(ch##_valid_i)
#define TMU_SC_NoHandshake(ch)
#define TMU_SC_Input(ch, name, n, w) TMU_SC_IN(ch##_##name##_i, (n) * (w))
#define TMU_SC_Output(ch, name, n, w) TMU_SC_OUT(ch##_##name##_o, (n) * (w))
#define TMU_SC_NoPort(ch, name, n, w)
#define TMU_SC_C(kind, ch) TMU_ROW_C(TMU_SC_, kind, ch)
#define TMU_SC_F(kind, ch, name, fmt, n) TMU_ROW_F(TMU_SC_, kind, ch, name, fmt, n)

// In a module's body: clk_i, rst_ni and the block's ports.
#define TMU_SC_PORTS(block) \
  TMU_SC_IN_BIT(clk_i)      \
  TMU_SC_IN_BIT(rst_ni)     \
  TMU_PORTS_##block(TMU_SC_C, TMU_SC_F)
// clang-format on
