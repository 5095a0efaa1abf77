#pragma once
// The program's memory bound: the library's (cpkit/core/memory_limit.hpp), named here so that
// the commands' `byte_text`, `parse_byte_size` and `kMemoryLimitBytes` (cpkit::) keep their
// include line.
#include "cpkit/core/memory_limit.hpp"
