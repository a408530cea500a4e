# SPDX-License-Identifier: Apache-2.0
# Desktop integration (freedesktop.org): the launcher, the AppStream description software centres
# show, a MIME type for .vdb files (OpenVDB's magic number), a thumbnailer that renders them, and
# the icon, rendered at build time by the program itself (the window shows it too).
set(icons ${PROJECT_BINARY_DIR}/generated/icons)
add_custom_command(OUTPUT ${icons}/hicolor/256x256/apps/${SCULPT_APP_ID}.png
  COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/render_icons.sh $<TARGET_FILE:sculpt> ${PROJECT_SOURCE_DIR}/data/strokes/face.json
          ${icons} ${SCULPT_APP_ID}
  DEPENDS sculpt ${PROJECT_SOURCE_DIR}/cmake/render_icons.sh ${PROJECT_SOURCE_DIR}/data/strokes/face.json VERBATIM)
add_custom_target(icons ALL DEPENDS ${icons}/hicolor/256x256/apps/${SCULPT_APP_ID}.png)

set(desktop ${PROJECT_SOURCE_DIR}/data/desktop)
install(FILES ${desktop}/${SCULPT_APP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications COMPONENT Runtime)
install(FILES ${desktop}/${SCULPT_APP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo COMPONENT Runtime)
install(FILES ${desktop}/sculpt-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages RENAME sculpt.xml COMPONENT Runtime)
install(FILES ${desktop}/sculpt.thumbnailer DESTINATION ${CMAKE_INSTALL_DATADIR}/thumbnailers COMPONENT Runtime)
install(DIRECTORY ${icons}/hicolor DESTINATION ${CMAKE_INSTALL_DATADIR}/icons COMPONENT Runtime)
