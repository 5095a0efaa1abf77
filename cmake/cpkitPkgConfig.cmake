# Install-time script: writes PREFIX/LIBDIR/pkgconfig/cpkit.pc with the prefix actually installed
# to (`cmake --install build --prefix P` sets CMAKE_INSTALL_PREFIX here, after configure).
file(READ "${CPKIT_PC_IN}" pc)
string(REPLACE "prefix=${CPKIT_PC_CONFIGURED_PREFIX}\n" "prefix=${CMAKE_INSTALL_PREFIX}\n" pc "${pc}")
set(dest "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${CPKIT_PC_LIBDIR}/pkgconfig")
file(MAKE_DIRECTORY "${dest}")
file(WRITE "${dest}/cpkit.pc" "${pc}")
message(STATUS "Installing: ${dest}/cpkit.pc")
