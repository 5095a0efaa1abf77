# cpkit_set_warnings(target): the warning set every cpkit target builds clean with.
function(cpkit_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
endfunction()
