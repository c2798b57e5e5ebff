# Stereo cross match, triangulation with covariance, registration into ego and the per-frame
# pipeline (paper §2.1, §2.1.1).
list(APPEND VSL_RECOGNITION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/epipolar.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/triangulation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/side_correlation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/one_image_door.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/partly_seen_door.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/bars_on_outline.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/partly_seen_bar.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/door_pair.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/door_pairing.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/stereo_views.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/stereo_match.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/stereo_assignment.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/stereo_options.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/frame_capture.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/frame_recognizer.cpp)
list(APPEND VSL_RECOGNITION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/stereo_match_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/triangulation_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/bar_match_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/cut_bar_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/partly_seen_bar_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/partly_seen_door_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/border_cut_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/occluder_cut_door_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/side_cut_door_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/one_image_door_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/side_correlation_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/frame_recognizer_test.cpp)
list(APPEND VSL_RECOGNITION_BENCHES ${CMAKE_CURRENT_SOURCE_DIR}/bench/stereo_bench.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/bench/frame_bench.cpp)
