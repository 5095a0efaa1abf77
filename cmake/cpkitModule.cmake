# cpkit_add_module(<target> <export name> <source>...): one of the library modules (core, lcp,
# rate_problem), set up as all of them are: the alias and exported name cpkit::<export name>,
# the file name lib<target>, the public headers of the module's include/ (installed), the
# warning set (cpkitWarnings.cmake) and installation into the cpkitTargets export set.
# Dependencies are linked by the caller.
function(cpkit_add_module target export_name)
  add_library(${target} ${ARGN})
  add_library(cpkit::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name} OUTPUT_NAME ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  cpkit_set_warnings(${target})
  install(TARGETS ${target} EXPORT cpkitTargets)
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
