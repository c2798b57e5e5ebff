# Project-wide compile settings and small helpers so that every target is declared the same way.

add_library(vsl_warnings INTERFACE)
target_compile_options(vsl_warnings INTERFACE -Wall -Wextra -Wpedantic)
if(VSL_SANITIZE)
  # GCC's -Wmaybe-uninitialized is unreliable with the sanitizers' instrumentation (GCC documents
  # false positives under -fsanitize=address): at -O1 it fires inside libstdc++'s std::function
  # and Eigen's storage of a std::optional. The normal build keeps the warning.
  # UBSan's null, alignment and pointer-overflow checks instrument every access through a pointer
  # or reference, which in Eigen's and OpenCV's templates made the sanitizer build 2.4 times as
  # slow to compile as the normal one (1.5 times without them, on the 2-core machine). They are
  # left out: a null dereference still faults under ASan with its stack, x86-64 loads need no
  # alignment, and the bounds, overflow, shift, enum, bool, vptr and return checks stay.
  target_compile_options(vsl_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                -fno-sanitize=null,alignment,pointer-overflow
                                                -fno-sanitize-recover=undefined
                                                -Wno-maybe-uninitialized)
  target_link_options(vsl_warnings INTERFACE -fsanitize=address,undefined)
endif()

# vsl_unit_tests: every executable that the tests labelled `unit` run, so that the sanitizer pass
# of tools/test builds only those (the libraries, the daemon cores, the message types and the
# fuzzer) and not the tools, daemons and end-to-end tests it does not run.
add_custom_target(vsl_unit_tests)

# One precompiled header shared by every library: Eigen, OpenCV's core and the standard headers
# most sources include. Parsing them was about 2.5 s of a library file's 5-9 s compile (-O2), on
# 280-odd files and in both builds of tools/test. As for the tests' (below), every library gets
# this target's flags and the include directories of its headers; -Winvalid-pch says when GCC
# cannot use it.
set(VSL_LIBRARY_PCH_INCLUDES $<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>
                             ${OpenCV_INCLUDE_DIRS})
add_library(vsl_library_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/library_pch.cpp)
target_link_libraries(vsl_library_pch PRIVATE vsl_warnings)
target_include_directories(vsl_library_pch SYSTEM PRIVATE ${VSL_LIBRARY_PCH_INCLUDES})
target_compile_options(vsl_library_pch PRIVATE -Winvalid-pch)
target_precompile_headers(vsl_library_pch PRIVATE <Eigen/Core> <Eigen/Geometry> <opencv2/core.hpp>
  <algorithm> <array> <cmath> <functional> <limits> <map> <memory> <optional> <stdexcept>
  <string> <vector>)

# vsl_library(NAME <target> SOURCES ... DEPS ...): a library whose public headers live in
# <dir>/include/vsl/<name>/; installed, they are in <prefix>/include/vsl/<name>/
# (cmake/VslInstall.cmake). The warnings and the precompiled header are a build-tree matter only,
# never exported.
function(vsl_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SOURCES})
  target_include_directories(${ARG_NAME} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_include_directories(${ARG_NAME} SYSTEM PRIVATE ${VSL_LIBRARY_PCH_INCLUDES})
  target_link_libraries(${ARG_NAME} PUBLIC ${ARG_DEPS}
                                    PRIVATE $<BUILD_INTERFACE:vsl_warnings> ${ARG_PRIVATE_DEPS})
  target_compile_options(${ARG_NAME} PRIVATE -Winvalid-pch)
  target_precompile_headers(${ARG_NAME} REUSE_FROM vsl_library_pch)
endfunction()

# vsl_executable(NAME <target> SOURCES ... DEPS ...)
function(vsl_executable)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE vsl_warnings ${ARG_DEPS})
endfunction()

# One precompiled header shared by every test executable: GoogleTest, Eigen, OpenCV's core and
# the standard headers most tests include. Parsing them was about 1.3 s of each test file's
# 3-5 s compile (-O2), on 120-odd test files and in both builds of tools/test. Every test target
# gets the same flags and definitions as this one (GCC uses a PCH only then: -Winvalid-pch
# says so when it does not) and the include directories of its headers.
set(VSL_TEST_DEFINITIONS VSL_SOURCE_DIR="${PROJECT_SOURCE_DIR}" VSL_BINARY_DIR="${PROJECT_BINARY_DIR}")
set(VSL_TEST_PCH_INCLUDES $<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>
                          ${OpenCV_INCLUDE_DIRS})
add_library(vsl_test_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/test_pch.cpp)
target_link_libraries(vsl_test_pch PRIVATE vsl_warnings GTest::gtest)
target_include_directories(vsl_test_pch SYSTEM PRIVATE ${VSL_TEST_PCH_INCLUDES})
target_compile_definitions(vsl_test_pch PRIVATE ${VSL_TEST_DEFINITIONS})
target_compile_options(vsl_test_pch PRIVATE -Winvalid-pch)
target_precompile_headers(vsl_test_pch PRIVATE <gtest/gtest.h> <Eigen/Core> <Eigen/Geometry>
  <opencv2/core.hpp> <algorithm> <array> <cmath> <filesystem> <fstream> <functional> <limits>
  <memory> <random> <sstream> <stdexcept> <string> <vector>)

# vsl_test(NAME <target> SOURCES ... DEPS ... [LABELS ...] [SERIAL]): one GoogleTest executable,
# its tests registered with CTest one by one. Tests run from the source tree root so that shipped
# files (config/, calib/) are found by their project-relative paths. SERIAL: ctest runs each of
# them alone (RUN_SERIAL), for the real-time pipeline whose daemons must not be starved of the
# cores by other tests, as on a robot PC they are not.
function(vsl_test)
  cmake_parse_arguments(ARG "SERIAL" "NAME" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE vsl_warnings GTest::gtest GTest::gtest_main ${ARG_DEPS})
  target_compile_definitions(${ARG_NAME} PRIVATE ${VSL_TEST_DEFINITIONS})
  target_include_directories(${ARG_NAME} SYSTEM PRIVATE ${VSL_TEST_PCH_INCLUDES})
  target_compile_options(${ARG_NAME} PRIVATE -Winvalid-pch)
  target_precompile_headers(${ARG_NAME} REUSE_FROM vsl_test_pch)
  set(properties "")
  if(ARG_LABELS)
    list(APPEND properties LABELS "${ARG_LABELS}")
  endif()
  if("unit" IN_LIST ARG_LABELS)
    add_dependencies(vsl_unit_tests ${ARG_NAME})
  endif()
  if(ARG_SERIAL)
    list(APPEND properties RUN_SERIAL TRUE)
  endif()
  gtest_discover_tests(${ARG_NAME} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} DISCOVERY_TIMEOUT 60
                       PROPERTIES ${properties})
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
