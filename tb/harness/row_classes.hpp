// What each row kind of a port description (harness/ports.hpp) means to code: the handshake
// ports of a channel kind and the direction of a field kind. The macro families that expand a
// block's rows into code (harness/describe.hpp, rtl_ports.hpp, sc_ports.hpp,
// hls/common/sc_ports.hpp) define one macro per class:
//   channels: <family>Handshake(ch)   <ch>_valid_i and <ch>_ready_o (a stimulus)
//             <family>Result(ch)      <ch>_valid_o and <ch>_ready_i (the result, a request)
//             <family>ValidOut(ch)    <ch>_valid_o alone (a request without ready)
//             <family>ValidIn(ch)     <ch>_valid_i alone (a response)
//             <family>NoHandshake(ch) (combinational, configuration, statistics)
//   fields:   <family>Input(ch, name, n, w)   the port <ch>_<name>_i, n elements of w bits
//             <family>Output(ch, name, n, w)  the port <ch>_<name>_o
//             <family>NoPort(ch, name, n, w)  not a port (an Env field)
// and passes TMU_ROW_C / TMU_ROW_F to TMU_PORTS_<block>.
#pragma once

#include "formats/formats.hpp"

#define TMU_ROW_CAT_(a, b) a##b
#define TMU_ROW_CAT(a, b) TMU_ROW_CAT_(a, b)

#define TMU_CHANNEL_CLASS_Sample Handshake
#define TMU_CHANNEL_CLASS_Write Handshake
#define TMU_CHANNEL_CLASS_Stream Handshake
#define TMU_CHANNEL_CLASS_Result Result
#define TMU_CHANNEL_CLASS_MemRequest Result
#define TMU_CHANNEL_CLASS_MemRequestNoReady ValidOut
#define TMU_CHANNEL_CLASS_MemResponse ValidIn
#define TMU_CHANNEL_CLASS_CombIn NoHandshake
#define TMU_CHANNEL_CLASS_CombOut NoHandshake
#define TMU_CHANNEL_CLASS_Cfg NoHandshake
#define TMU_CHANNEL_CLASS_Stat NoHandshake

#define TMU_FIELD_CLASS_In Input
#define TMU_FIELD_CLASS_Resp Input
#define TMU_FIELD_CLASS_Cfg Input
#define TMU_FIELD_CLASS_Out Output
#define TMU_FIELD_CLASS_Req Output
#define TMU_FIELD_CLASS_Stat Output
#define TMU_FIELD_CLASS_Env NoPort

// A family's expansion of a channel row and of a field row.
#define TMU_ROW_C(family, kind, ch) TMU_ROW_CAT(family, TMU_CHANNEL_CLASS_##kind)(ch)
#define TMU_ROW_F(family, kind, ch, name, fmt, n) \
  TMU_ROW_CAT(family, TMU_FIELD_CLASS_##kind)(ch, name, n, ::tmu::formats::k##fmt.width())
