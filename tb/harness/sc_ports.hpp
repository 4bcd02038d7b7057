// The SystemC bench of a block from its port description: TMU_DESCRIBE_SC(block) declares a
// signal for every port of TMU_PORTS_<block> (types from hls/common/sc_ports.hpp, as the
// module's ports), binds them to a module, and gives an accessor pair per row; PortsScBench
// owns the module and its signals and drives them with the same logic as the rtl adapter.
#pragma once

#include <functional>
#include <memory>
#include <systemc>
#include <utility>
#include <vector>

#include "harness/hls_runner.hpp"
#include "harness/port_logic.hpp"
#include "harness/row_classes.hpp"
#include "hls/common/sc_ports.hpp"

namespace tmu::tb {

template <class T>
void sc_put(sc_core::sc_signal<T>& s, const uint64_t* v, int n, int w) {
  T bits = 0;
  for (int e = 0; e < n; ++e) bits.range((e + 1) * w - 1, e * w) = v[e];
  s.write(bits);
}
template <class T>
void sc_get(const sc_core::sc_signal<T>& s, uint64_t* v, int n, int w) {
  const T bits = s.read();
  for (int e = 0; e < n; ++e) v[e] = bits.range((e + 1) * w - 1, e * w).to_uint64();
}

// Signals is the block's TMU_DESCRIBE_SC struct, Dut its module; args go to the module's
// constructor after its name.
template <class Signals, class Dut>
class PortsScBench : public sc_core::sc_module, public ScAdapter {
 public:
  template <class... Args>
  PortsScBench(sc_core::sc_module_name name, sc_core::sc_clock& clk,
               sc_core::sc_signal<bool>& rst_n, const BlockPorts& ports,
               std::unique_ptr<Environment> env, Args&&... args)
      : sc_module(name),
        dut_("dut", std::forward<Args>(args)...),
        logic_(ports, Signals::rows(), std::move(env)) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    signals_.bind(dut_);
    logic_.init(signals_);
  }

  void drive(const Txn* item) override { logic_.drive(signals_, item); }
  bool accepts(const Txn& item) const override { return logic_.accepts(signals_, item); }
  void set_out_ready(bool ready) override { logic_.set_out_ready(signals_, ready); }
  bool out_valid() const override { return logic_.out_valid(signals_); }
  Txn out() const override { return logic_.out(signals_); }
  void configure(const Txn& item) override { logic_.configure(signals_, item); }
  void env_drive() override { logic_.env_drive(signals_); }
  void env_sample() override { logic_.env_sample(signals_); }
  bool quiet() const override { return logic_.quiet(); }
  void finish(RunResult& result) override { logic_.finish(signals_, result); }

 private:
  Dut dut_;
  Signals signals_;
  PortLogic<Signals> logic_;
};

}  // namespace tmu::tb

// clang-format off
// The signals (TMU_SCS_), their binding to a module d (TMU_SCB_) and their accessors (TMU_SCR_).
#define TMU_SCS_SIG(port, w) sc_core::sc_signal<::tmu::hls::sc_port_t<(w)>> port{#port};
#define TMU_SCS_BIT(port) sc_core::sc_signal<bool> port{#port};
#define TMU_SCS_Handshake(ch) TMU_SCS_BIT(ch##_valid_i) TMU_SCS_BIT(ch##_ready_o)
#define TMU_SCS_Result(ch) TMU_SCS_BIT(ch##_valid_o) TMU_SCS_BIT(ch##_ready_i)
#define TMU_SCS_ValidOut(ch) TMU_SCS_BIT(ch##_valid_o)
#define TMU_SCS_ValidIn(ch) TMU_SCS_BIT(ch##_valid_i)
#define TMU_SCS_NoHandshake(ch)
#define TMU_SCS_Input(ch, name, n, w) TMU_SCS_SIG(ch##_##name##_i, (n) * (w))
#define TMU_SCS_Output(ch, name, n, w) TMU_SCS_SIG(ch##_##name##_o, (n) * (w))
#define TMU_SCS_NoPort(ch, name, n, w)
#define TMU_SCS_C(kind, ch) TMU_ROW_C(TMU_SCS_, kind, ch)
#define TMU_SCS_F(kind, ch, name, fmt, n) TMU_ROW_F(TMU_SCS_, kind, ch, name, fmt, n)

#define TMU_SCB(port) d.port(port);
#define TMU_SCB_Handshake(ch) TMU_SCB(ch##_valid_i) TMU_SCB(ch##_ready_o)
#define TMU_SCB_Result(ch) TMU_SCB(ch##_valid_o) TMU_SCB(ch##_ready_i)
#define TMU_SCB_ValidOut(ch) TMU_SCB(ch##_valid_o)
#define TMU_SCB_ValidIn(ch) TMU_SCB(ch##_valid_i)
#define TMU_SCB_NoHandshake(ch)
#define TMU_SCB_Input(ch, name, n, w) TMU_SCB(ch##_##name##_i)
#define TMU_SCB_Output(ch, name, n, w) TMU_SCB(ch##_##name##_o)
#define TMU_SCB_NoPort(ch, name, n, w)
#define TMU_SCB_C(kind, ch) TMU_ROW_C(TMU_SCB_, kind, ch)
#define TMU_SCB_F(kind, ch, name, fmt, n) TMU_ROW_F(TMU_SCB_, kind, ch, name, fmt, n)

#define TMU_SCR_SET_BIT(port) +[](S& s, const uint64_t* v) { s.port.write(v[0] != 0); }
#define TMU_SCR_GET_BIT(port) +[](const S& s, uint64_t* v) { v[0] = s.port.read(); }
#define TMU_SCR_SET(port, n, w) +[](S& s, const uint64_t* v) { ::tmu::tb::sc_put(s.port, v, n, w); }
#define TMU_SCR_GET(port, n, w) +[](const S& s, uint64_t* v) { ::tmu::tb::sc_get(s.port, v, n, w); }
#define TMU_SCR_Handshake(ch) {TMU_SCR_SET_BIT(ch##_valid_i), TMU_SCR_GET_BIT(ch##_ready_o)},
#define TMU_SCR_Result(ch) {TMU_SCR_SET_BIT(ch##_ready_i), TMU_SCR_GET_BIT(ch##_valid_o)},
#define TMU_SCR_ValidOut(ch) {nullptr, TMU_SCR_GET_BIT(ch##_valid_o)},
#define TMU_SCR_ValidIn(ch) {TMU_SCR_SET_BIT(ch##_valid_i), nullptr},
#define TMU_SCR_NoHandshake(ch) {},
#define TMU_SCR_Input(ch, name, n, w) {TMU_SCR_SET(ch##_##name##_i, n, w), nullptr},
#define TMU_SCR_Output(ch, name, n, w) {nullptr, TMU_SCR_GET(ch##_##name##_o, n, w)},
#define TMU_SCR_NoPort(ch, name, n, w) {},
#define TMU_SCR_C(kind, ch) TMU_ROW_C(TMU_SCR_, kind, ch)
#define TMU_SCR_F(kind, ch, name, fmt, n) TMU_ROW_F(TMU_SCR_, kind, ch, name, fmt, n)

// TMU_DESCRIBE_SC(block): defines tmu::tb::desc::block_sc, a signal per port of
// TMU_PORTS_<block> with bind(module) and rows(), the accessors in row order.
#define TMU_DESCRIBE_SC(block)                                 \
  namespace tmu::tb::desc {                                    \
  struct block##_sc {                                          \
    TMU_PORTS_##block(TMU_SCS_C, TMU_SCS_F)                    \
    template <class Dut>                                       \
    void bind(Dut& d) {                                        \
      TMU_PORTS_##block(TMU_SCB_C, TMU_SCB_F)                  \
    }                                                          \
    static std::vector<::tmu::tb::PortRow<block##_sc>> rows() { \
      using S = block##_sc;                                    \
      return {TMU_PORTS_##block(TMU_SCR_C, TMU_SCR_F)};        \
    }                                                          \
  };                                                           \
  }
// clang-format on
