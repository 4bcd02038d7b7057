// A Verilated model behind one small interface, so that the cycle loop, the port logic and
// the runner (harness/rtl_runner.cpp, rtl_ports.cpp) are compiled once for every model
// instead of once per model type: a block's top, its parameter variants and its ~90 mutants
// each instantiate only RtlModelOf<M> and their port accessors (describe.hpp's rtl_rows). The
// mutants' engines were 57 s of one file's compile when the whole runner was a template.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <memory>

namespace tmu::tb {

// A model's ports as the port accessors see them: opaque, each accessor casts it back to the
// model type it was written for (describe.hpp's rtl_rows<M>, reached only through the model).
struct RtlPorts;

class RtlModel {
 public:
  virtual ~RtlModel() = default;
  virtual void eval() = 0;
  // clk_i high and the model evaluated; clk_i low (evaluated with the next inputs). A
  // combinational top has no clk_i and rst_ni (active-low, synchronous): these do nothing.
  virtual void rising_edge() = 0;
  virtual void clock_low() = 0;
  virtual void set_reset(bool active) = 0;
  // False when the model was built without waveforms (the mutants).
  virtual bool trace(VerilatedFstC* fst) = 0;
  virtual void final() = 0;
  virtual RtlPorts& ports() = 0;
};

template <class M>
concept Clocked = requires(M m) {
  m.clk_i = 1;
};

// Verilated with --trace-fst (every model but the mutants).
template <class M>
concept Traced = requires(M m, VerilatedFstC* fst) {
  m.trace(fst, 99);
};

template <class M>
class RtlModelOf final : public RtlModel {
 public:
  explicit RtlModelOf(VerilatedContext* ctx) : m_(ctx, "TOP") {}
  void eval() override { m_.eval(); }
  void rising_edge() override {
    if constexpr (Clocked<M>) {
      m_.clk_i = 1;
      m_.eval();
    }
  }
  void clock_low() override {
    if constexpr (Clocked<M>) m_.clk_i = 0;
  }
  void set_reset(bool active) override {
    if constexpr (Clocked<M>) m_.rst_ni = !active;
  }
  bool trace(VerilatedFstC* fst) override {
    if constexpr (Traced<M>) m_.trace(fst, 99);
    return Traced<M>;
  }
  void final() override { m_.final(); }
  RtlPorts& ports() override { return reinterpret_cast<RtlPorts&>(m_); }

 private:
  M m_;
};

using RtlModelFactory = std::unique_ptr<RtlModel> (*)(VerilatedContext*);

template <class M>
std::unique_ptr<RtlModel> make_rtl_model(VerilatedContext* ctx) {
  return std::make_unique<RtlModelOf<M>>(ctx);
}

}  // namespace tmu::tb
