# cpack -G DEB: two Debian packages (docs/deployment.md).
#   vsl      daemons, drivers, tools, data, configs in /etc/vsl (conffiles), systemd units,
#            the system user `vsl`, the LCM receive-buffer sysctl. Its library dependencies are
#            computed by dpkg-shlibdeps from the binaries.
#   vsl-dev  static libraries, headers, the CMake package, vsl.pc, the .lcm sources; it depends
#            on the -dev packages its exported targets name (those no tool can compute).
# The package's prefix is /usr whatever the build's CMAKE_INSTALL_PREFIX: the files that name
# install paths are written at install time (cmake/install_system_files.cmake).

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vsl)
set(CPACK_PACKAGE_VENDOR "vsl developers")
set(CPACK_PACKAGE_CONTACT "vsl developers <vsl@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Model-based visual self-localization for robots with an active stereo head")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # executables only: CMake's install strip leaves static archives alone
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)  # xz takes minutes on the static libraries
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/vsl-robotics/vsl")

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME vsl)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# adduser for the system user; procps (sysctl) for the receive buffer; LCM's tools and lcm-spy's
# jars for watching and replaying; Python and PyTorch only for the offline training tool.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "adduser, procps")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "liblcm-bin, liblcm-java, libjchart2d-java, default-jre-headless | java-runtime-headless")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "python3-torch, python3-onnx, python3-numpy, python3-opencv, python3-yaml")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
    "vsl daemons over LCM: stereo camera drivers (V4L2, libcamera, simulated), door and handle recognition, fusion, the localizer; tools for world models, evaluation and replay.")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME vsl-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "vsl (= ${PROJECT_VERSION}), libeigen3-dev, libceres-dev, libopencv-dev, liblcm-dev, libyaml-dev, liburdfdom-dev, libsdformat-dev, libassimp-dev, libcoin-dev")
set(CPACK_COMPONENT_DEV_DESCRIPTION
    "vsl libraries (static), headers, the CMake package (find_package(vsl)), vsl.pc and the LCM message definitions.")
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)

# Maintainer scripts and the conffiles list (every file the package puts under /etc).
set(VSL_DEB_CONTROL ${PROJECT_BINARY_DIR}/debian-control)
file(MAKE_DIRECTORY ${VSL_DEB_CONTROL})
file(GLOB VSL_TOP_CONFIGS RELATIVE ${PROJECT_SOURCE_DIR}/config ${PROJECT_SOURCE_DIR}/config/*.yaml)
set(VSL_CONFFILES "/etc/default/vsl\n/etc/sysctl.d/60-vsl-lcm.conf\n")
foreach(config IN LISTS VSL_TOP_CONFIGS)
  string(APPEND VSL_CONFFILES "/etc/vsl/${config}\n")
endforeach()
file(WRITE ${VSL_DEB_CONTROL}/conffiles "${VSL_CONFFILES}")
foreach(script postinst prerm postrm)
  file(COPY ${PROJECT_SOURCE_DIR}/cmake/debian/${script} DESTINATION ${VSL_DEB_CONTROL}
       FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ
                        WORLD_EXECUTE)
endforeach()
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA
    ${VSL_DEB_CONTROL}/conffiles ${VSL_DEB_CONTROL}/postinst ${VSL_DEB_CONTROL}/prerm
    ${VSL_DEB_CONTROL}/postrm)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
