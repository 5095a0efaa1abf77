# A ctest entry that only reports a skip (cmake -DWHY=... -DMISSING_PEER=ON|OFF -P skip.cmake):
# prints "skipped: WHY" (the entry's SKIP_REGULAR_EXPRESSION), except that a missing peer
# (MISSING_PEER=ON) fails where peers are required: CPKIT_REQUIRE_PEERS=1, or CI=true unless
# CPKIT_REQUIRE_PEERS=0 (tests/peer_skip.hpp).
set(required OFF)
if(NOT "$ENV{CPKIT_REQUIRE_PEERS}" STREQUAL "")
  if("$ENV{CPKIT_REQUIRE_PEERS}" STREQUAL "1")
    set(required ON)
  endif()
elseif("$ENV{CI}" STREQUAL "true" OR "$ENV{CI}" STREQUAL "1")
  set(required ON)
endif()
if(MISSING_PEER AND required)
  message(FATAL_ERROR "${WHY} (a missing peer fails where peers are required: CI=true or "
                      "CPKIT_REQUIRE_PEERS=1)")
endif()
message("skipped: ${WHY}")
