# Every dependency comes from a Debian 12 package; a missing one stops configure with the
# package name. scripts/setup-deps.sh installs them all.
find_package(PkgConfig QUIET)
if(NOT PkgConfig_FOUND)
  message(FATAL_ERROR "pkg-config not found: install the Debian package 'pkg-config'")
endif()

find_package(Eigen3 3.4 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  message(FATAL_ERROR "Eigen 3.4 not found: install the Debian package 'libeigen3-dev'")
endif()

# Debian's Ipopt 3.11.9 ships only ipopt.pc.
pkg_check_modules(IPOPT QUIET IMPORTED_TARGET GLOBAL ipopt)
if(NOT IPOPT_FOUND)
  message(FATAL_ERROR "Ipopt not found via pkg-config: install the Debian package 'coinor-libipopt-dev'")
endif()

find_package(NLopt CONFIG QUIET)
if(NOT TARGET NLopt::nlopt)
  message(FATAL_ERROR "NLopt not found: install the Debian package 'libnlopt-cxx-dev'")
endif()

find_package(nlohmann_json 3 QUIET)
if(NOT TARGET nlohmann_json::nlohmann_json)
  message(FATAL_ERROR "nlohmann-json not found: install the Debian package 'nlohmann-json3-dev'")
endif()
# simdjson: the fast reader of dense JSON problem files (docs/file_formats.md).
find_package(simdjson QUIET CONFIG)
if(NOT TARGET simdjson::simdjson)
  message(FATAL_ERROR "simdjson not found: install the Debian package 'libsimdjson-dev'")
endif()

if(CPKIT_BUILD_APPS)
  find_package(CLI11 CONFIG QUIET)
  if(NOT TARGET CLI11::CLI11)
    message(FATAL_ERROR "CLI11 not found: install the Debian package 'libcli11-dev'")
  endif()
endif()

if(CPKIT_BUILD_TESTS)
  find_package(Catch2 2 QUIET)
  if(NOT TARGET Catch2::Catch2)
    message(FATAL_ERROR "Catch2 v2 not found: install the Debian package 'catch2'")
  endif()
endif()

find_package(Threads REQUIRED)
