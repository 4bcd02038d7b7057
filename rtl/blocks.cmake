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
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${src})
  file(READ ${src} original)
  string(REPLACE "${ARG_FROM}" "${ARG_TO}" mutated "${original}")
  if(mutated STREQUAL original)
    message(FATAL_ERROR "${model}: mutation of ${ARG_FILE} did not apply: update rtl/blocks.cmake")
  endif()
  get_filename_component(file_name ${ARG_FILE} NAME)
  set(mutant ${CMAKE_CURRENT_BINARY_DIR}/mutants/${model}/${file_name})
  file(WRITE ${mutant} "${mutated}")
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
tmu_mutant(ccc_cache_bilinear round FILE ccc/tmu_ccc_bilerp.sv
  FROM "VW'(1) << (2 * WW - 1)" TO "VW'(1) << (2 * WW - 2)"
  WHY "the blend adds a quarter instead of half an LSB before dropping the fraction")
tmu_mutant(ccc_cache_bilinear count FILE ccc/tmu_ccc_cache_bilinear.sv
  FROM "3'(m[0]) + 3'(m[1]) + 3'(m[2]) + 3'(m[3])" TO "3'(m[0]) + 3'(m[1]) + 3'(m[2])"
  WHY "the hit/miss counter drops the fourth block of a footprint (right outputs, wrong statistics)")
tmu_mutant(ccc_cache_bilinear neighbour FILE ccc/tmu_ccc_footprint_axis.sv
  FROM "{1'b0, blk_o} + (BlockW + 1)'(1)" TO "{1'b0, blk_o} - (BlockW + 1)'(1)"
  WHY "the lookahead prefetches the block before instead of after (wrong memory requests)")
tmu_mutant(ccc_cache_bilinear unreset FILE ccc/tmu_ccc_cache_bilinear.sv EXPECT x-leak
  FROM "      hits_q        <= '0;\n" TO ""
  WHY "the hit counter starts where its flops happen to be")

tmu_write_block_tables()
