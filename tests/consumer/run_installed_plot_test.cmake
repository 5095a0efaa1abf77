# Installs cpkit into WORK_DIR/prefix and runs the INSTALLED `cpkit map --plot` and
# `cpkit simulate --plot`: the plotting scripts must come from PREFIX/share/cpkit (found relative to
# the executable), not from the source tree. A stand-in Python records which script it was given;
# then the real Python draws the pictures from the installed scripts.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${CPKIT_BINARY_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(cpkit ${WORK_DIR}/prefix/bin/cpkit)
file(WRITE ${WORK_DIR}/fake_python "#!/bin/sh\necho \"$1\" >> ${WORK_DIR}/scripts_used\n")
file(CHMOD ${WORK_DIR}/fake_python PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
set(ENV{CPKIT_PYTHON} ${WORK_DIR}/fake_python)
execute_process(COMMAND ${cpkit} map --preset fig5b --out ${WORK_DIR}/out/fig5b --plot
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
execute_process(COMMAND ${cpkit} simulate --config ${EXAMPLES_DIR}/fretting.json --cycles 1
                        --plot ${WORK_DIR}/out/sim RESULT_VARIABLE rc2 OUTPUT_QUIET ERROR_QUIET)
file(READ ${WORK_DIR}/scripts_used used)
string(STRIP "${used}" used)
set(expected "${WORK_DIR}/prefix/share/cpkit/cpkit_plot.py\n${WORK_DIR}/prefix/share/cpkit/cpkit_plot_simulation.py")
if(NOT used STREQUAL expected)
  message(FATAL_ERROR "the installed cpkit ran the plotting scripts\n${used}\ninstead of\n${expected}")
endif()
# The real thing, from the installed scripts (needs python3-matplotlib, a set-up dependency;
# without it the test is reported as skipped, saying why, or fails where peers are required).
unset(ENV{CPKIT_PYTHON})
execute_process(COMMAND /usr/bin/python3 -c "import matplotlib" RESULT_VARIABLE no_mpl
                OUTPUT_QUIET ERROR_QUIET)
if(no_mpl)
  set(why "/usr/bin/python3 has no matplotlib (Debian: python3-matplotlib); the installed "
          "scripts were found, the pictures not drawn")
  # Where every peer is installed (CI), a missing one is a failure (tests/peer_skip.hpp).
  if("$ENV{CPKIT_REQUIRE_PEERS}" STREQUAL "1" OR
     ("$ENV{CPKIT_REQUIRE_PEERS}" STREQUAL "" AND ("$ENV{CI}" STREQUAL "true" OR "$ENV{CI}" STREQUAL "1")))
    message(FATAL_ERROR "${why} (a missing peer fails where peers are required: CI=true or "
                        "CPKIT_REQUIRE_PEERS=1)")
  endif()
  message("skipped: ${why}")
  return()
endif()
execute_process(COMMAND ${cpkit} map --preset fig5b --out ${WORK_DIR}/real/fig5b --plot
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc OR NOT EXISTS ${WORK_DIR}/real/fig5b.png OR NOT EXISTS ${WORK_DIR}/real/fig5b.svg)
  message(FATAL_ERROR "installed `cpkit map --plot` drew no picture (exit ${rc}):\n${err}")
endif()
