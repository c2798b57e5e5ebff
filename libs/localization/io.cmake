list(APPEND VSL_LOCALIZATION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/types.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/percept_file.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/localizer_options.cpp)
list(APPEND VSL_LOCALIZATION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/percept_file_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/localizer_options_test.cpp)
