# Run by `cmake --install` (component runtime) and so by cpack: the files that name install
# paths, written for the prefix this install uses (CMAKE_INSTALL_PREFIX here is the install-time
# one; DESTDIR, as cpack stages a package, applies through file(INSTALL)).
#   <etc>/vsl/*.yaml                 config/*.yaml with their data paths pointing into share/vsl
#   <prefix>/lib/systemd/system/     the units of config/systemd, with bin/ and <etc> filled in
#   <etc>/default/vsl, <etc>/sysctl.d/60-vsl-lcm.conf
# <etc> is /etc for the prefix /usr (the FHS, as GNUInstallDirs has it), <prefix>/etc otherwise.
# In: VSL_SOURCE_DIR, VSL_BINARY_DIR.

if(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(VSL_ETC_DIR /etc)
else()
  set(VSL_ETC_DIR ${CMAKE_INSTALL_PREFIX}/etc)
endif()
set(VSL_BIN_DIR ${CMAKE_INSTALL_PREFIX}/bin)
set(stage ${VSL_BINARY_DIR}/install-stage)
file(REMOVE_RECURSE ${stage})
file(MAKE_DIRECTORY ${stage}/vsl ${stage}/units)

# Daemon configs. Their paths are relative to the file (as in the checkout): the ones into the
# config folders (worlds/, heads/, recognition/, layouts/) and ../calib/ are rewritten relative
# to <etc>/vsl, into <prefix>/share/vsl; the ones between the top-level configs
# (options: localizer.yaml) stay, as those are installed side by side.
file(RELATIVE_PATH to_share ${VSL_ETC_DIR}/vsl ${CMAKE_INSTALL_PREFIX}/share/vsl)
file(GLOB configs ${VSL_SOURCE_DIR}/config/*.yaml)
foreach(config IN LISTS configs)
  get_filename_component(name ${config} NAME)
  file(READ ${config} text)
  string(REGEX REPLACE "([:,[] *)((worlds|heads|recognition|layouts)/)" "\\1${to_share}/config/\\2"
         text "${text}")
  string(REGEX REPLACE "([:,[] *)\\.\\./calib/" "\\1${to_share}/calib/" text "${text}")
  file(WRITE ${stage}/vsl/${name}
       "# Installed by vsl (docs/deployment.md). Paths are relative to this file:\n"
       "# ${to_share} is ${CMAKE_INSTALL_PREFIX}/share/vsl.\n${text}")
endforeach()

file(GLOB unit_templates ${VSL_SOURCE_DIR}/config/systemd/*.service.in)
foreach(template IN LISTS unit_templates)
  get_filename_component(name ${template} NAME_WLE)
  configure_file(${template} ${stage}/units/${name} @ONLY)
endforeach()
configure_file(${VSL_SOURCE_DIR}/config/systemd/vsl.target ${stage}/units/vsl.target COPYONLY)

file(GLOB staged_configs ${stage}/vsl/*.yaml)
file(GLOB staged_units ${stage}/units/*)
file(INSTALL ${staged_configs} DESTINATION ${VSL_ETC_DIR}/vsl)
file(INSTALL ${staged_units} DESTINATION ${CMAKE_INSTALL_PREFIX}/lib/systemd/system)
file(INSTALL ${VSL_SOURCE_DIR}/config/systemd/vsl.default DESTINATION ${VSL_ETC_DIR}/default
     RENAME vsl)
file(INSTALL ${VSL_SOURCE_DIR}/config/systemd/60-vsl-lcm.conf DESTINATION ${VSL_ETC_DIR}/sysctl.d)
