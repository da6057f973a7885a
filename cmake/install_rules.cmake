# What `cmake --install` (and so the Debian package, cmake/debian_package.cmake) puts where, under
# the prefix (/usr for the package):
#   bin/emit                                   the command
#   lib/<triplet>/libemit_<component>.so.*     the library's components (core, io, live, eval, jobs)
#   lib/<triplet>/emit/libemit_gmsh.so         the Gmsh module emit_core loads to mesh (mesh/gmsh_mesher.hpp)
#   lib/<triplet>/cmake/emit/                  emitConfig.cmake: find_package(emit [COMPONENTS ...]),
#                                              emit::<component>, and emit::emit for all of them
#   include/emit/...                           its headers; the board's packet format they include in
#   include/emit/firmware/core/                (as "core/frame_packet.hpp")
#   lib/python3/dist-packages/emit/            the Python module (EMIT_PYTHON_INSTALL_DIR)
#   share/emit/sensors/                        the example sensors (`emit eval --sheet` reads them)
#   share/doc/emit/                            README, the Python quickstart, copyright, changelog
#   share/man/man1/emit.1.gz                   the manual page, from the commands' help
include(CMakePackageConfigHelpers)

set(EMIT_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/emit)
# Documents go in compressed as Debian wants them (gzip -9n: no name, no time stamp).
find_program(EMIT_GZIP gzip REQUIRED)

install(TARGETS emit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS emit_core emit_io emit_live emit_eval emit_jobs emit_lib EXPORT emitTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS emit_gmsh LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/emit)  # a module: no soname, not for linking
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/emit DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/firmware/core DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/emit/firmware
        FILES_MATCHING PATTERN "*.hpp")
install(EXPORT emitTargets NAMESPACE emit:: DESTINATION ${EMIT_CMAKE_INSTALL_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/emitConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/emitConfig.cmake INSTALL_DESTINATION ${EMIT_CMAKE_INSTALL_DIR})
# 0.x: a release may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/emitConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/emitConfig.cmake ${PROJECT_BINARY_DIR}/emitConfigVersion.cmake
        DESTINATION ${EMIT_CMAKE_INSTALL_DIR})

# emit(1) from the commands' own help (cmake/man_page.cmake), where help2man is (install-deps.sh
# installs it); not in a sanitizer build, which is never installed.
find_program(EMIT_HELP2MAN help2man)
if(EMIT_HELP2MAN AND NOT EMIT_SANITIZE)
  set(EMIT_MAN_PAGE ${PROJECT_BINARY_DIR}/man/emit.1.gz)
  add_custom_command(OUTPUT ${EMIT_MAN_PAGE}
                     COMMAND ${CMAKE_COMMAND} -DEMIT=$<TARGET_FILE:emit> -DHELP2MAN=${EMIT_HELP2MAN} -DGZIP=${EMIT_GZIP}
                             -DOUTPUT=${EMIT_MAN_PAGE} -P ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
                     DEPENDS emit ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
                     COMMENT "Writing emit(1) from the commands' help (help2man)")
  add_custom_target(emit_man_page ALL DEPENDS ${EMIT_MAN_PAGE})
  install(FILES ${EMIT_MAN_PAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
elseif(NOT EMIT_SANITIZE)
  message(STATUS "no help2man: the manual page emit(1) is not made (scripts/install-deps.sh installs it)")
endif()

install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/sensors/ DESTINATION ${CMAKE_INSTALL_DATADIR}/emit/sensors
        FILES_MATCHING PATTERN "*.json" PATTERN "*.step")
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/examples/python/quickstart.py DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

if(EMIT_BUILD_PYTHON)
  # Debian's python3 looks in /usr/lib/python3/dist-packages for packages of the system.
  set(EMIT_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
      "Where the Python module `emit` goes, relative to the prefix")
  install(TARGETS emit_python LIBRARY DESTINATION ${EMIT_PYTHON_INSTALL_DIR}/emit)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/emit/ DESTINATION ${EMIT_PYTHON_INSTALL_DIR}/emit
          FILES_MATCHING PATTERN "*.py" PATTERN "*.pyi" PATTERN "py.typed" PATTERN "__pycache__" EXCLUDE)
endif()
