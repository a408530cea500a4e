# What `cmake --install` puts where (GNU layout): the two programs; the core and session libraries
# with their headers (include/sculpt/core/..., include/sculpt/sculpt/session/...) and the CMake
# package that finds them (find_package(sculpt): sculpt::core, sculpt::session); the file formats'
# schemas and example scenes and stroke scripts in share/sculpt; the README and licences in
# share/doc/sculpt.
include(CMakePackageConfigHelpers)
install(TARGETS sculpt sculpt-ui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(TARGETS sculpt_core sculpt_session EXPORT sculptTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY core/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sculpt/core FILES_MATCHING PATTERN "*.h")
install(DIRECTORY sculpt/session/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sculpt/sculpt/session
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/generated/sculpt_version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sculpt)
set(packageDir ${CMAKE_INSTALL_LIBDIR}/cmake/sculpt)
install(EXPORT sculptTargets NAMESPACE sculpt:: DESTINATION ${packageDir})
configure_package_config_file(cmake/sculptConfig.cmake.in ${PROJECT_BINARY_DIR}/sculptConfig.cmake
                              INSTALL_DESTINATION ${packageDir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sculptConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sculptConfig.cmake ${PROJECT_BINARY_DIR}/sculptConfigVersion.cmake
        DESTINATION ${packageDir})

install(FILES data/reports.schema.json data/scene.schema.json data/strokes.schema.json data/ui-events.schema.json
        DESTINATION ${CMAKE_INSTALL_DATADIR}/sculpt)
install(DIRECTORY data/scenes data/strokes DESTINATION ${CMAKE_INSTALL_DATADIR}/sculpt/examples)
install(FILES README.md LICENSE THIRD_PARTY_LICENSES DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/sculpt)
