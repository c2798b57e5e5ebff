# The learned recognizer: a convolutional door and handle detector (ONNX through OpenCV's dnn),
# its boxes paired and refined across the stereo images.
list(APPEND VSL_RECOGNITION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/learned_detector.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/box_refiner.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/box_stereo.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/bar_trace.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/door_rectangle_fit.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/box_stereo_options.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/learned_stereo_recognizer.cpp)
list(APPEND VSL_RECOGNITION_TESTS ${CMAKE_CURRENT_SOURCE_DIR}/test/learned_detector_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/box_refiner_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/box_stereo_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/bar_trace_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/door_rectangle_fit_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/learned_stereo_recognizer_test.cpp)
list(APPEND VSL_RECOGNITION_BENCHES ${CMAKE_CURRENT_SOURCE_DIR}/bench/learned_bench.cpp)
