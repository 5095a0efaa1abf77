# Every dependency comes from a Debian 12 package; a missing one stops configure with the
# package name. scripts/setup-deps.sh installs them all.
find_package(PkgConfig QUIET)
if(NOT PkgConfig_FOUND)
  message(FATAL_ERROR "pkg-config not found: install the Debian package 'pkg-config'")
endif()

# cpkit_require(<target> <what> <Debian package> <find command> <arguments>...): runs the find
# command (find_package, or pkg_check_modules, which adds " via pkg-config" to the message) and
# stops configure, naming the Debian package, when it did not provide <target>. A macro, so that
# the variables the find command sets stay visible here.
macro(cpkit_require target what package command)
  cmake_language(CALL ${command} ${ARGN})
  if(NOT TARGET ${target})
    if("${command}" STREQUAL "pkg_check_modules")
      message(FATAL_ERROR "${what} not found via pkg-config: install the Debian package '${package}'")
    endif()
    message(FATAL_ERROR "${what} not found: install the Debian package '${package}'")
  endif()
endmacro()

cpkit_require(Eigen3::Eigen "Eigen 3.4" libeigen3-dev find_package Eigen3 3.4 QUIET NO_MODULE)

# Debian's Ipopt 3.11.9 ships only ipopt.pc.
cpkit_require(PkgConfig::IPOPT "Ipopt" coinor-libipopt-dev
              pkg_check_modules IPOPT QUIET IMPORTED_TARGET GLOBAL ipopt)

cpkit_require(NLopt::nlopt "NLopt" libnlopt-cxx-dev find_package NLopt CONFIG QUIET)

cpkit_require(nlohmann_json::nlohmann_json "nlohmann-json" nlohmann-json3-dev
              find_package nlohmann_json 3 QUIET)
# simdjson: the fast reader of dense JSON problem files (docs/file_formats.md).
cpkit_require(simdjson::simdjson "simdjson" libsimdjson-dev find_package simdjson QUIET CONFIG)

# fclib: reader and writer of FCLIB frictional contact problems (HDF5). Found through its
# pkg-config file (which brings HDF5's): its CMake package (find_package(fclib CONFIG)) calls
# FindHDF5 with the C language, which this C++-only project (and its consumers) do not enable.
cpkit_require(PkgConfig::FCLIB "fclib" libfclib-dev
              pkg_check_modules FCLIB QUIET IMPORTED_TARGET GLOBAL fclib)

if(CPKIT_BUILD_APPS)
  cpkit_require(CLI11::CLI11 "CLI11" libcli11-dev find_package CLI11 CONFIG QUIET)
endif()

if(CPKIT_BUILD_TESTS)
  cpkit_require(Catch2::Catch2 "Catch2 v2" catch2 find_package Catch2 2 QUIET)
endif()

find_package(Threads REQUIRED)

# The Python module (python/): optional. Without pybind11, the Python 3 headers or numpy the
# module is skipped with a message and everything else builds. Debian's interpreter is the
# default so that the module matches the python3 that sees Debian's numpy/scipy/getfem.
set(CPKIT_HAVE_PYTHON FALSE)
if(CPKIT_BUILD_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python 3 interpreter of the cpkit module")
  endif()
  set(PYTHON_EXECUTABLE ${Python3_EXECUTABLE})
  find_package(Python3 3.7 QUIET COMPONENTS Interpreter Development.Module)
  set(_cpkit_numpy FALSE)
  if(Python3_Interpreter_FOUND)
    execute_process(COMMAND ${Python3_EXECUTABLE} -c "import numpy"
                    RESULT_VARIABLE _cpkit_numpy_rc OUTPUT_QUIET ERROR_QUIET)
    if(_cpkit_numpy_rc EQUAL 0)
      set(_cpkit_numpy TRUE)
    endif()
  endif()
  # pybind11 is looked for only with a working Python: its own fallback search would stop the
  # configure step with an error instead of skipping the module.
  if(NOT Python3_Interpreter_FOUND OR NOT Python3_Development.Module_FOUND)
    message(STATUS "cpkit: Python module skipped: no Python 3 interpreter with headers at ${Python3_EXECUTABLE} (install the Debian package 'python3-dev')")
  elseif(NOT _cpkit_numpy)
    message(STATUS "cpkit: Python module skipped: numpy not importable by ${Python3_EXECUTABLE} (install the Debian package 'python3-numpy')")
  else()
    find_package(pybind11 2.6 CONFIG QUIET)
    if(NOT pybind11_FOUND)
      message(STATUS "cpkit: Python module skipped: pybind11 not found (install the Debian package 'pybind11-dev')")
    else()
      set(CPKIT_HAVE_PYTHON TRUE)
      message(STATUS "cpkit: Python module for ${Python3_EXECUTABLE} (${Python3_VERSION})")
    endif()
  endif()
endif()

if(CPKIT_WITH_MPI)
  find_package(MPI COMPONENTS CXX)
  if(NOT MPI_CXX_FOUND)
    message(FATAL_ERROR "CPKIT_WITH_MPI=ON but MPI was not found: install the Debian package "
                        "'libopenmpi-dev' (or configure with -DCPKIT_WITH_MPI=OFF)")
  endif()
endif()
