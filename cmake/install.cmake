# SPDX-License-Identifier: GPL-3.0-or-later
# cmake --install: the core library, its headers (include/roughContact/..., the tree as it is
# in src/core), the command-line tools (src/cli installs them to bin), a CMake package
# (find_package(roughContact CONFIG) -> roughContact::roughContact) and roughContact.pc.
include(CMakePackageConfigHelpers)

set(ROUGHCONTACT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/roughContact)

install(TARGETS roughContact EXPORT roughContactTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/core/roughContact
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.inc")
install(EXPORT roughContactTargets
        NAMESPACE roughContact::
        FILE roughContactTargets.cmake
        DESTINATION ${ROUGHCONTACT_CMAKE_DIR})

# The config finds what the exported target needs: for a static library its private
# dependencies (pkg-config modules), for a shared one nothing.
get_target_property(ROUGHCONTACT_LIBRARY_TYPE roughContact TYPE)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/roughContactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/roughContactConfig.cmake
  INSTALL_DESTINATION ${ROUGHCONTACT_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/roughContactConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/roughContactConfig.cmake
              ${PROJECT_BINARY_DIR}/roughContactConfigVersion.cmake
        DESTINATION ${ROUGHCONTACT_CMAKE_DIR})

# roughContact.pc, relocatable: its prefix is found from the file's own place (${pcfiledir}),
# so `cmake --install build --prefix DIR` gives a working file in any DIR.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(ROUGHCONTACT_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH _rel "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  string(REGEX REPLACE "/$" "" _rel "${_rel}")
  set(ROUGHCONTACT_PC_PREFIX "\${pcfiledir}/${_rel}")
endif()
# The static core needs its dependencies on every consumer's link line, so they are Requires
# (public): `pkg-config --libs roughContact` gives -lfftw3 -lzip ... and links them as the
# system has them (shared). Not Requires.private: that needs `--static`, which also pulls the
# dependencies' own private ones (libzip's -lbz2 -llzma -lzstd), whose static libraries a
# system need not have (Debian 13 does not install them with libzip-dev). The shared core
# carries its dependencies itself.
set(ROUGHCONTACT_PC_LIBS_EXTRA "")
if(ROUGHCONTACT_LIBRARY_TYPE STREQUAL "STATIC_LIBRARY")
  set(ROUGHCONTACT_PC_REQUIRES "fftw3 libzip pugixml libcrypto")
  if(ROUGHCONTACT_OPENMP)
    # FFTW's OpenMP threads (no pkg-config module of its own) and the compiler's OpenMP runtime,
    # on Libs for the reason above
    set(ROUGHCONTACT_PC_LIBS_EXTRA " ${FFTW3_OMP_LIBRARY} ${OpenMP_CXX_FLAGS}")
  endif()
else()
  set(ROUGHCONTACT_PC_REQUIRES "")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/roughContact.pc.in
               ${PROJECT_BINARY_DIR}/roughContact.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/roughContact.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
