# SPDX-License-Identifier: Apache-2.0
# What `cmake --install` puts where (GNU layout): the two programs; the core and session libraries
# with their headers (include/sculpt/core/..., include/sculpt/sculpt/session/...) and the CMake
# package that finds them (find_package(sculpt): sculpt::core, sculpt::session); the file formats'
# schemas and example scenes and stroke scripts in share/sculpt; the README and licences in
# share/doc/sculpt. Two components, packaged apart (cmake/Package.cmake): Runtime (the programs
# and what they use) and Development (the libraries, headers and CMake package).
include(CMakePackageConfigHelpers)
install(TARGETS sculpt sculpt-ui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)

install(TARGETS sculpt_core sculpt_session EXPORT sculptTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        COMPONENT Development)
install(DIRECTORY core/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sculpt/core COMPONENT Development
        FILES_MATCHING PATTERN "*.h")
install(DIRECTORY sculpt/session/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sculpt/sculpt/session
        COMPONENT Development FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/generated/sculpt_version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sculpt
        COMPONENT Development)
set(packageDir ${CMAKE_INSTALL_LIBDIR}/cmake/sculpt)
install(EXPORT sculptTargets NAMESPACE sculpt:: DESTINATION ${packageDir} COMPONENT Development)
configure_package_config_file(cmake/sculptConfig.cmake.in ${PROJECT_BINARY_DIR}/sculptConfig.cmake
                              INSTALL_DESTINATION ${packageDir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sculptConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sculptConfig.cmake ${PROJECT_BINARY_DIR}/sculptConfigVersion.cmake
        DESTINATION ${packageDir} COMPONENT Development)

install(FILES data/reports.schema.json data/scene.schema.json data/strokes.schema.json data/ui-events.schema.json
        DESTINATION ${CMAKE_INSTALL_DATADIR}/sculpt COMPONENT Runtime)
install(DIRECTORY data/scenes data/strokes DESTINATION ${CMAKE_INSTALL_DATADIR}/sculpt/examples COMPONENT Runtime)
install(FILES README.md LICENSE THIRD_PARTY_LICENSES DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/sculpt
        COMPONENT Runtime)
