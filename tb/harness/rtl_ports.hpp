// The Verilated face of a block's port description (harness/ports.hpp): TMU_DESCRIBE(block)'s
// rtl_rows<M> turns the rows of TMU_PORTS_<block> into an accessor per row for any Verilated
// model M with those ports (the block's top, its parameter variants and its mutants), through
// which PortLogic<RtlPorts> (harness/rtl_runner.hpp) drives and samples the model. Nothing here
// names a port: a wrong or missing port in the description is a compile error at the first
// model it is used with.
#pragma once

#include <verilated.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "harness/port_logic.hpp"
#include "harness/row_classes.hpp"
#include "harness/rtl_model.hpp"

namespace tmu::tb {

// Packs n elements of w bits (element e at bits [e w, (e + 1) w)) into a port, and back.
template <class T>
requires std::is_integral_v<T>
void rtl_put(T& port, const uint64_t* v, int n, int w) {
  const uint64_t mask = w >= 64 ? ~uint64_t{0} : (uint64_t{1} << w) - 1;
  uint64_t bits = 0;
  for (int e = 0; e < n; ++e) bits |= (v[e] & mask) << (e * w);
  port = static_cast<T>(bits);
}
template <class T>
requires std::is_integral_v<T>
void rtl_get(const T& port, uint64_t* v, int n, int w) {
  const uint64_t mask = w >= 64 ? ~uint64_t{0} : (uint64_t{1} << w) - 1;
  for (int e = 0; e < n; ++e) v[e] = (static_cast<uint64_t>(port) >> (e * w)) & mask;
}
template <std::size_t N>
void rtl_put(VlWide<N>& port, const uint64_t* v, int n, int w) {
  for (std::size_t i = 0; i < N; ++i) port[i] = 0;
  for (int e = 0; e < n; ++e) {
    for (int b = 0; b < w; ++b) {
      const int bit = e * w + b;
      if ((v[e] >> b) & 1u) port[static_cast<size_t>(bit / 32)] |= EData{1} << (bit % 32);
    }
  }
}
template <std::size_t N>
void rtl_get(const VlWide<N>& port, uint64_t* v, int n, int w) {
  for (int e = 0; e < n; ++e) {
    v[e] = 0;
    for (int b = 0; b < w; ++b) {
      const int bit = e * w + b;
      v[e] |= uint64_t{(port[static_cast<size_t>(bit / 32)] >> (bit % 32)) & 1u} << b;
    }
  }
}

}  // namespace tmu::tb

// The accessors of TMU_PORTS_<block>'s rows, for TMU_DESCRIBE (M is the model type; the
// RtlPorts an accessor is given are an M's, harness/rtl_model.hpp).
// clang-format off
#define TMU_RTL_SET(port, n, w) +[](::tmu::tb::RtlPorts& p, const uint64_t* v) { \
    ::tmu::tb::rtl_put(reinterpret_cast<M&>(p).port, v, n, w); }
#define TMU_RTL_GET(port, n, w) +[](const ::tmu::tb::RtlPorts& p, uint64_t* v) { \
    ::tmu::tb::rtl_get(reinterpret_cast<const M&>(p).port, v, n, w); }
#define TMU_RTL_Handshake(ch) {TMU_RTL_SET(ch##_valid_i, 1, 1), TMU_RTL_GET(ch##_ready_o, 1, 1)},
#define TMU_RTL_Result(ch) {TMU_RTL_SET(ch##_ready_i, 1, 1), TMU_RTL_GET(ch##_valid_o, 1, 1)},
#define TMU_RTL_ValidOut(ch) {nullptr, TMU_RTL_GET(ch##_valid_o, 1, 1)},
#define TMU_RTL_ValidIn(ch) {TMU_RTL_SET(ch##_valid_i, 1, 1), nullptr},
#define TMU_RTL_NoHandshake(ch) {},
#define TMU_RTL_Input(ch, name, n, w) {TMU_RTL_SET(ch##_##name##_i, n, w), nullptr},
#define TMU_RTL_Output(ch, name, n, w) {nullptr, TMU_RTL_GET(ch##_##name##_o, n, w)},
#define TMU_RTL_NoPort(ch, name, n, w) {},
#define TMU_RTL_C(kind, ch) TMU_ROW_C(TMU_RTL_, kind, ch)
#define TMU_RTL_F(kind, ch, name, fmt, n) TMU_ROW_F(TMU_RTL_, kind, ch, name, fmt, n)
// clang-format on
