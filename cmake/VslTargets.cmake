# Project-wide compile settings and small helpers so that every target is declared the same way.

add_library(vsl_warnings INTERFACE)
target_compile_options(vsl_warnings INTERFACE -Wall -Wextra -Wpedantic)
if(VSL_SANITIZE)
  # GCC's -Wmaybe-uninitialized is unreliable with the sanitizers' instrumentation (GCC documents
  # false positives under -fsanitize=address): at -O1 it fires inside libstdc++'s std::function
  # and Eigen's storage of a std::optional. The normal build keeps the warning.
  target_compile_options(vsl_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                -fno-sanitize-recover=undefined
                                                -Wno-maybe-uninitialized)
  target_link_options(vsl_warnings INTERFACE -fsanitize=address,undefined)
endif()

# vsl_library(NAME <target> SOURCES ... DEPS ...): a library whose public headers live in
# <dir>/include/vsl/<name>/.
function(vsl_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SOURCES})
  target_include_directories(${ARG_NAME} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${ARG_NAME} PUBLIC ${ARG_DEPS} PRIVATE vsl_warnings ${ARG_PRIVATE_DEPS})
endfunction()

# vsl_executable(NAME <target> SOURCES ... DEPS ...)
function(vsl_executable)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE vsl_warnings ${ARG_DEPS})
endfunction()

# vsl_test(NAME <target> SOURCES ... DEPS ... [LABELS ...]): one GoogleTest executable, its tests
# registered with CTest one by one. Tests run from the source tree root so that shipped files
# (config/, calib/) are found by their project-relative paths.
function(vsl_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE vsl_warnings GTest::gtest GTest::gtest_main ${ARG_DEPS})
  target_compile_definitions(${ARG_NAME} PRIVATE VSL_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                 VSL_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gtest_discover_tests(${ARG_NAME} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                       PROPERTIES LABELS "${ARG_LABELS}" DISCOVERY_TIMEOUT 60)
endfunction()

# vsl_benchmark(NAME <target> SOURCES ... DEPS ...)
function(vsl_benchmark)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS" ${ARGN})
  if(NOT VSL_BUILD_BENCHMARKS)
    return()
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE vsl_warnings benchmark::benchmark ${ARG_DEPS})
  target_compile_definitions(${ARG_NAME} PRIVATE VSL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endfunction()

include(GoogleTest)
