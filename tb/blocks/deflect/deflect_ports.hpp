// The bump deflection unit's ports (001 §4.4, §6.2; rtl/deflect/tmu_deflect.sv at the grid
// A = 9, hls/deflect/deflect_sc.hpp): the one list the RTL top, the SystemC module and the
// harness follow (tb/harness/ports.hpp says how to read it). The map memory's response is the
// whole block, its 16 entries packed, entry o at bits 15 o.
#pragma once

#define TMU_PORTS_deflect(C, F)           \
  C(Sample, in)                           \
  F(In, in, normal_phi, SpherePhi, 1)     \
  F(In, in, normal_theta, SphereTheta, 1) \
  F(In, in, bump_phi, SpherePhi, 1)       \
  F(In, in, bump_theta, SphereTheta, 1)   \
  C(Result, out)                          \
  F(Out, out, phi, SpherePhi, 1)          \
  F(Out, out, theta, SphereTheta, 1)      \
  F(Out, out, access, MapAccess, 1)       \
  C(MemRequestNoReady, map_req)           \
  F(Req, map_req, block, S2sBlockAddr, 1) \
  C(MemResponse, map_resp)                \
  F(Resp, map_resp, data, S2sEntry, 16)
