# gab_layer_includes(TARGET PRIVATE_DIR...): a layer's include folders.
# include/ is the installed API, public; the private folders (internal/,
# src/) serve the layer's own sources, and its tests and benchmarks reach
# them on purpose by linking TARGET_internal (tests/layering checks that
# nothing else includes them).
function(gab_layer_includes target)
  target_include_directories(${target}
    PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${ARGN})
  add_library(${target}_internal INTERFACE)
  target_include_directories(${target}_internal INTERFACE ${ARGN})
  target_link_libraries(${target}_internal INTERFACE ${target})
endfunction()
