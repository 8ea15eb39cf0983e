# Install and package (docs/api.md, "Installing"): the shared library
# impossible::impossible, its headers, the CLI, a CMake package, a pkg-config
# file and a Debian package. Shaders and the default layout are embedded in
# the binaries (embedded_assets), so no data files are installed.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# --- libimpossible.so: the API module's objects and, privately, the static
# modules under it (only what the API reaches is linked in). Only the
# impossible::api symbols are exported (cmake/impossible.map), so glad's GL
# pointers, nlohmann and the internal modules cannot clash with the caller's.
# 0.x releases break the ABI at each minor version: SONAME libimpossible.so.0.3.
add_library(impossible_shared SHARED $<TARGET_OBJECTS:impossible_api>)
add_library(impossible::impossible ALIAS impossible_shared)
target_link_libraries(impossible_shared PRIVATE impossible_session impossible_design embedded_assets)
target_include_directories(
  impossible_shared PUBLIC $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}/include> $<BUILD_INTERFACE:${CMAKE_BINARY_DIR}/include>
                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
# The headers use C++17 (optional, variant); the library itself is C++20.
target_compile_features(impossible_shared INTERFACE cxx_std_17)
set(impossible_map ${CMAKE_SOURCE_DIR}/cmake/impossible.map)
target_link_options(impossible_shared PRIVATE -Wl,--version-script=${impossible_map})
if(NOT IMPOSSIBLE_FUZZER)  # clang links no sanitizer runtime into shared libraries
  target_link_options(impossible_shared PRIVATE -Wl,--no-undefined)
endif()
set_target_properties(
  impossible_shared
  PROPERTIES OUTPUT_NAME impossible
             EXPORT_NAME impossible
             VERSION ${PROJECT_VERSION}
             SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
             LINK_DEPENDS ${impossible_map})

install(TARGETS impossible RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(
  TARGETS impossible_shared
  EXPORT impossibleTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${CMAKE_SOURCE_DIR}/include/impossible/impossible.hpp ${CMAKE_BINARY_DIR}/include/impossible/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impossible)
install(FILES ${CMAKE_SOURCE_DIR}/docs/api.md ${CMAKE_SOURCE_DIR}/docs/python.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# --- find_package(impossible): targets, config and version files ----------
set(impossible_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/impossible)
install(EXPORT impossibleTargets NAMESPACE impossible:: DESTINATION ${impossible_cmake_dir})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/impossibleConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/cmake/impossibleConfig.cmake INSTALL_DESTINATION ${impossible_cmake_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/impossibleConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/impossibleConfig.cmake ${CMAKE_BINARY_DIR}/cmake/impossibleConfigVersion.cmake
        DESTINATION ${impossible_cmake_dir})

# --- pkg-config: the prefix is the one installed into (cmake --install
# --prefix, or /usr for the package), so it is filled in at install time.
set(impossible_pc_dir ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
set(impossible_prefix "@impossible_prefix@")
configure_file(${CMAKE_SOURCE_DIR}/cmake/impossible.pc.in ${CMAKE_BINARY_DIR}/cmake/impossible.pc.in @ONLY)
install(CODE "set(impossible_prefix \"\${CMAKE_INSTALL_PREFIX}\")
  configure_file(${CMAKE_BINARY_DIR}/cmake/impossible.pc.in ${CMAKE_BINARY_DIR}/cmake/pc/impossible.pc @ONLY)
  file(INSTALL ${CMAKE_BINARY_DIR}/cmake/pc/impossible.pc DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${impossible_pc_dir}\")")

# --- CPack: impossible_VERSION_ARCH.deb (cpack -G DEB, or the package target)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME impossible)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the impossible project")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Stereo portal renderer for impossible spaces: CLI and C++ library")
set(CPACK_PACKAGE_CONTACT "impossible maintainers <impossible@localhost>")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# The runtime libraries (libEGL, libOSMesa, libglfw, libstdc++ ...) from
# dpkg-shlibdeps, which reads the installed packages' data offline.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The library's SONAME goes into the package's shlibs file.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
set(CPACK_STRIP_FILES ON)
include(CPack)

# --- The install test (tests/install/install_test.sh): install into a
# temporary prefix, build and run examples/embed (CMake) and
# examples/headless (pkg-config) against it, build the .deb and check it.
# Not in the sanitizer build: a program linking the sanitized libimpossible.so
# would need the ASan runtime preloaded, and the plain build runs it anyway.
if(NOT IMPOSSIBLE_SANITIZE AND NOT IMPOSSIBLE_FUZZER)
  add_test(NAME install
           COMMAND bash ${CMAKE_SOURCE_DIR}/tests/install/install_test.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}
                   ${CMAKE_COMMAND} ${CMAKE_CPACK_COMMAND} ${CMAKE_CXX_COMPILER} "${CMAKE_GENERATOR}")
  set_tests_properties(install PROPERTIES LABELS install TIMEOUT 600)
endif()
