# The Debian package: `cpack -G DEB` in a build configured with -DCMAKE_INSTALL_PREFIX=/usr
# (scripts/package.sh does both, and lints the package) makes emit_<version>_<arch>.deb of what
# cmake/install_rules.cmake installs. One package: the command, the library with its headers and
# CMake config, the Python module. Its run-time dependencies are found by dpkg-shlibdeps; those of
# building against it (the headers' Eigen, nlohmann_json, OpenBLAS) and of the Python module are
# named below.
set(EMIT_DEB_MAINTAINER "emit maintainers <maintainers@users.noreply.h-seed-a342eb11.example>"
    CACHE STRING "The Debian package's Maintainer field")

# A native package's changelog and the copyright file, where Debian's policy wants them: the
# changelog compressed as dpkg-deb would (gzip -9n: no name, no time stamp).
file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/debian/changelog EMIT_DEB_CHANGELOG_TOP LIMIT_COUNT 1)
if(NOT EMIT_DEB_CHANGELOG_TOP MATCHES "^emit \\(${PROJECT_VERSION}\\) ")
  message(FATAL_ERROR "cmake/debian/changelog: its first entry is \"${EMIT_DEB_CHANGELOG_TOP}\", "
                      "not emit (${PROJECT_VERSION}): add an entry for this version")
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/debian/changelog)
file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/debian)
execute_process(COMMAND ${EMIT_GZIP} -9nc ${PROJECT_SOURCE_DIR}/cmake/debian/changelog
                OUTPUT_FILE ${PROJECT_BINARY_DIR}/debian/changelog.gz COMMAND_ERROR_IS_FATAL ANY)
install(FILES ${PROJECT_BINARY_DIR}/debian/changelog.gz ${PROJECT_SOURCE_DIR}/cmake/debian/copyright
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
# What lintian says of the package by design, each with its reason in the file.
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/lintian-overrides DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides
        RENAME emit)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME emit)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "pressure images from tomographic tactile sensors")
# The long description, below CPACK_PACKAGE_DESCRIPTION_SUMMARY's line (CPack indents it, and
# turns the empty line into the paragraph mark).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "emit images where and how hard a soft tactile skin is pressed, from the
voltages between a few electrodes on its border: electromechanical impedance
tomography (EMIT), and current-injection skins calibrated from presses.
It meshes the sheet, builds its finite-element model and Jacobian, and
reconstructs contacts by regularised inversion or contact fitting, live from
the acquisition board, a recording or a digital twin.

This package holds the emit command, the shared libraries libemit_core,
libemit_io, libemit_live, libemit_eval and libemit_jobs with their headers and
CMake package (find_package(emit COMPONENTS ...), targets emit::core, ...,
emit::emit), and the Python module emit.
")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER ${EMIT_DEB_MAINTAINER})
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# The Python module is built for this python3 (its ABI tag is in the file's name).
set(EMIT_DEB_PYTHON_DEPENDS "")
if(EMIT_BUILD_PYTHON)
  math(EXPR next_minor "${EMIT_PYTHON_VERSION_MINOR} + 1")
  set(EMIT_DEB_PYTHON_DEPENDS ", python3 (>= ${EMIT_PYTHON_VERSION_MAJOR}.${EMIT_PYTHON_VERSION_MINOR}~), \
python3 (<< ${EMIT_PYTHON_VERSION_MAJOR}.${next_minor}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libeigen3-dev (>= 3.4), nlohmann-json3-dev (>= 3.10), libopenblas-dev, fonts-dejavu-core${EMIT_DEB_PYTHON_DEPENDS}")
# The library is in a folder of ldconfig's: the ldconfig trigger, as Debian's policy asks (CPack
# also writes a postinst and postrm calling ldconfig; cmake/debian/lintian-overrides).
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/cmake/debian/triggers)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_OUTPUT_FILE_PREFIX ${PROJECT_BINARY_DIR})
include(CPack)
