# prism_add_layer(NAME SOURCES...): one layer of Prism as a static library `prism_NAME` with
# the alias and export name prism::NAME, the house warnings, headers included as
# "NAME/file.h" from the source root (and from include/prism when installed), and install
# rules for the library and the layer's headers (tests excluded).
function(prism_add_layer name)
  set(target prism_${name})
  add_library(${target} ${ARGN})
  add_library(prism::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME ${target})
  prism_warnings(${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/prism>)
  install(TARGETS ${target} EXPORT PrismTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/prism/${name}
          FILES_MATCHING PATTERN "*.h" PATTERN "*_test*" EXCLUDE PATTERN "tests" EXCLUDE)
endfunction()
