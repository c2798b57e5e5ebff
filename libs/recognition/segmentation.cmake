# Colour segmentation (paper §2.1, Fig. 2-a): region growing and mean shift into blobs.
list(APPEND VSL_RECOGNITION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation_options.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation_region_growing.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation_line_barrier.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation_mean_shift.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation_split.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/segmentation_twin_split.cpp)
list(APPEND VSL_RECOGNITION_TESTS ${CMAKE_CURRENT_SOURCE_DIR}/test/segmentation_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/segmentation_line_barrier_test.cpp)
# Run the benchmark from the repository root: it loads config/worlds/kitchen.yaml from there.
list(APPEND VSL_RECOGNITION_BENCHES ${CMAKE_CURRENT_SOURCE_DIR}/bench/segmentation_bench.cpp)
