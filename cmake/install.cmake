# `cmake --install` (and `make install PREFIX=...`): the haptex binary, every module as a static
# library with its headers, a CMake package (find_package(haptex) giving haptex::<module>) and a
# pkg-config file (docs/library.md).
include(CMakePackageConfigHelpers)

install(TARGETS haptex RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# media/codecs.hpp: the codecs plugin, where the binary's RUNPATH ($ORIGIN/../lib/haptex) finds it.
install(TARGETS haptex_opencv_codecs LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/haptex)
# core/h5/structure_probe.hpp: found there from bin/ (HAPTEX_PROBE_FROM_BINARY).
install(TARGETS haptex-h5-probe RUNTIME DESTINATION ${CMAKE_INSTALL_LIBDIR}/haptex)
foreach(target IN LISTS haptex_modules)
  string(REGEX REPLACE "^haptex_" "" module ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${module})
  install(DIRECTORY ${module}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/haptex/${module} FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/generated/core/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/haptex/core)
install(TARGETS ${haptex_modules} EXPORT haptexTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/haptex)
install(EXPORT haptexTargets NAMESPACE haptex:: DESTINATION ${config_dir})
configure_package_config_file(cmake/haptexConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/haptexConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/haptexConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/haptexConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/haptexConfigVersion.cmake
              cmake/haptex_dependencies.cmake DESTINATION ${config_dir})

# Static libraries link in reverse order of declaration: each module is declared after what it links.
set(libs ${haptex_modules})
list(REVERSE libs)
list(TRANSFORM libs PREPEND "-l")
string(JOIN " " HAPTEX_PC_LIBS ${libs})
# Relocatable: the prefix is found from the file's own place, wherever --prefix puts the tree.
file(RELATIVE_PATH HAPTEX_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" HAPTEX_PC_TO_PREFIX ${HAPTEX_PC_TO_PREFIX})
configure_file(cmake/haptex.pc.in ${CMAKE_CURRENT_BINARY_DIR}/haptex.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/haptex.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
