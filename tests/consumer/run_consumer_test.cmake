# Installs the cpkit build tree into WORK_DIR/prefix, builds the consumer against it, runs it.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${CPKIT_BINARY_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
# The Python module is installed with its package files when it was built (the full build), and
# not at all otherwise (run-main.sh's cpkit_cli-only build: python/CMakeLists.txt).
file(GLOB built_module ${CPKIT_BINARY_DIR}/python/cpkit/_cpkit*.so)
file(GLOB_RECURSE installed_module ${WORK_DIR}/prefix/_cpkit*.so)
file(GLOB_RECURSE installed_init ${WORK_DIR}/prefix/__init__.py)
if(built_module AND NOT (installed_module AND installed_init))
  message(FATAL_ERROR "the Python module was built (${built_module}) but not installed")
endif()
if(NOT built_module AND installed_init)
  message(FATAL_ERROR "half a Python package installed (no extension built): ${installed_init}")
endif()
# The same rules as a build without the module would run them (scripts/run-main.sh builds the
# program alone): python/cmake_install.cmake with the extension's path pointing at a file that
# does not exist must succeed, say so, and install no part of the package.
if(built_module AND EXISTS ${CPKIT_BINARY_DIR}/python/cmake_install.cmake)
  list(GET built_module 0 so)
  file(READ ${CPKIT_BINARY_DIR}/python/cmake_install.cmake rules)
  string(REPLACE "${so}" "${WORK_DIR}/not_built/_cpkit.so" rules "${rules}")
  file(WRITE ${WORK_DIR}/python_install_not_built.cmake "${rules}")
  execute_process(COMMAND ${CMAKE_COMMAND} -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix_not_built
                          -P ${WORK_DIR}/python_install_not_built.cmake
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  file(GLOB_RECURSE half ${WORK_DIR}/prefix_not_built/*.py ${WORK_DIR}/prefix_not_built/*.so)
  if(rc OR half OR NOT out MATCHES "Not installing the Python module cpkit: not built")
    message(FATAL_ERROR "installing without the Python module built: exit ${rc}, installed "
                        "'${half}', said:\n${out}")
  endif()
endif()
# The consumer reads its problem from a file (the readers need simdjson at link time).
file(WRITE ${WORK_DIR}/problem.json "{\"M\": [[2, 1], [1, 2]], \"q\": [-5, -6]}\n")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer against the installed cpkit failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed (${rc})")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer ${WORK_DIR}/problem.json RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer program failed (${rc})")
endif()

# The same program without CMake, through the installed pkg-config file (cpkit.pc).
file(GLOB pcfile ${WORK_DIR}/prefix/*/pkgconfig/cpkit.pc ${WORK_DIR}/prefix/*/*/pkgconfig/cpkit.pc)
if(NOT pcfile)
  message(FATAL_ERROR "cmake --install wrote no pkgconfig/cpkit.pc under ${WORK_DIR}/prefix")
endif()
get_filename_component(pcdir "${pcfile}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${pcdir}")
execute_process(COMMAND pkg-config --cflags --libs cpkit OUTPUT_VARIABLE flags
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "pkg-config --cflags --libs cpkit failed (${rc})")
endif()
if(NOT flags MATCHES "-I${WORK_DIR}/prefix/include")
  message(FATAL_ERROR "cpkit.pc does not point at the install prefix: ${flags}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND c++ -std=c++17 -O1 ${CONSUMER_SOURCE_DIR}/main.cpp ${flags}
                        -o ${WORK_DIR}/consumer_pkgconfig RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer with pkg-config's flags failed (${rc})")
endif()
execute_process(COMMAND ${WORK_DIR}/consumer_pkgconfig ${WORK_DIR}/problem.json RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the pkg-config consumer program failed (${rc})")
endif()
