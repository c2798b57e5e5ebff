# What `cmake --install` puts where (docs/deployment.md). Components: `runtime` (the Debian
# package vsl) and `dev` (vsl-dev).
#
#   <prefix>/bin/                        daemons, drivers and tools                    runtime
#   <prefix>/share/vsl/config/           worlds, heads, recognition models, layouts    runtime
#   <prefix>/share/vsl/calib/            camera calibrations                           runtime
#   <prefix>/share/vsl/vsl-train-detector/  the offline training tool (Python)        runtime
#   <prefix>/share/java/vsl_lcmtypes.jar the LCM types for lcm-spy (vsl-spy)           runtime
#   <etc>/vsl/*.yaml                     the daemons' configs, pointing into share/vsl runtime
#   <prefix>/lib/systemd/system/         vsl-*.service, vsl.target                     runtime
#   <etc>/default/vsl, <etc>/sysctl.d/60-vsl-lcm.conf                                   runtime
#   <prefix>/lib/libvsl_*.a, <prefix>/include/vsl/                                     dev
#   <prefix>/lib/cmake/vsl/  (find_package(vsl)), <prefix>/lib/pkgconfig/vsl.pc       dev
#   <prefix>/share/vsl/lcmtypes/*.lcm    the message definitions                       dev
#
# <etc> is /etc for the prefix /usr (the Debian package) and <prefix>/etc otherwise. The files
# under <etc> and the units name install paths, so they are written at install time
# (cmake/install_system_files.cmake), for the prefix the install actually uses.

include(CMakePackageConfigHelpers)

# --- Programs ----------------------------------------------------------------------------------
install(TARGETS vsl-sim-head vsl-v4l2-stereo vsl-libcamera-stereo
                vsl-recognition vsl-fusion vsl-localizer
                vsl-request vsl-view vsl-world vsl-worldgen vsl-localize vsl-scenario vsl-evaluate
                vsl-render vsl-make-dataset vsl-eval-recognition vsl-train-recognition
                vsl-calibrate
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(PROGRAMS tools/vsl-spy DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(DIRECTORY tools/vsl-train-detector/ DESTINATION ${CMAKE_INSTALL_DATADIR}/vsl/vsl-train-detector
        COMPONENT runtime
        FILES_MATCHING PATTERN "*.py" PATTERN "vsl-train-detector"
        PATTERN "vsl-train-detector" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ
                                                 GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/install-links)
file(CREATE_LINK ../${CMAKE_INSTALL_DATADIR}/vsl/vsl-train-detector/vsl-train-detector
     ${CMAKE_BINARY_DIR}/install-links/vsl-train-detector SYMBOLIC)
install(FILES ${CMAKE_BINARY_DIR}/install-links/vsl-train-detector
        DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)

# --- Data --------------------------------------------------------------------------------------
# The config folders keep their layout (heads name ../../calib/...); the top-level daemon configs
# go to <etc>/vsl instead (install_system_files.cmake).
install(DIRECTORY config/worlds config/heads config/recognition config/layouts
        DESTINATION ${CMAKE_INSTALL_DATADIR}/vsl/config COMPONENT runtime)
install(FILES calib/armar3_sim.yaml DESTINATION ${CMAKE_INSTALL_DATADIR}/vsl/calib
        COMPONENT runtime)
install(FILES $<TARGET_PROPERTY:vsl_lcmtypes_jar,JAR_FILE> DESTINATION ${CMAKE_INSTALL_DATADIR}/java
        COMPONENT runtime)
install(CODE "set(VSL_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
set(VSL_BINARY_DIR \"${PROJECT_BINARY_DIR}\")
set(VSL_VERSION \"${PROJECT_VERSION}\")
set(VSL_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
include(\"${PROJECT_SOURCE_DIR}/cmake/install_system_files.cmake\")"
        COMPONENT runtime)

# --- Libraries, headers, the CMake package -----------------------------------------------------
# Every library of libs/ as vsl::<name> (vsl_world -> vsl::world), the LCM types as
# vsl::lcmtypes. The interface targets that wrap Debian libraries without a CMake package go
# along (vsl::external_<name>): they name the system's files, which vsl-dev depends on.
set(VSL_EXPORTED_LIBRARIES
    vsl_config vsl_geometry vsl_head vsl_world vsl_world_import vsl_render vsl_recognition
    vsl_worldgen vsl_runtime vsl_localization vsl_scenario vsl_fusion vsl_lcmtypes)
set(VSL_EXPORTED_EXTERNALS
    vsl_lcm_external vsl_yaml_external vsl_opencv_external vsl_urdfdom_external
    vsl_sdformat_external vsl_assimp_external vsl_coin_external)
foreach(target IN LISTS VSL_EXPORTED_LIBRARIES)
  string(REGEX REPLACE "^vsl_" "" name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
endforeach()
foreach(target IN LISTS VSL_EXPORTED_EXTERNALS)
  string(REGEX REPLACE "^vsl_(.*)_external$" "external_\\1" name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
endforeach()
install(TARGETS ${VSL_EXPORTED_LIBRARIES} ${VSL_EXPORTED_EXTERNALS} EXPORT vslTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(target IN LISTS VSL_EXPORTED_LIBRARIES)
  if(NOT target STREQUAL "vsl_lcmtypes")
    string(REGEX REPLACE "^vsl_" "" name ${target})
    install(DIRECTORY libs/${name}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)
  endif()
endforeach()
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcmtypes/include/ lcmtypes/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)
file(GLOB VSL_LCM_SOURCES ${PROJECT_SOURCE_DIR}/lcmtypes/*.lcm)
install(FILES ${VSL_LCM_SOURCES} DESTINATION ${CMAKE_INSTALL_DATADIR}/vsl/lcmtypes COMPONENT dev)

set(VSL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/vsl)
install(EXPORT vslTargets NAMESPACE vsl:: DESTINATION ${VSL_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(cmake/vslConfig.cmake.in ${PROJECT_BINARY_DIR}/vslConfig.cmake
                              INSTALL_DESTINATION ${VSL_CMAKE_DIR} PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vslConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vslConfig.cmake ${PROJECT_BINARY_DIR}/vslConfigVersion.cmake
        DESTINATION ${VSL_CMAKE_DIR} COMPONENT dev)
# pkg-config: vsl.pc with ${pcfiledir}-relative paths, so that it is right under any prefix.
file(RELATIVE_PATH VSL_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
configure_file(cmake/vsl.pc.in ${PROJECT_BINARY_DIR}/vsl.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/vsl.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT dev)
