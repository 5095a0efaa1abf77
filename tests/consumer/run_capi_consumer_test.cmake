# The C API as a C or Fortran user meets it: installs the build tree into WORK_DIR/prefix, then,
# with the INSTALLED files only (pkg-config's flags, the installed cpkit.h and cpkit.f90):
#  - builds docs/examples/capi_example.c with the C compiler alone (gcc -std=c99, no C++ driver)
#    and runs it: it solves the tiny LCP and one contact and checks the hand answers itself;
#  - compiles the installed Fortran module, builds docs/examples/capi_example.f90 and the issue's
#    program with gfortran and runs them (hand answer; status 2 for n = -1 and NaN in q);
#  - checks that the C and Fortran blocks of docs/library.md are these example files, verbatim;
#  - builds the same C file in a C-only CMake project (find_package(cpkit), cpkit::capi);
#  - checks that libcpkit.so exports the C API's symbols only.
# Skipped (exit message "skipped: ...") only where gfortran is missing, for the Fortran part.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${CPKIT_BINARY_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(prefix ${WORK_DIR}/prefix)
foreach(f include/cpkit/cpkit.h include/cpkit/cpkit.f90)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "cmake --install did not install ${f}")
  endif()
endforeach()

# The documentation's blocks are the example files (the docs show what is tested).
file(READ ${DOCS_DIR}/library.md doc)
function(doc_block fence file)
  string(FIND "${doc}" "```${fence}\n" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "docs/library.md has no ```${fence} block")
  endif()
  string(LENGTH "```${fence}\n" skip)
  math(EXPR at "${at} + ${skip}")
  string(SUBSTRING "${doc}" ${at} -1 rest)
  string(FIND "${rest}" "```" end)
  string(SUBSTRING "${rest}" 0 ${end} block)
  file(READ ${file} text)
  if(NOT block STREQUAL text)
    message(FATAL_ERROR "the ```${fence} block of docs/library.md differs from ${file}: keep them "
                        "identical (the file is the tested program)")
  endif()
endfunction()
doc_block(c ${DOCS_DIR}/examples/capi_example.c)
doc_block(fortran ${DOCS_DIR}/examples/capi_example.f90)

file(GLOB pcfile ${prefix}/*/pkgconfig/cpkit.pc ${prefix}/*/*/pkgconfig/cpkit.pc)
if(NOT pcfile)
  message(FATAL_ERROR "cmake --install wrote no pkgconfig/cpkit.pc under ${prefix}")
endif()
get_filename_component(pcdir "${pcfile}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${pcdir}")
unset(ENV{LD_LIBRARY_PATH})
execute_process(COMMAND pkg-config --cflags --libs cpkit OUTPUT_VARIABLE cflags_libs
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
execute_process(COMMAND pkg-config --libs cpkit OUTPUT_VARIABLE libs
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc2)
if(rc OR rc2)
  message(FATAL_ERROR "pkg-config --cflags --libs cpkit failed (${rc} ${rc2})")
endif()
separate_arguments(cflags_libs UNIX_COMMAND "${cflags_libs}")
separate_arguments(libs UNIX_COMMAND "${libs}")

# Only cpkit_* symbols leave the shared library (no C++ symbol to clash with a caller's).
get_filename_component(libdir ${pcdir} DIRECTORY)
set(so ${libdir}/libcpkit.so)
execute_process(COMMAND nm -D --defined-only ${so} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
string(REGEX MATCHALL "[0-9a-f]+ [A-Za-z] [^\n]+" lines "${symbols}")
set(count 0)
foreach(line ${lines})
  if(NOT line MATCHES " (cpkit_[a-z0-9_]+(@@CPKIT_0)?|CPKIT_0)$")
    message(FATAL_ERROR "libcpkit.so exports a symbol outside the C API: ${line}")
  endif()
  math(EXPR count "${count} + 1")
endforeach()
if(rc OR count LESS 15)
  message(FATAL_ERROR "nm -D ${so}: exit ${rc}, ${count} cpkit_* symbols (expected >= 15)")
endif()

# C, with the C compiler alone.
execute_process(COMMAND gcc -std=c99 -Wall -Wextra -pedantic -Werror
                        ${DOCS_DIR}/examples/capi_example.c ${cflags_libs} -o ${WORK_DIR}/capi_c
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc)
  message(FATAL_ERROR "gcc -std=c99 capi_example.c $(pkg-config --cflags --libs cpkit) failed:\n${out}")
endif()
execute_process(COMMAND ${WORK_DIR}/capi_c RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(rc OR NOT out MATCHES "lcp: status 0, z = \\(1\\.3333333333333[0-9]*, 2\\.3333333333333[0-9]*\\)"
   OR NOT out MATCHES "contact: status 0, r = \\(1, -0\\.2, -?0\\)"
   OR NOT out MATCHES "n = -1: status 2: cpkit: bad input: n must be >= 1, got -1"
   OR NOT out MATCHES "NaN in q: status 2: cpkit: bad input: q has a non-finite entry")
  message(FATAL_ERROR "the C example failed (exit ${rc}) or printed something else")
endif()

# C with CMake: find_package(cpkit) in a C-only project, target cpkit::capi.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/capi -B ${WORK_DIR}/cmake_c
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                        -DEXAMPLE_SOURCE=${DOCS_DIR}/examples/capi_example.c
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/cmake_c
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
endif()
if(rc)
  message(FATAL_ERROR "a C project with find_package(cpkit) and cpkit::capi failed:\n${out}")
endif()
execute_process(COMMAND ${WORK_DIR}/cmake_c/capi_example RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "the C example built with CMake (cpkit::capi) failed (exit ${rc})")
endif()

# Fortran: the installed module compiled by the caller's compiler.
find_program(gfortran gfortran)
if(NOT gfortran)
  message("skipped: no gfortran (scripts/setup-deps.sh --tests installs it); the C part passed")
  return()
endif()
execute_process(COMMAND ${gfortran} -c ${prefix}/include/cpkit/cpkit.f90
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc)
  message(FATAL_ERROR "gfortran -c PREFIX/include/cpkit/cpkit.f90 failed:\n${out}")
endif()
foreach(program ${DOCS_DIR}/examples/capi_example.f90 ${CMAKE_CURRENT_LIST_DIR}/capi/issue_program.f90)
  get_filename_component(stem ${program} NAME_WE)
  execute_process(COMMAND ${gfortran} ${program} cpkit.o ${libs} -o ${stem}_f
                  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc)
    message(FATAL_ERROR "gfortran ${stem}.f90 cpkit.o $(pkg-config --libs cpkit) failed:\n${out}")
  endif()
  execute_process(COMMAND ${WORK_DIR}/${stem}_f RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${stem}:\n${out}")
  # gfortran's list-directed output: "0" then z, at least 14 correct digits each.
  if(rc OR NOT out MATCHES "^ +0 *\n +1\\.33333333333333[0-9]* +2\\.33333333333333[0-9]* *\n")
    message(FATAL_ERROR "${stem} (Fortran) did not print 0 and z = (4/3, 7/3) (exit ${rc})")
  endif()
  if(stem STREQUAL "capi_example" AND
     (NOT out MATCHES "n = -1: status 2: cpkit: bad input: n must be >= 1"
      OR NOT out MATCHES "NaN in q: status 2: cpkit: bad input: q has a non-finite entry"))
    message(FATAL_ERROR "the Fortran example's bad inputs did not give status 2 with a message")
  endif()
endforeach()
