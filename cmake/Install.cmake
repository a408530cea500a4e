# What `cmake --install` puts where (GNU layout): the two programs, the file formats' schemas and
# example scenes and stroke scripts in share/sculpt, the README and licences in share/doc/sculpt.
# The libraries and headers for other programs come with the CMake package (not yet: issue 57).
include(GNUInstallDirs)
install(TARGETS sculpt sculpt-ui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES data/reports.schema.json data/scene.schema.json data/strokes.schema.json data/ui-events.schema.json
        DESTINATION ${CMAKE_INSTALL_DATADIR}/sculpt)
install(DIRECTORY data/scenes data/strokes DESTINATION ${CMAKE_INSTALL_DATADIR}/sculpt/examples)
install(FILES README.md LICENSE THIRD_PARTY_LICENSES DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/sculpt)
