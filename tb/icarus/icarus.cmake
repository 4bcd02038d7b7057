# The same RTL under Icarus Verilog (tb/icarus, docs/harness.md "Icarus Verilog"): the engine
# compiles a block's testbench with iverilog on first use into the cache <build>/icarus. Icarus
# is optional: without it the build works and the engine reports "iverilog not found".
find_program(TMU_IVERILOG iverilog)
find_program(TMU_VVP vvp)
set(tmu_iverilog "")
set(tmu_vvp "")
if(TMU_IVERILOG AND TMU_VVP)
  set(tmu_iverilog ${TMU_IVERILOG})
  set(tmu_vvp ${TMU_VVP})
else()
  message(STATUS "iverilog/vvp not found: the icarus engine will report it (Debian package iverilog)")
endif()
target_sources(tmu_tb PRIVATE ${CMAKE_CURRENT_LIST_DIR}/icarus_engine.cpp
  ${CMAKE_CURRENT_LIST_DIR}/icarus_level.cpp ${CMAKE_CURRENT_LIST_DIR}/testbench.cpp)
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/icarus_engine.cpp PROPERTIES
  COMPILE_DEFINITIONS "TMU_SOURCE_DIR=\"${PROJECT_SOURCE_DIR}\";TMU_IVERILOG=\"${tmu_iverilog}\";TMU_VVP=\"${tmu_vvp}\";TMU_ICARUS_CACHE_DIR=\"${CMAKE_BINARY_DIR}/icarus\"")
