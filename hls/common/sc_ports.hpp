// The SystemC face of a block's port description (tb/harness/ports.hpp): TMU_SC_PORTS(block),
// written in a module's body, declares clk_i, rst_ni and every port of TMU_PORTS_<block> with
// the RTL's names, each as sc_port_t<width> (handshakes bool), so that the module, its RTL and
// the harness's bench (tb/harness/sc_ports.hpp) cannot disagree on a port.
#pragma once

#include <systemc>
#include <type_traits>

#include "fixed/fixed.hpp"
#include "formats/formats.hpp"

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

#define TMU_SC_IN(port, w) sc_core::sc_in<::tmu::hls::sc_port_t<(w)>> port{#port};
#define TMU_SC_OUT(port, w) sc_core::sc_out<::tmu::hls::sc_port_t<(w)>> port{#port};
#define TMU_SC_IN_BIT(port) sc_core::sc_in<bool> port{#port};
#define TMU_SC_OUT_BIT(port) sc_core::sc_out<bool> port{#port};
#define TMU_SC_C(kind, ch) TMU_SC_C_##kind(ch)
#define TMU_SC_C_Sample(ch) TMU_SC_IN_BIT(ch##_valid_i) TMU_SC_OUT_BIT(ch##_ready_o)
#define TMU_SC_C_Write(ch) TMU_SC_C_Sample(ch)
#define TMU_SC_C_Stream(ch) TMU_SC_C_Sample(ch)
#define TMU_SC_C_Result(ch) TMU_SC_OUT_BIT(ch##_valid_o) TMU_SC_IN_BIT(ch##_ready_i)
#define TMU_SC_C_MemRequest(ch) TMU_SC_C_Result(ch)
#define TMU_SC_C_MemRequestNoReady(ch) TMU_SC_OUT_BIT(ch##_valid_o)
#define TMU_SC_C_MemResponse(ch) TMU_SC_IN_BIT(ch##_valid_i)
#define TMU_SC_C_CombIn(ch)
#define TMU_SC_C_CombOut(ch)
#define TMU_SC_C_Cfg(ch)
#define TMU_SC_C_Stat(ch)
#define TMU_SC_F(kind, ch, name, fmt, n) \
  TMU_SC_F_##kind(ch, name, (n) * ::tmu::formats::k##fmt.width())
#define TMU_SC_F_In(ch, name, w) TMU_SC_IN(ch##_##name##_i, w)
#define TMU_SC_F_Resp(ch, name, w) TMU_SC_IN(ch##_##name##_i, w)
#define TMU_SC_F_Cfg(ch, name, w) TMU_SC_IN(ch##_##name##_i, w)
#define TMU_SC_F_Out(ch, name, w) TMU_SC_OUT(ch##_##name##_o, w)
#define TMU_SC_F_Req(ch, name, w) TMU_SC_OUT(ch##_##name##_o, w)
#define TMU_SC_F_Stat(ch, name, w) TMU_SC_OUT(ch##_##name##_o, w)
#define TMU_SC_F_Env(ch, name, w)

// In a module's body: clk_i, rst_ni and the block's ports.
#define TMU_SC_PORTS(block) \
  TMU_SC_IN_BIT(clk_i)      \
  TMU_SC_IN_BIT(rst_ni)     \
  TMU_PORTS_##block(TMU_SC_C, TMU_SC_F)
