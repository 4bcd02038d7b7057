# cmake -DSRC=<source> -DDST=<mutant> -DEDIT=<file setting FROM and TO> [-DIF_CHANGED=1]
#   [-DROWS=rtl/blocks.cmake] -P rtl/mutate.cmake
#
# Writes a mutant's copy of its source: SRC with the text FROM replaced by TO. rtl/blocks.cmake
# runs the same at configure time and makes this the build rule of the copy too, because the
# models are re-verilated before CMake reconfigures: without the rule, a changed source would
# be verilated with its stale mutant copy, which may no longer fit the files around it.
include(${EDIT})
file(READ ${SRC} original)
string(REPLACE "${FROM}" "${TO}" mutated "${original}")
if(mutated STREQUAL original)
  # The build rule runs with the last configure's FROM and TO: when the table (ROWS) has
  # changed since, the reconfiguration about to follow writes the copy from the new row.
  if(ROWS AND "${ROWS}" IS_NEWER_THAN "${EDIT}")
    message(STATUS "${DST}: left for the reconfiguration (rtl/blocks.cmake changed)")
    file(TOUCH ${DST})
    return()
  endif()
  message(FATAL_ERROR "${DST}: the mutation of ${SRC} did not apply: update rtl/blocks.cmake")
endif()
# At configure time the copy is written only when it changes, so that a reconfiguration does
# not re-verilate every mutant; the build rule always writes it (its output must be newer).
if(IF_CHANGED AND EXISTS ${DST})
  file(READ ${DST} current)
  if(current STREQUAL mutated)
    return()
  endif()
endif()
file(WRITE ${DST} "${mutated}")
