# `cmake --install` of a build that has no Python module (scripts/run-main.sh builds the cpkit
# program alone) creates no Python folder: issue 37 found an empty PREFIX/lib/python3.X/
# dist-packages. The build's own install script of python/ is run with the module's file
# replaced by a missing one (which is what such a build has), into a fresh prefix and into one
# whose lib/ already exists (kept, nothing added under it).
file(REMOVE_RECURSE ${WORK_DIR})
file(READ ${CPKIT_BINARY_DIR}/python/cmake_install.cmake script)
string(FIND "${script}" "${MODULE_FILE}" at)
if(at LESS 0)
  message(FATAL_ERROR "${MODULE_FILE} is not named in python/cmake_install.cmake")
endif()
string(REPLACE "${MODULE_FILE}" "${WORK_DIR}/not-built/_cpkit.so" script "${script}")
file(WRITE ${WORK_DIR}/install_python.cmake "${script}")
foreach(case fresh existing_lib)
  set(prefix ${WORK_DIR}/${case})
  if(case STREQUAL "existing_lib")
    file(MAKE_DIRECTORY ${prefix}/lib)
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -DCMAKE_INSTALL_PREFIX=${prefix}
                          -P ${WORK_DIR}/install_python.cmake
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "the install script failed (${rc}):\n${out}${err}")
  endif()
  if(NOT out MATCHES "Not installing the Python module cpkit: not built")
    message(FATAL_ERROR "no 'not built' notice:\n${out}")
  endif()
  file(GLOB_RECURSE left LIST_DIRECTORIES true RELATIVE ${WORK_DIR} ${prefix}/*)
  set(expected "")
  if(case STREQUAL "existing_lib")
    set(expected "${case}/lib")
  endif()
  if(NOT "${left}" STREQUAL "${expected}")
    message(FATAL_ERROR "${case}: the install left '${left}' (expected '${expected}')")
  endif()
endforeach()
message("no Python folder created without the module (fresh prefix and existing lib/)")
