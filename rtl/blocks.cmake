# The RTL models of every co-simulation block, and its mutants: the one table of both
# (docs/harness.md, "Adding a block"). Included by rtl/CMakeLists.txt after the manifest's
# models (V<top> for every top of manifest.txt) are declared.
#
# tmu_block(<block> [TOP <top>] [VARIANT <key>] [OPTIONS <text>] [LEVEL <level>] [PREFIX <model>]
#           [ARGS <args>...])
#   A Verilated model of <top> (default tmu_<block>) that <block>'s engine <level> (default rtl)
#   runs when the block's variant is <key> (default "", the block as its options leave it):
#   V<top> for the manifest's model; with Verilator ARGS (parameters, --threads) its own model,
#   PREFIX or V<top>_<key>.
#   OPTIONS are the `texsim cosim` options that give the block that variant; the conformance
#   suite (tests/conformance_test.cpp) runs every variant with them.
# tmu_mutant(<block> <name> [VARIANT <key>] FILE <source> FROM <text> TO <text> WHY <text>
#            [EXPECT fails|x-leak])
#   A deliberately broken copy of the variant's model, V<top>_mutant_<name>: FILE (relative to
#   rtl/) with FROM replaced by TO, the other sources unchanged; the build fails when FROM is
#   gone. The conformance suite runs the block's cosim on it and expects the run to fail
#   (fails: outputs, counters, requests, a run error or an assertion), or, for x-leak, the two
#   runs with different random initial values to differ (a flop read before it is written).
#
# Generated for the C++ side (in build/rtl/generated):
#   rtl_models_<block>.hpp  TMU_RTL_MODELS_<block>(X): X(block, "key", "level", Model, "top",
#                           "Verilog parameters NAME=VALUE ...", "options")
#   mutants.hpp             TMU_MUTANTS(X): X(block, name, "key", Model, "expect", "why")
#   block_list.hpp          TMU_BLOCKS(X): X(block) for every block, in this file's order;
#                           TMU_BLOCK_VARIANTS(X): X(block, "key", "top", "cosim options") per
#                           variant

function(tmu_block block)
  cmake_parse_arguments(ARG "" "TOP;VARIANT;OPTIONS;LEVEL;PREFIX" "ARGS" ${ARGN})
  if(NOT ARG_TOP)
    set(ARG_TOP tmu_${block})
  endif()
  if(NOT ARG_LEVEL)
    set(ARG_LEVEL rtl)
  endif()
  set(key "${ARG_VARIANT}")
  set(model V${ARG_TOP})
  if(ARG_ARGS)
    set(model V${ARG_TOP}_${key})
    if(ARG_PREFIX)
      set(model ${ARG_PREFIX})
    endif()
    tmu_verilate(TOP ${ARG_TOP} PREFIX ${model} SOURCES ${TMU_SOURCES_${ARG_TOP}} ARGS ${ARG_ARGS})
  endif()
  set_property(GLOBAL APPEND PROPERTY TMU_BLOCKS ${block})
  # The Verilog parameters among the Verilator arguments, for the same RTL under Icarus.
  set(params "")
  foreach(arg IN LISTS ARG_ARGS)
    if(arg MATCHES "^-G(.*)$")
      string(APPEND params "${CMAKE_MATCH_1} ")
    endif()
  endforeach()
  string(STRIP "${params}" params)
  set_property(GLOBAL APPEND PROPERTY TMU_BLOCK_${block}_MODELS
    "X(${block}, \"${key}\", \"${ARG_LEVEL}\", ${model}, \"${ARG_TOP}\", \"${params}\", \"${ARG_OPTIONS}\")")
  set_property(GLOBAL APPEND PROPERTY TMU_BLOCK_${block}_HEADERS "#include <${model}.h>")
  if(ARG_LEVEL STREQUAL "rtl")  # a variant: what the conformance suite runs, mutants build on
    set_property(GLOBAL APPEND PROPERTY TMU_VARIANT_ROWS
      "X(${block}, \"${key}\", \"${ARG_TOP}\", \"${ARG_OPTIONS}\")")
    set_property(GLOBAL PROPERTY TMU_VARIANT_${block}_${key}_TOP ${ARG_TOP})
    set_property(GLOBAL PROPERTY TMU_VARIANT_${block}_${key}_ARGS "${ARG_ARGS}")
  endif()
endfunction()

function(tmu_mutant block name)
  cmake_parse_arguments(ARG "" "VARIANT;FILE;FROM;TO;WHY;EXPECT" "" ${ARGN})
  if(TMU_RTL_COVERAGE)  # only the tests run mutants; scripts/coverage.sh builds texsim only
    return()
  endif()
  if(NOT ARG_EXPECT)
    set(ARG_EXPECT fails)
  endif()
  set(key "${ARG_VARIANT}")
  get_property(top GLOBAL PROPERTY TMU_VARIANT_${block}_${key}_TOP)
  get_property(args GLOBAL PROPERTY TMU_VARIANT_${block}_${key}_ARGS)
  if(NOT top)
    message(FATAL_ERROR "mutant ${block}/${name}: no rtl model of variant '${key}' (tmu_block first)")
  endif()
  set(model V${top}_mutant_${name})
  set(src ${TMU_RTL_DIR}/${ARG_FILE})
  get_filename_component(file_name ${ARG_FILE} NAME)
  set(mutant ${CMAKE_CURRENT_BINARY_DIR}/mutants/${model}/${file_name})
  # The edit as a file (bracket arguments keep quotes, newlines and semicolons), applied now
  # (an edit that no longer applies fails the configuration) and by the copy's build rule.
  set(edit ${mutant}.edit.cmake)
  set(text "set(FROM [==[${ARG_FROM}]==])\nset(TO [==[${ARG_TO}]==])\n")
  set(old_text "")
  if(EXISTS ${edit})
    file(READ ${edit} old_text)
  endif()
  if(NOT old_text STREQUAL text)  # rewritten only when it changes: the copy rebuilds on it
    file(WRITE ${edit} "${text}")
  endif()
  set(mutate -DSRC=${src} -DDST=${mutant} -DEDIT=${edit})
  set(script ${TMU_RTL_DIR}/mutate.cmake)
  execute_process(COMMAND ${CMAKE_COMMAND} ${mutate} -DIF_CHANGED=1 -P ${script} RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${model}: see the error above")
  endif()
  # TMU_MUTANTS=ci (rtl/CMakeLists.txt): each block's first mutant and the first x-leak one
  # are built and run; the others' edits are still checked above.
  if(TMU_MUTANTS STREQUAL "ci")
    set(kind ${block})
    if(ARG_EXPECT STREQUAL "x-leak")
      set(kind x-leak)
    endif()
    get_property(taken GLOBAL PROPERTY TMU_MUTANT_TAKEN_${kind})
    if(taken)
      return()
    endif()
    set_property(GLOBAL PROPERTY TMU_MUTANT_TAKEN_${kind} ON)
  endif()
  add_custom_command(OUTPUT ${mutant}
    COMMAND ${CMAKE_COMMAND} ${mutate} -DROWS=${CMAKE_CURRENT_LIST_FILE} -P ${script}
    DEPENDS ${src} ${edit} ${TMU_RTL_DIR}/mutate.cmake VERBATIM)
  set(sources ${TMU_SOURCES_${top}})
  list(TRANSFORM sources REPLACE "^${src}$" ${mutant})
  tmu_verilate(TOP ${top} PREFIX ${model} SOURCES ${sources} ARGS ${args} MUTANT)
  string(REPLACE "\\" "\\\\" why "${ARG_WHY}")
  string(REPLACE "\"" "\\\"" why "${why}")
  set_property(GLOBAL APPEND PROPERTY TMU_MUTANT_ROWS
    "X(${block}, ${name}, \"${key}\", ${model}, \"${ARG_EXPECT}\", \"${why}\")")
  set_property(GLOBAL APPEND PROPERTY TMU_MUTANT_HEADERS "#include <${model}.h>")
endfunction()

# Writes the generated headers (only when their text changes, so nothing rebuilds needlessly).
function(tmu_write_block_tables)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  get_property(blocks GLOBAL PROPERTY TMU_BLOCKS)
  list(REMOVE_DUPLICATES blocks)
  set(list_rows "")
  set(block_headers "")
  foreach(block IN LISTS blocks)
    get_property(models GLOBAL PROPERTY TMU_BLOCK_${block}_MODELS)
    get_property(headers GLOBAL PROPERTY TMU_BLOCK_${block}_HEADERS)
    list(JOIN models " \\\n  " rows)
    list(JOIN headers "\n" includes)
    file(CONFIGURE OUTPUT ${dir}/rtl_models_${block}.hpp CONTENT
"// GENERATED by rtl/blocks.cmake: the Verilated models of block ${block}.
#pragma once
${includes}
// X(block, \"variant\", \"level\", Model, \"top\", \"parameters\", \"cosim options\")
#define TMU_RTL_MODELS_${block}(X) \\
  ${rows}
" @ONLY)
    string(APPEND list_rows " X(${block})")
    string(APPEND block_headers "#include \"blocks/${block}/${block}_block.hpp\"\n")
  endforeach()
  get_property(variants GLOBAL PROPERTY TMU_VARIANT_ROWS)
  list(JOIN variants " \\\n  " variant_rows)
  file(CONFIGURE OUTPUT ${dir}/block_list.hpp CONTENT
"// GENERATED by rtl/blocks.cmake: every co-simulation block, and every variant of each.
#pragma once
#define TMU_BLOCKS(X)${list_rows}
// X(block, \"variant\", \"top\", \"cosim options\")
#define TMU_BLOCK_VARIANTS(X) \\
  ${variant_rows}
" @ONLY)
  get_property(mutants GLOBAL PROPERTY TMU_MUTANT_ROWS)
  get_property(mutant_headers GLOBAL PROPERTY TMU_MUTANT_HEADERS)
  list(JOIN mutants " \\\n  " rows)
  list(JOIN mutant_headers "\n" includes)
  file(CONFIGURE OUTPUT ${dir}/mutants.hpp CONTENT
"// GENERATED by rtl/blocks.cmake: every mutant, with the header of every block.
#pragma once
${includes}
${block_headers}
// X(block, name, \"variant\", Model, \"expect\", \"why\")
#define TMU_MUTANTS(X) \\
  ${rows}
" @ONLY)
endfunction()

# ---- the blocks -------------------------------------------------------------------------------

# Noise unit (002 §4.1).
tmu_block(noise)
if(TMU_RTL_THREADS)
  tmu_block(noise LEVEL rtl-threads PREFIX Vtmu_noise_threads ARGS --threads 2)
endif()
tmu_mutant(noise hash FILE perlin/tmu_noise.sv
  FROM "assign h4 = scramble(s3_h_q[n*LW +: LW] + s3_iw_q + LW'(n / 4));"
  TO "assign h4 = scramble(s3_h_q[n*LW +: LW]);"
  WHY "the hash drops the second add of the last coordinate (T(h) instead of T(h + x3))")
tmu_mutant(noise fade FILE perlin/tmu_noise.sv
  FROM "FW'((num + (64'(1) << (3 * S - 1))) >> (3 * S))" TO "FW'(num >> (3 * S))"
  WHY "the fade table truncates instead of rounding half up")
# The pipelines built on tmu_pipe_ctrl (noise, specular_combine, cube_address, normal_encoder)
# keep their valids there: their x-leak mutants remove its reset, in their own model's copy.
tmu_mutant(noise unreset FILE common/tmu_pipe_ctrl.sv EXPECT x-leak
  FROM "      valid_q <= '0;\n" TO ""
  WHY "the stage valids keep their initial values through reset (random samples leave)")

# Fractal sums of four octaves (002 §4.1.1): pipelined (four noise units) and shared (one).
tmu_block(fractal TOP tmu_fractal_pipelined)
if(TMU_RTL_THREADS)
  tmu_block(fractal TOP tmu_fractal_pipelined LEVEL rtl-threads PREFIX Vtmu_fractal_pipelined_threads
    ARGS --threads 2)
endif()
tmu_block(fractal TOP tmu_fractal_shared VARIANT shared OPTIONS "--fractal shared")
tmu_mutant(fractal abs FILE perlin/tmu_fractal_pipelined.sv
  FROM "pi[PW-1] ? {1'b0, neg}" TO "pi[PW-1] ? {neg[PW-1], neg}"
  WHY "|-1.0| read as a signed PW-bit value (-1.0 again)")
tmu_mutant(fractal octave FILE perlin/tmu_fractal_pipelined.sv
  FROM "localparam int unsigned Shift = i;" TO "localparam int unsigned Shift = i + 1;"
  WHY "octave i reads the coordinates at 2^(i+1) (the octave shift off by one)")
tmu_mutant(fractal unreset FILE perlin/tmu_fractal_pipelined.sv EXPECT x-leak
  FROM "      s8_valid_q <= 1'b0;\n" TO ""
  WHY "the sums' output valid keeps its initial value through reset")
tmu_mutant(fractal abs VARIANT shared FILE perlin/tmu_fractal_shared.sv
  FROM "p[PW-1] ? {1'b0, neg}" TO "p[PW-1] ? {neg[PW-1], neg}"
  WHY "|-1.0| read as a signed PW-bit value")
tmu_mutant(fractal early VARIANT shared FILE perlin/tmu_fractal_shared.sv
  FROM "last_issue = issue && oct_q == 2'd3;" TO "last_issue = issue && oct_q == 2'd2;"
  WHY "the controller takes the next sample with octave 2 (three octaves for the first sample, the later ones in the order 3, 0, 1, 2)")
tmu_mutant(fractal unreset VARIANT shared FILE perlin/tmu_fractal_shared.sv EXPECT x-leak
  FROM "      acc_oct_q   <= 2'd0;\n" TO ""
  WHY "the accumulator's octave count starts where the flops happen to be")

# CCC low-cost unit (000 §4, Figs. 6-7).
tmu_block(ccc_cache_bilinear)
# First: tests/blocks/ccc_cache_bilinear_test.cpp runs it by name, and TMU_MUTANTS=ci builds
# each block's first mutant.
tmu_mutant(ccc_cache_bilinear neighbour FILE ccc/tmu_ccc_footprint_axis.sv
  FROM "{1'b0, blk_o} + (BlockW + 1)'(1)" TO "{1'b0, blk_o} - (BlockW + 1)'(1)"
  WHY "the lookahead prefetches the block before instead of after (wrong memory requests)")
tmu_mutant(ccc_cache_bilinear round FILE ccc/tmu_ccc_bilerp.sv
  FROM "VW'(1) << (2 * WW - 1)" TO "VW'(1) << (2 * WW - 2)"
  WHY "the blend adds a quarter instead of half an LSB before dropping the fraction")
tmu_mutant(ccc_cache_bilinear count FILE ccc/tmu_ccc_cache_bilinear.sv
  FROM "3'(m[0]) + 3'(m[1]) + 3'(m[2]) + 3'(m[3])" TO "3'(m[0]) + 3'(m[1]) + 3'(m[2])"
  WHY "the hit/miss counter drops the fourth block of a footprint (right outputs, wrong statistics)")
tmu_mutant(ccc_cache_bilinear unreset FILE ccc/tmu_ccc_cache_bilinear.sv EXPECT x-leak
  FROM "      hits_q        <= '0;\n" TO ""
  WHY "the hit counter starts where its flops happen to be")

# TEXRAM trilinear unit (000 §2, §5, §6), and at the accuracy sweep's other widths S,W,L
# (SubTexelBits, WeightBits, LodFracBits; `texsim cosim trilinear --widths`).
tmu_block(trilinear)
if(TMU_RTL_THREADS)
  tmu_block(trilinear LEVEL rtl-threads PREFIX Vtmu_trilinear_threads ARGS --threads 2)
endif()
tmu_block(trilinear VARIANT s6w6l6 OPTIONS "--widths 6,6,6"
  ARGS -GSubTexelBits=6 -GWeightBits=6 -GLodFracBits=6)
tmu_block(trilinear VARIANT s4w4l4 OPTIONS "--widths 4,4,4"
  ARGS -GSubTexelBits=4 -GWeightBits=4 -GLodFracBits=4)
tmu_mutant(trilinear mirror FILE texram/tmu_trilinear_border.sv
  FROM "reflect ? ~tap_i[CoordW-1:0] & mask : low" TO "low"
  WHY "mirror reflects nothing (acts as wrap): wrong colours and cells once a tap crosses an edge")
tmu_mutant(trilinear round FILE texram/tmu_trilinear_blend.sv
  FROM "ZW'(1) << (3 * W - 1)" TO "ZW'(1) << (3 * W - 2)"
  WHY "the blend rounds with a quarter instead of half an LSB")
tmu_mutant(trilinear reads FILE texram/tmu_trilinear.sv
  FROM "(t % 4 == 0 || !nearest)" TO "(t % 4 == 0 || 1'b1)"
  WHY "nearest reads the banks of all four taps (right colours, wrong memory requests)")
tmu_mutant(trilinear sphere FILE texram/tmu_trilinear_sphere.sv
  FROM "wide >>> (ShiftLog2 - log2_i)" TO "wide >> (ShiftLog2 - log2_i)"
  WHY "sphere addressing below 128 texels shifts logically: a coordinate left of the map (uN < -1) becomes a huge positive one")
tmu_mutant(trilinear unreset FILE texram/tmu_trilinear.sv EXPECT x-leak
  FROM "      s1_valid_q    <= 1'b0;\n      s2_valid_q    <= 1'b0;\n      s3_valid_q    <= 1'b0;\n      s4_valid_q    <= 1'b0;\n"
  TO ""
  WHY "the four address stages' valids keep their initial values through reset (random samples enter)")
tmu_mutant(trilinear round_w6 VARIANT s6w6l6 FILE texram/tmu_trilinear_blend.sv
  FROM "ZW'(1) << (3 * W - 1)" TO "ZW'(1) << (3 * W - 2)"
  WHY "at W = 6 the blend rounds with a quarter instead of half an LSB")
tmu_mutant(trilinear weight_w4 VARIANT s4w4l4 FILE texram/tmu_trilinear_axis.sv
  FROM "s[Frac-1 -: WeightBits]" TO "s[Frac-2 -: WeightBits]"
  WHY "at W = 4 the filter weight is read one bit too low (frac(s) halved, its top bit lost)")

# Clip-map address unit (003): virtual coordinates, toroidal tiles, the two substitution rules,
# the load port's writes (tmu_texram_access behind it, the trilinear unit's).
tmu_block(clipmap)
tmu_mutant(clipmap toroid FILE texram/tmu_clip_address.sv
  FROM "assign sx       = side_log2 == '0 ? CoordW'(replica_x_i) : x_i & mask;"
  TO "assign sx       = side_log2 == '0 ? CoordW'(replica_x_i) : x_i & (mask >> 1);"
  WHY "the toroidal position drops the tile's top column bit: two texels of a row share a cell")
tmu_mutant(clipmap coarsest FILE texram/tmu_clip_tap.sv
  FROM "for (int m = Levels - 1; m >= 0; m--) begin" TO "for (int m = 0; m < Levels; m++) begin"
  WHY "a wayward tap takes the coarsest tile that holds it, not the first")
tmu_mutant(clipmap raise FILE texram/tmu_clipmap.sv
  FROM "held = holds[s1_level0_q] && (!s1_two_q || holds[s1_level1_q]);"
  TO "held = holds[s1_level0_q];"
  WHY "per-sample substitution tests the first level only: a trilinear sample's second level reads taps its tile does not hold")
tmu_mutant(clipmap unreset FILE texram/tmu_clipmap.sv EXPECT x-leak
  FROM "      s1_valid_q    <= 1'b0;\n      s2_valid_q    <= 1'b0;\n"
  TO ""
  WHY "the first two stages' valids keep their initial values through reset (random samples enter)")

# Footprint assembly on a clip-map (000 §10 in front of 003): the footprint unit's setup, marcher
# and average around tmu_clipmap (`texsim cosim footprint_clip`).
tmu_block(footprint_clip)
tmu_mutant(footprint_clip overtake FILE footprint/tmu_footprint_clip.sv
  FROM "(load_valid_i && idle)" TO "(load_valid_i)"
  WHY "a load reaches the clip-map while a fragment's probes are still in the setup or the marcher (it overtakes them, and is written again when the port shows ready)")
tmu_mutant(footprint_clip saturate FILE footprint/tmu_footprint_clip.sv
  FROM "(cfg_border_u_i == BorderClamp || cfg_border_u_i == BorderColour)" TO "(1'b0)"
  WHY "a probe beyond the port wraps on a clamp axis of the virtual texture instead of saturating")

# TEXRAM bank address unit (000 §2, Fig. 2), the address logic tmu_mipgen and tmu_trilinear
# instantiate. Combinational, without a flop: no x-leak mutant (no reset to remove, nothing
# holds an initial value; the suite's X check still runs, and stays identical).
tmu_block(bank_address)
tmu_mutant(bank_address row FILE texram/tmu_bank_address.sv
  FROM "{position[AddrW-3:0], 2'b00}" TO "{position[AddrW-3:1], 3'b000}"
  WHY "a four-plane address loses the position's lowest bit (two texel pairs share a cell)")
tmu_mutant(bank_address parity FILE texram/tmu_bank_address.sv
  FROM "((l % 2) == 1) == in_level_i[0]" TO "((l % 2) == 1) != in_level_i[0]"
  WHY "a level's offset sums the levels of the other parity (the banks' levels overlap)")

# Footprint assembly (000 §10, eq. 19-22), and at other setup widths D,T,F (DerivBits,
# TableBits, LogFracBits; the trilinear unit at 8,8,8; `texsim cosim footprint --fp-widths`):
# F = 5 takes the widening path of lambda's rounding (G = 6 fraction bits < 8), F = 12 drops 5
# bits, with the largest table (T = 10).
tmu_block(footprint)
tmu_block(footprint VARIANT d8t4f5 OPTIONS "--fp-widths 8,4,5"
  ARGS -GDerivBits=8 -GTableBits=4 -GLogFracBits=5)
tmu_block(footprint VARIANT d16t10f12 OPTIONS "--fp-widths 16,10,12"
  ARGS -GDerivBits=16 -GTableBits=10 -GLogFracBits=12)
tmu_mutant(footprint round FILE footprint/tmu_footprint_average.sv
  FROM "(SumW'(1 << head_k) >> 1)" TO "(SumW'(1 << head_k) >> 2)"
  WHY "the average adds a quarter instead of half of N before the shift")
tmu_mutant(footprint step FILE footprint/tmu_footprint_march.sv
  FROM "(d_u <<< plan_log2_n_i) + d_u;" TO "(d_u <<< plan_log2_n_i);"
  WHY "the probes start half a probe spacing off along u (the first numerator misses its + d)")
tmu_mutant(footprint k FILE footprint/tmu_footprint_setup.sv
  FROM "(SW'(1) << (G - 1))" TO "(SW'(1) << (G - 2))"
  WHY "k = log2 N rounds rho up from three quarters instead of a half (too few probes)")
tmu_mutant(footprint unreset FILE footprint/tmu_footprint.sv EXPECT x-leak
  FROM "      probes_q <= '0;\n" TO ""
  WHY "the probe counter starts where its flops happen to be")
tmu_mutant(footprint k_d8 VARIANT d8t4f5 FILE footprint/tmu_footprint_setup.sv
  FROM "(SW'(1) << (G - 1))" TO "(SW'(1) << (G - 2))"
  WHY "at F = 5 k rounds rho up from three quarters instead of a half")
tmu_mutant(footprint lambda_d16 VARIANT d16t10f12 FILE footprint/tmu_footprint_setup.sv
  FROM "((SW + 1)'(1) <<< (G - 9))" TO "((SW + 1)'(1) <<< (G - 10))"
  WHY "at F = 12 lambda's rounding to 8 fraction bits adds a quarter instead of half an LSB")

# The footprint setup on its own (the setup of tmu_footprint), at the default widths.
tmu_block(footprint_setup)
tmu_mutant(footprint_setup direction FILE footprint/tmu_footprint_setup.sv
  FROM "assign r2_longer = sum2 > sum1;" TO "assign r2_longer = sum2 >= sum1;"
  WHY "equal lengths march along r2 instead of r1 (the plan's direction)")
tmu_mutant(footprint_setup cap FILE footprint/tmu_footprint_setup.sv
  FROM "CapW'(2 * SpacingLog2);" TO "CapW'(2 * SpacingLog2 + 2);"
  WHY "the length cap of k lets probes come an eighth of a texel apart instead of a quarter")
tmu_mutant(footprint_setup unreset FILE footprint/tmu_footprint_setup.sv EXPECT x-leak
  FROM "      s1_valid_q <= 1'b0;\n      s2_valid_q <= 1'b0;\n      s3_valid_q <= 1'b0;\n      s4_valid_q <= 1'b0;\n      s5_valid_q <= 1'b0;\n      s6_valid_q <= 1'b0;\n      s7_valid_q <= 1'b0;\n"
  TO ""
  WHY "the seven stages' valids keep their initial values through reset (random plans leave)")

# TEXRAM mipmap generator (000 §12, Fig. 14).
tmu_block(mipgen)
tmu_mutant(mipgen round FILE texram/tmu_mipgen.sv
  FROM "(sum + (SumW'(2) << k))" TO "(sum + (SumW'(1) << k))"
  WHY "the texel's rounding adds a quarter instead of half of 2^(k+2) before dropping k + 2 bits (wrong on every tie)")
tmu_mutant(mipgen carry FILE texram/tmu_mipgen.sv
  FROM "KW'((2 * l < CarryBits) ? 2 * l : CarryBits)" TO "KW'((2 * l < CarryBits) ? (l > 1 ? 2 * l - 1 : 2 * l) : CarryBits)"
  WHY "the carried values keep one fraction bit less than the rule: sums lose their last bit, some texels from level 2 on are one off")
tmu_mutant(mipgen above FILE texram/tmu_mipgen.sv
  FROM "pair = PairW'(val_q) + PairW'(above_q);" TO "pair = PairW'(val_q) + PairW'(val_q);"
  WHY "interlaced field 2 pairs each texel with itself instead of the texel above (adder 1402, Fig. 14(a))")
tmu_mutant(mipgen fifo FILE texram/tmu_mipgen.sv
  FROM ".addr_i  (x_q[FifoAddrW:1])," TO ".addr_i  (x_q[FifoAddrW-1:0]),"
  WHY "the line FIFOs are addressed by column, not column pair: right until a line fills its FIFO (a 1024-texel line at stage 0), then its second half overwrites its first")
tmu_mutant(mipgen restart FILE texram/tmu_mipgen.sv
  FROM "assign pos_y = in_start_i ? '0 : src_y_q;" TO "assign pos_y = src_y_q;"
  WHY "a frame's first texel after a frame cut short keeps the old line: the new frame's texels land on the old frame's lines")
tmu_mutant(mipgen unreset FILE texram/tmu_mipgen.sv EXPECT x-leak
  FROM "      busy_q  <= 1'b0;\n" TO ""
  WHY "the generator starts busy or idle as its flop happens to be (writes out of nothing, or the first texel refused)")

# TEXRAM video port receiver (000 §11; golden/texram/video/video_port.hpp, docs/video.md).
tmu_block(video_port)
tmu_mutant(video_port line_start FILE texram/tmu_video_port.sv
  FROM "in_frame_q && in_flags_i == expected;" TO "in_frame_q && (in_flags_i | LineStart) == (expected | LineStart);"
  WHY "the receiver ignores first-of-line: a line one texel short or long is taken as the next line's texel (the frame is shown torn instead of dropped)")
tmu_mutant(video_port field_order FILE texram/tmu_video_port.sv
  FROM "assign order_err  = !match && " TO "assign order_err  = 1'b0 && !match && "
  WHY "a first-of-frame item flagged field 2 is discarded silently (no field-order error, not counted)")
tmu_mutant(video_port field2 FILE texram/tmu_video_port.sv
  FROM "(fields && y_next == height) ? CoordW'(1) : y_next[CoordW-1:0]" TO "y_next[CoordW-1:0]"
  WHY "after field 1's last line the receiver expects line height instead of line 1: every interlaced frame's field 2 is dropped")
tmu_mutant(video_port unreset FILE texram/tmu_video_port.sv EXPECT x-leak
  FROM "      discarded_q <= '0;\n" TO ""
  WHY "the discarded-items counter starts where its flops happen to be")

# TEXRAM video page-row buffers and write arbiter (000 §11-12; golden/texram/video/row_buffers.hpp
# at 8-cell rows and 8 buffers a bank, docs/video.md).
tmu_block(video_rows)
tmu_mutant(video_rows no_bound FILE texram/tmu_video_rows.sv
  FROM "(!sampler || rq_age_q[wr_k[IdW-1:0]] >= cfg_max_wait_i)" TO "(!sampler)"
  WHY "no write-latency bound: under a sampler at every cycle a ready row waits for ever (the frame is never swapped in)")
tmu_mutant(video_rows writes_first FILE texram/tmu_video_rows.sv
  FROM "(!sampler || rq_age_q[wr_k[IdW-1:0]] >= cfg_max_wait_i)" TO "(1'b1 || rq_age_q[wr_k[IdW-1:0]] >= cfg_max_wait_i)"
  WHY "a ready row goes before the sampler at once, without waiting L (the rasterizer slows down)")
tmu_mutant(video_rows no_flush FILE texram/tmu_video_rows.sv
  FROM "if (st_q[i] == Collecting && tag_q[i] == flush_tag_i)" TO "if (1'b0 && st_q[i] == Collecting && tag_q[i] == flush_tag_i)"
  WHY "a frame's end flushes nothing: its partial rows stay in the buffers and never reach the memory")
tmu_mutant(video_rows fault_free FILE texram/tmu_video_rows.sv
  FROM "assign fault    = !open_v_q[acc_bank] || open_pg_q[acc_bank] != acc_page;" TO "assign fault    = 1'b0;"
  WHY "page faults cost no second cycle (the sampler's lost cycles are undercounted)")
tmu_mutant(video_rows sampler_pages FILE texram/tmu_video_rows.sv
  FROM "open_v_q <= '0;\n        end" TO "open_v_q <= open_v_q;\n        end"
  WHY "a sampler access keeps every bank's page open (a write after the sampler is taken as a page hit)")
tmu_mutant(video_rows read_overlay FILE texram/tmu_video_rows.sv
  FROM "(rd_go ? rd_mask : '0)" TO "'0"
  WHY "a read takes no cell from the row buffers: the line above read back for interlaced field 2 misses the cells not yet written to the memory")
tmu_mutant(video_rows drained FILE texram/tmu_video_rows.sv
  FROM "!(freeing && IdW'(i) == writing_now)" TO "1'b1"
  WHY "the held frame's last write is still counted in the cycle it ends: its swap comes a cycle late")
tmu_mutant(video_rows plain_tags FILE texram/tmu_video_rows.sv
  FROM "(!rd_mask[c] || not_before(tag_q[rd_id], rd_best[c]))" TO "(!rd_mask[c] || tag_q[rd_id] >= rd_best[c])"
  WHY "tags compared as plain numbers: after the wrap (0xFFFE, then 1) a read takes the older frame's cell from the row buffers")
tmu_mutant(video_rows unreset FILE texram/tmu_video_rows.sv EXPECT x-leak
  FROM "      max_busy_q  <= '0;\n" TO ""
  WHY "the busy-buffer high-water mark starts where its flops happen to be")

# TEXRAM video unit (000 §11-12; golden/texram/video/video_unit.hpp at 8-cell rows and 8 buffers a
# bank, docs/video.md): the port, a mipmap generator per plane and the row buffers into the memory.
tmu_block(video_unit)
# ... and at the chip's rows of a page (512 cells, a row's access 64 words on the memory port):
# docs/video.md's figure from the RTL (--video-workload).
tmu_block(video_unit VARIANT page OPTIONS "--video-cells 512" ARGS -GCells=512)
tmu_mutant(video_unit early_swap FILE texram/tmu_video_unit.sv
  FROM "assign swap_now    = pending_q && o_drained;" TO "assign swap_now    = pending_q;"
  WHY "the front buffer swapped at the frame's end, before its last rows reach the memory: the sampler reads a torn frame")
tmu_mutant(video_unit read_memory_only FILE texram/tmu_video_unit.sv
  FROM "assign cap_value   = o_mask[cap_q] ? o_data[8*cap_q +: 8] : resp_q[8*cap_q[2:0] +: 8];" TO "assign cap_value   = resp_q[8*cap_q[2:0] +: 8];"
  WHY "the line above read from the memory only: cells still in a row buffer come back stale")
tmu_mutant(video_unit one_line FILE texram/tmu_video_unit.sv
  FROM "assign above_slot = r_y[1] ^ !r_y[0];" TO "assign above_slot = 1'b0;"
  WHY "one line of shift registers: the reads of the next line above overwrite the line in use")
tmu_mutant(video_unit front_buffer FILE texram/tmu_video_unit.sv
  FROM "cur_d = !newest_q;" TO "cur_d = newest_q;"
  WHY "a frame written into the buffer the sampler reads (no double buffering)")
tmu_mutant(video_unit unreset FILE texram/tmu_video_unit.sv EXPECT x-leak
  FROM "      late_q     <= '0;\n" TO ""
  WHY "the late-read counter starts where its flops happen to be")
tmu_mutant(video_unit one_word_read VARIANT page FILE texram/tmu_video_unit.sv
  FROM "else if (cap_q[2:0] == 3'd7) state_d = StBeat;" TO ""
  WHY "a read of a page row requests its first word only: the line above's later cells are taken from that word's response")

# CCC decoder (000 §3, Fig. 5).
tmu_block(ccc_decoder)
tmu_mutant(ccc_decoder decision FILE ccc/tmu_ccc_decoder.sv
  FROM "decision_bits[req_texel_i]" TO "decision_bits[req_texel_i & 4'he]"
  WHY "odd texels read the even texel's decision bit (colour a for b on half the texels)")
tmu_mutant(ccc_decoder stall FILE ccc/tmu_ccc_decoder.sv
  FROM "if (req_fire) rgb_q" TO "if (req_valid_i) rgb_q"
  WHY "the output register reloads while the output is stalled (a held output changes: the output-stable assertion)")
# The valid is the decoder's only reset flop and one bit: with its reset simply removed it starts
# at 0 in both runs of the X check (seeds 11 and 22), which then cannot tell. Its reset value
# taken from the data register, 24 bits without reset, leaks on every seed.
tmu_mutant(ccc_decoder unreset FILE ccc/tmu_ccc_decoder.sv EXPECT x-leak
  FROM "      valid_q <= 1'b0;\n" TO "      valid_q <= |rgb_q;\n"
  WHY "the output valid resets to a value of the unreset data register (a random colour leaves before any request)")

# Specular combine (000 §7 eq. 6, §8 eq. 7).
tmu_block(specular_combine)
tmu_mutant(specular_combine wrap FILE texram/tmu_specular_combine.sv
  FROM "sum[ChW] ? '1 : sum[ChW-1:0]" TO "sum[ChW-1:0]"
  WHY "the sum wraps instead of saturating at 255 (a channel darkens: the no-darkening assertion)")
tmu_mutant(specular_combine alpha FILE texram/tmu_specular_combine.sv
  FROM "s1_alpha_q   <= in_diffuse_i" TO "s1_alpha_q   <= in_specular_i"
  WHY "C's alpha is E's instead of D's")
# Its two stage valids without reset (in its copy of tmu_pipe_ctrl) started alike under both
# X-check seeds: two bits are too few. The output register's 32 bits are not.
tmu_mutant(specular_combine first FILE texram/tmu_specular_combine.sv EXPECT x-leak
  FROM "if (load[2]) s2_colour_q <= colour;" TO "if (load[2] && valid[2]) s2_colour_q <= colour;"
  WHY "the output register loads only behind another colour: a lone colour leaves as the register's initial value (read before it is written)")

# Cube environment map addressing (000 §7).
tmu_block(cube_address)
tmu_mutant(cube_address tie FILE deflect/tmu_cube_address.sv
  FROM "s1_a_q >= s1_b_q &&" TO "s1_a_q > s1_b_q &&"
  WHY "a tie of |x| and |y| goes to y (the cube's x-y edges and corners change face)")
tmu_mutant(cube_address sign FILE deflect/tmu_cube_address.sv
  FROM "{!s1_sx_q, s1_a_q, !s1_sy_q, s1_b_q};  // -Z" TO "{s1_sx_q, s1_a_q, !s1_sy_q, s1_b_q};  // -Z"
  WHY "the -Z face's sc = -x loses its sign (u mirrored on that face only)")
tmu_mutant(cube_address unreset FILE common/tmu_pipe_ctrl.sv EXPECT x-leak
  FROM "      valid_q <= '0;\n" TO ""
  WHY "the seven stage valids keep their initial values through reset (random addresses leave)")

# Normal encoder (001 §4.1): the default angle table (E = 4, M = 5) and the paper's linear index
# (E = 1, M = 7: 128 entries). Other widths run on golden, hls and icarus only.
tmu_block(normal_encoder)
tmu_block(normal_encoder VARIANT e1m7 OPTIONS "--encoder 7,1,7" ARGS -GLutExp=1 -GLutMant=7)
tmu_mutant(normal_encoder nr FILE deflect/tmu_normal_divider.sv
  FROM "16'(nr_product >> 29)" TO "16'((nr_product >> 30) << 1)"
  WHY "the Newton-Raphson step truncates one bit more (r1's LSB lost): t one LSB low, seen where t sits on a table bucket's first value")
tmu_mutant(normal_encoder pole FILE deflect/tmu_normal_encoder.sv
  FROM "k_theta >= Q ?" TO "1'b0 ?"
  WHY "theta does not saturate at the poles (k = Q wraps to magnitude 0)")
tmu_mutant(normal_encoder unreset FILE common/tmu_pipe_ctrl.sv EXPECT x-leak
  FROM "      valid_q <= '0;\n" TO ""
  WHY "the eight stage valids keep their initial values through reset (random normals leave)")
tmu_mutant(normal_encoder entry_round VARIANT e1m7 FILE deflect/tmu_normal_angle_lut.sv
  FROM "/ Q) + 0.5));" TO "/ Q) + 0.4));"
  WHY "the linear angle table rounds its entries up from 0.6 instead of a half (some entries one step low)")

# Shading/environment-map coordinate generator (001 §5): the default 512 x 256 grid with 10-bit
# entries, and the parameters' other corner, a 128 x 64 grid with 8-bit entries (no rounding in
# the dot products, the ports' upper bits ignored).
tmu_block(coord_gen)
tmu_block(coord_gen VARIANT a7w8 OPTIONS "--coord-tables 7,8" ARGS -GPhiBits=7 -GValueBits=8)
tmu_mutant(coord_gen phi_neg FILE deflect/tmu_coord_dot.sv
  FROM "phi_neg_i ? -phi_entry_i : phi_entry_i" TO "phi_entry_i"
  WHY "F2, G2, H2 not negated for phi >= 2Q (the phi + pi symmetry lost)")
tmu_mutant(coord_gen round FILE deflect/tmu_coord_reflect.sv
  FROM "(PW'(1) << (Frac - 2))" TO "(PW'(1) << (Frac - 3))"
  WHY "the reflection adds a quarter instead of half an LSB before its shift")
tmu_mutant(coord_gen unreset FILE deflect/tmu_coord_gen.sv EXPECT x-leak
  FROM "      s1_valid_q  <= 1'b0;\n      s2_valid_q  <= 1'b0;\n      out_valid_q <= 1'b0;\n" TO ""
  WHY "the three stage valids keep their initial values through reset (random coordinates leave)")
tmu_mutant(coord_gen phi_addr VARIANT a7w8 FILE deflect/tmu_coord_gen.sv
  FROM "assign phi_addr_ok   = (tw_addr_i >> HalfBits) == '0;"
  TO "assign phi_addr_ok   = (tw_addr_i >> AW) == '0;"
  WHY "on the small grid a write beyond a phi table's 2Q entries is not ignored: it overwrites entry addr mod 2Q")

# Bump deflection unit with its MBR (001 §4.4, §6.2): the map memory's requests compared.
tmu_block(deflect)
tmu_mutant(deflect tag FILE deflect/tmu_deflect.sv
  FROM "mbr_tag_q == s1_block_q" TO "mbr_tag_q[BlockW-1:1] == s1_block_q[BlockW-1:1]"
  WHY "the MBR's tag compare ignores the block address's lowest bit (neighbouring blocks alias: hits for misses, wrong entries, missing requests)")
tmu_mutant(deflect unpack FILE deflect/tmu_bump_unpack.sv
  FROM "g[7:MagBits] != '0 ? '1 : g[MagBits-1:0]" TO "g[MagBits-1:0]"
  WHY "a bump texel's |theta| wraps instead of saturating at Q - 1 (G >= Q reads G mod Q)")
tmu_mutant(deflect quadrant FILE deflect/tmu_deflect_address.sv
  FROM "quadrant[1] ^ quadrant[0]" TO "quadrant[1]"
  WHY "z's sign is phi''s top bit alone (quadrants 1 and 3 swap their z signs)")
tmu_mutant(deflect unreset FILE deflect/tmu_deflect.sv EXPECT x-leak
  FROM "      s1_valid_q  <= 1'b0;\n      s1_missed_q <= 1'b0;\n      fetching_q  <= 1'b0;\n      mbr_valid_q <= 1'b0;\n"
  TO "      fetching_q  <= 1'b0;\n"
  WHY "S1's valid and miss flag and the MBR's valid keep their initial values through reset (three bits, so two random starts rarely agree: a random request is looked up, the random MBR hit. The fetch flag keeps its reset: else a start with it set deadlocks both runs alike)")

# Material unit (002 §4.2): the fractal sums pipelined, or shared (`--fractal shared`).
tmu_block(material)
tmu_block(material VARIANT shared OPTIONS "--fractal shared" ARGS -GSharedFractal=1)
tmu_mutant(material brick FILE perlin/tmu_material.sv
  FROM "assign even_row  = !row_bit;" TO "assign even_row  = row_bit;"
  WHY "the half-brick shift on the odd rows instead of the even ones")
# (fire_clamp, not fire: the test Mutant.IsCaught/material_fire would read as block material_fire.)
tmu_mutant(material fire_clamp FILE perlin/tmu_material.sv
  FROM "fire_sum < 0 ? '0 : (fire_sum > $signed(FireW'(2**IW - 1)) ? '1 : fire_sum[IW-1:0])"
  TO "fire_sum[IW-1:0]"
  WHY "fire's index wraps mod 2^15 instead of saturating at 0 and 2^15 - 1")
tmu_mutant(material unreset FILE perlin/tmu_material.sv EXPECT x-leak
  FROM "      s1_valid_q  <= 1'b0;\n      s2_valid_q  <= 1'b0;\n      c1_valid_q  <= 1'b0;\n      c2_valid_q  <= 1'b0;\n      out_valid_q <= 1'b0;\n"
  TO ""
  WHY "the five stage valids keep their initial values through reset (random samples leave)")
# (Both variants' mutants are named V<top>_mutant_<name>: the shared one's names differ.)
tmu_mutant(material early VARIANT shared FILE perlin/tmu_fractal_shared.sv
  FROM "last_issue = issue && oct_q == 2'd3;" TO "last_issue = issue && oct_q == 2'd2;"
  WHY "the shared fractal unit takes the next sample with octave 2: wrong sums, then the unit and the material's FIFO beside it fall out of step (a deadlock)")

# Fire's e^-v table of the material unit (002 §4.2.2), a combinational top: no hls level (the
# golden table is one function call), no x-leak mutant (no flops).
tmu_block(material_fire)
tmu_mutant(material_fire series FILE perlin/tmu_material_fire.sv
  FROM "localparam int unsigned Terms   = 12;" TO "localparam int unsigned Terms   = 3;"
  WHY "e^(-1/32) from three terms of its series: 20 of the 512 entries one off (the first k = 3)")

# Tau unit (004: EP0637814 claims 4-6, 15): (s, t) -> (u, v), r1, r2, lambda through a node grid.
tmu_block(tau)
tmu_mutant(tau extrapolate FILE tau/tmu_tau_weights.sv
  FROM "        c[2] = c[2] - c[0];" TO "        c[2] = c[2] + c[0];"
  WHY "the spline's node -1 is extrapolated as 2 n(0) + n(1) instead of 2 n(0) - n(1): wrong u, v in the first cell")
tmu_mutant(tau weight FILE tau/tmu_tau_weights.sv
  FROM "      c[3] = x3 - x2;" TO "      c[3] = x3 - x2 + w_t'(1);"
  WHY "the last Catmull-Rom weight is one unit of 2^-13 too large (the weights no longer sum to one)")
tmu_mutant(tau ordering FILE tau/tmu_tau.sv
  FROM "assign node_ready_o = state_q == Idle;" TO "assign node_ready_o = 1'b1;"
  WHY "a node write is taken while a sample reads the memory (it overtakes the sample, or its address replaces the read's)")
tmu_mutant(tau unreset FILE tau/tmu_tau.sv EXPECT x-leak
  FROM "      state_q     <= Idle;\n" TO ""
  WHY "the state starts where its flops happen to be (a random step of a sample that never came)")


# The TEXRAM chip (000 §14): seven linked DRFs, the trilinear unit on each map at its base,
# footprint assembly (§10) and detail maps (§9) per DRF,
# eq. 6-7 per pixel (`texsim cosim texram_chip`; docs/texram_chip.md "The chip block").
tmu_block(texram_chip)
tmu_mutant(texram_chip base FILE texram/tmu_texram_step.sv
  FROM "tri_addr[b*AddrW +: AddrW] + base" TO "tri_addr[b*AddrW +: AddrW]"
  WHY "the map's base is not added: every map is read at cell 0 of the banks (wrong requests and colours)")
tmu_mutant(texram_chip link FILE texram/tmu_texram_chip.sv
  FROM "num_d   = next_drf;" TO "num_d   = '0;"
  WHY "the link is ignored: every chain ends after its leading DRF (missing parameters deadlock, colours wrong)")
tmu_mutant(texram_chip reflectance FILE texram/tmu_texram_chip.sv
  FROM "if (!have_refl_q) refl_d = constant_rgba;" TO "refl_d = constant_rgba;"
  WHY "an environment DRF's constant replaces a reflectance map's R (eq. 7 with the wrong R)")
tmu_mutant(texram_chip reset FILE texram/tmu_texram_drf_file.sv
  FROM "shape_q[n]    <= ShapeReset;" TO "shape_q[n]    <= '0;"
  WHY "the DRFs reset with filter nearest, not golden's trilinear: the pixels before the first program read other banks")
tmu_mutant(texram_chip fp_round FILE footprint/tmu_footprint_average.sv
  FROM "(SumW'(1 << head_k) >> 1)" TO "SumW'(0)"
  WHY "footprint assembly's average truncates instead of rounding half up (colours one level low)")
tmu_mutant(texram_chip detail_level FILE texram/tmu_texram_detail.sv
  FROM "lambda_d = in_lambda_i + (Level <<< 2);" TO "lambda_d = in_lambda_i + Level * 3;"
  WHY "the detail map is read one level too fine (lambda + 3, not + 4)")
tmu_mutant(texram_chip stream_lead FILE texram/tmu_texram_chip.sv
  FROM "param_valid_i && param_lead_i == num_q &&" TO "param_valid_i &&"
  WHY "a streamed parameter's lead is not checked: a pixel of another DRF is sampled on the streaming DRF's map")
tmu_mutant(texram_chip stream_emit FILE texram/tmu_texram_chip.sv
  FROM "out_last_d   = op != OpEmit;" TO "out_last_d   = 1'b1;"
  WHY "a streamed emit's sample leaves as the pixel's colour (last 1), and its colour after it as another pixel's")
tmu_mutant(texram_chip unreset FILE texram/tmu_texram_chip.sv EXPECT x-leak
  FROM "      pixels_q    <= '0;\n" TO ""
  WHY "the pixel counter starts where its flops happen to be")

# The volume unit (000 §13, Fig. 15): rays -> resamples from the four level-0 banks, 2 or 8
# accesses each (`texsim cosim volume`; docs/volume.md "The block").
tmu_block(volume)
tmu_mutant(volume address FILE volume/tmu_volume_address.sv
  FROM "y_i[2:1], x_i[3:1]};" TO "y_i[2:1], x_i[2:0]};"
  WHY "the cell's x bits are x[2:0] instead of x[3:1]: voxels 16 apart along x share a cell (wrong requests and values)")
tmu_mutant(volume gradient_sign FILE volume/tmu_volume_blend.sv
  FROM ": {2'b0, p} - {2'b0, m};" TO ": {2'b0, m} - {2'b0, p};"
  WHY "the central difference inside the volume is f(x - 1) - f(x + 1): every gradient component points the wrong way")
tmu_mutant(volume rounding FILE volume/tmu_volume_blend.sv
  FROM "assign value_sum = sum + 34'(1 << 23);" TO "assign value_sum = sum;"
  WHY "the value's blend truncates instead of rounding half up (golden fx::trilerp)")
tmu_mutant(volume step_sign FILE volume/tmu_volume_march.sv
  FROM "{{(PW - SW){step_q[a*SW + SW - 1]}}, step_q[a*SW +: SW]}" TO "{(PW - SW)'(0), step_q[a*SW +: SW]}"
  WHY "the marcher adds the step without its sign: a negative step moves 16 voxels forward instead of back")
tmu_mutant(volume unreset FILE volume/tmu_volume.sv EXPECT x-leak
  FROM "      resamples_q <= '0;\n" TO ""
  WHY "the resample counter starts where its flops happen to be")

tmu_write_block_tables()
