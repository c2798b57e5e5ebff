# Owned by the core (pruning, hypotheses, validation, Localizer) work; see CMakeLists.txt.
list(APPEND VSL_LOCALIZATION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/percept_noise.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/typed_adjacency.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/node_grid.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/pose_uncertainty.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/floor_model.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segment_nodes.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/proximity_filter.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/orientation_filter.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/seeds.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/hypotheses.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/localizer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/truth_check.cpp)
list(APPEND VSL_LOCALIZATION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/support/synthetic_percepts.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/support/test_worlds.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/percept_noise_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/spatial_index_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/floor_model_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/segment_nodes_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/proximity_filter_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/orientation_filter_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/seeds_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/hypotheses_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/validation_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/localizer_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/localizer_accuracy_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/truth_check_test.cpp)
list(APPEND VSL_LOCALIZATION_BENCHES
  ${CMAKE_CURRENT_SOURCE_DIR}/test/support/synthetic_percepts.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/bench/localizer_bench.cpp)
