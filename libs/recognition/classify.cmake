# Descriptors (Eqs. 2, 3), Gaussian class models and the door and handle recognizers (paper §2.1).
list(APPEND VSL_RECOGNITION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/descriptors.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/class_model.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/corner_verification.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/door_recognizer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/quadrilateral.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/handle_recognizer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/recognizer_factory.cpp)
list(APPEND VSL_RECOGNITION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/descriptors_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/class_model_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/recognizers_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/quadrilateral_test.cpp)
list(APPEND VSL_RECOGNITION_BENCHES ${CMAKE_CURRENT_SOURCE_DIR}/bench/classify_bench.cpp)
