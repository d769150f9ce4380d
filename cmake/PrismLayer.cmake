# prism_add_layer(NAME SOURCES...): one layer of Prism as a static library `prism_NAME` with
# the alias and export name prism::NAME, the house warnings, headers included by their folder
# from the source root ("spectral/file.h", "techniques/underwater/file.h"; the same from
# include/prism when installed), and install rules for the library and the layer's headers
# (tests excluded, and the viewer's parts, which are not installed: techniques' viewer/ folders and
# gpu's window context, whose headers named what no installed library holds).
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
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})  # e.g. techniques/underwater
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/prism/${folder}
          FILES_MATCHING PATTERN "*.h" PATTERN "*_test*" EXCLUDE PATTERN "tests" EXCLUDE PATTERN "viewer" EXCLUDE
          PATTERN "window_context.h" EXCLUDE)
endfunction()
