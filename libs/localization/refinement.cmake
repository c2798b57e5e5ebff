# Owned by the refinement work; see CMakeLists.txt.
list(APPEND VSL_LOCALIZATION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/pose_estimate.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/refinement.cpp)
list(APPEND VSL_LOCALIZATION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/refinement_test.cpp)
list(APPEND VSL_LOCALIZATION_BENCHES
  ${CMAKE_CURRENT_SOURCE_DIR}/bench/refinement_bench.cpp)
