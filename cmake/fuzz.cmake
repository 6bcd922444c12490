# libFuzzer targets (SIMHUMAN_FUZZ=ON, clang): one executable per tests/fuzz/*_fuzz.cc. Besides
# core, plan and language (CMakeLists.txt), the fuzz build has the world module (MuJoCo from
# Debian: scenes, object catalogs, and the humanoid that BVH retargeting compiles) and a fuzz-only
# library of the Torch-free sources of learn/ and control/ that read user files: motion clips,
# BVH, and the MPC and PPO configs. Run them with scripts/fuzz_smoke.sh.
find_package(mujoco REQUIRED)
message(STATUS "simhuman fuzz deps: mujoco ${mujoco_VERSION}")
simhuman_module(world DEPS simhuman_core mujoco::mujoco)
set(parsers ${CMAKE_SOURCE_DIR}/src/simhuman)
add_library(simhuman_fuzz_parsers STATIC
            ${parsers}/learn/motion_clip.cc ${parsers}/learn/bvh.cc ${parsers}/learn/ppo_config.cc ${parsers}/learn/task_names.cc
            ${parsers}/control/mpc/mpc_config.cc)
target_link_libraries(simhuman_fuzz_parsers PUBLIC simhuman_world)
file(GLOB fuzz_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/fuzz/*_fuzz.cc)
set(SIMHUMAN_FUZZ_TARGETS "")
foreach(src ${fuzz_sources})
  get_filename_component(name ${src} NAME_WE)
  add_executable(${name} ${src})
  target_link_libraries(${name} PRIVATE simhuman_language simhuman_fuzz_parsers)
  target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  list(APPEND SIMHUMAN_FUZZ_TARGETS ${name})
endforeach()
add_custom_target(fuzz_targets DEPENDS ${SIMHUMAN_FUZZ_TARGETS})
message(STATUS "simhuman fuzz targets: ${SIMHUMAN_FUZZ_TARGETS}")
