# libFuzzer targets (SIMHUMAN_FUZZ=ON, clang): one executable per tests/fuzz/*_fuzz.cc, linked
# with the language module (which brings plan and core) and the MuJoCo-free part of world
# (objects and scenes, for built-in scene catalogs). Run them with scripts/fuzz_smoke.sh.
add_library(simhuman_world_catalog STATIC ${CMAKE_SOURCE_DIR}/src/simhuman/world/objects.cc
                                          ${CMAKE_SOURCE_DIR}/src/simhuman/world/scene.cc)
target_include_directories(simhuman_world_catalog PUBLIC ${CMAKE_SOURCE_DIR}/src)
target_link_libraries(simhuman_world_catalog PUBLIC simhuman_core)
file(GLOB fuzz_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/fuzz/*_fuzz.cc)
set(SIMHUMAN_FUZZ_TARGETS "")
foreach(src ${fuzz_sources})
  get_filename_component(name ${src} NAME_WE)
  add_executable(${name} ${src})
  target_link_libraries(${name} PRIVATE simhuman_language simhuman_world_catalog)
  target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  list(APPEND SIMHUMAN_FUZZ_TARGETS ${name})
endforeach()
add_custom_target(fuzz_targets DEPENDS ${SIMHUMAN_FUZZ_TARGETS})
message(STATUS "simhuman fuzz targets: ${SIMHUMAN_FUZZ_TARGETS}")
