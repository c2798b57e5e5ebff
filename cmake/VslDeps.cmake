# Third-party dependencies, all from Debian packages (see tools/packages.txt).
# Third-party headers are included as SYSTEM so that the project's own warnings stay meaningful.

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(GTest REQUIRED)
find_package(benchmark REQUIRED)
find_package(Threads REQUIRED)
find_package(Ceres REQUIRED)
find_package(Java 11 REQUIRED COMPONENTS Development)
include(UseJava)

# LCM 1.3.1 ships no CMake config package: find the library, header and generator directly.
find_library(LCM_LIBRARY NAMES lcm REQUIRED)
find_path(LCM_INCLUDE_DIR NAMES lcm/lcm-cpp.hpp REQUIRED)
find_program(LCM_GEN lcm-gen REQUIRED)
find_file(LCM_JAR lcm.jar PATHS /usr/share/java REQUIRED)
add_library(vsl_lcm_external INTERFACE)
target_link_libraries(vsl_lcm_external INTERFACE ${LCM_LIBRARY})
target_include_directories(vsl_lcm_external SYSTEM INTERFACE ${LCM_INCLUDE_DIR})

# libyaml (the reference C YAML parser, libyaml-dev) under vsl_config. yaml-cpp was measured and
# rejected for world files: 12.7 s and 2 GB for a 100k-object building, libyaml 2.3 s.
find_library(YAML_LIBRARY NAMES yaml REQUIRED)
find_path(YAML_INCLUDE_DIR NAMES yaml.h REQUIRED)
add_library(vsl_yaml_external INTERFACE)
target_link_libraries(vsl_yaml_external INTERFACE ${YAML_LIBRARY})
target_include_directories(vsl_yaml_external SYSTEM INTERFACE ${YAML_INCLUDE_DIR})

# OpenCV 4.6 (libopencv-dev): images, the renderer, recognition (dnn runs the learned detector),
# calibration. Its headers warn under C++20 (-Wdeprecated-enum-enum-conversion), hence SYSTEM.
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs calib3d dnn)
add_library(vsl_opencv_external INTERFACE)
target_link_libraries(vsl_opencv_external INTERFACE ${OpenCV_LIBS})
target_include_directories(vsl_opencv_external SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})

# libcamera 0.0.3 (libcamera-dev) for vsl-libcamera-stereo: pkg-config only, no CMake package.
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBCAMERA REQUIRED IMPORTED_TARGET libcamera)
add_library(vsl_libcamera_external INTERFACE)
target_link_libraries(vsl_libcamera_external INTERFACE PkgConfig::LIBCAMERA)
target_include_directories(vsl_libcamera_external SYSTEM INTERFACE ${LIBCAMERA_INCLUDE_DIRS})

# World import (libs/world_import): each format through its own well-kept Debian library.
# urdfdom 3 (liburdfdom-dev) ships a CMake package with plain variables, not targets.
find_package(urdfdom REQUIRED)
add_library(vsl_urdfdom_external INTERFACE)
target_link_libraries(vsl_urdfdom_external INTERFACE ${urdfdom_LIBRARIES})
target_include_directories(vsl_urdfdom_external SYSTEM INTERFACE ${urdfdom_INCLUDE_DIRS})
# SDFormat 12 (libsdformat-dev): SDF and Gazebo .world files.
find_package(sdformat12 REQUIRED)
add_library(vsl_sdformat_external INTERFACE)
target_link_libraries(vsl_sdformat_external INTERFACE sdformat12::sdformat12)
# Assimp 5 (libassimp-dev): COLLADA, OBJ, glTF, STL, PLY and the meshes URDF and SDF refer to.
find_package(assimp REQUIRED)
add_library(vsl_assimp_external INTERFACE)
target_link_libraries(vsl_assimp_external INTERFACE assimp::assimp)
# Coin3D 4 (libcoin-dev): VRML 2 and Open Inventor. No CMake or pkg-config package in Debian.
find_library(COIN_LIBRARY NAMES Coin REQUIRED)
find_path(COIN_INCLUDE_DIR NAMES Inventor/SoDB.h REQUIRED)
add_library(vsl_coin_external INTERFACE)
target_link_libraries(vsl_coin_external INTERFACE ${COIN_LIBRARY})
target_include_directories(vsl_coin_external SYSTEM INTERFACE ${COIN_INCLUDE_DIR})
