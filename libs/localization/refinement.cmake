# Owned by the refinement work; see CMakeLists.txt.
list(APPEND VSL_LOCALIZATION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/pose_estimate.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/refinement.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/deleted_residuals.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/chi_square.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/pose_agreement.cpp)
list(APPEND VSL_LOCALIZATION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/refinement_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/deleted_residuals_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/pose_agreement_test.cpp)
list(APPEND VSL_LOCALIZATION_BENCHES
  ${CMAKE_CURRENT_SOURCE_DIR}/bench/refinement_bench.cpp)
