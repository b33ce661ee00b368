# geomint_add_experiment(NAME DIR [SOURCE...]): the executable NAME of an experiment, from every .cpp of DIR
# (experiments/NAME: main.cpp, one file per study, what they share) and the SOURCEs (e.g. a new system's
# methods/on_<system>.cpp outside this tree), linked to the library `geomint`; it finds its scenes and
# published values in DIR (GEOMINT_EXPERIMENT_DIR). Used by this tree's CMakeLists.txt and, through the
# build tree's geomint-config.cmake, by a project of experiments outside it (tests/tools/new_study_test.sh).
function(geomint_add_experiment name dir)
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  add_executable(${name} ${sources} ${ARGN})
  target_link_libraries(${name} PRIVATE geomint)
  target_compile_options(${name} PRIVATE ${GEOMINT_WARNINGS})
  target_compile_definitions(${name} PRIVATE GEOMINT_EXPERIMENT_DIR="${dir}")
endfunction()
