# SPDX-License-Identifier: Apache-2.0
# Made from the built programs, so they always say what the build does: the man pages (help2man,
# from --help and each command's --help) and the shell completions (`sculpt --completion SHELL`,
# from the command tree). Installed where man and each shell look.
find_program(HELP2MAN help2man REQUIRED)
set(generated ${PROJECT_BINARY_DIR}/generated)
add_custom_command(OUTPUT ${generated}/sculpt.1
  COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/man_page.sh $<TARGET_FILE:sculpt> ${generated}/sculpt.1
          "volumetric clay sculpting on sparse signed-distance grids"
  DEPENDS sculpt ${PROJECT_SOURCE_DIR}/cmake/man_page.sh VERBATIM)
add_custom_command(OUTPUT ${generated}/sculpt-ui.1
  COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/man_page.sh $<TARGET_FILE:sculpt-ui> ${generated}/sculpt-ui.1
          "the sculpting window: virtual clay on sparse signed-distance grids"
  DEPENDS sculpt-ui ${PROJECT_SOURCE_DIR}/cmake/man_page.sh VERBATIM)
set(completions ${generated}/completions)
add_custom_command(OUTPUT ${completions}/sculpt ${completions}/_sculpt ${completions}/sculpt.fish
  COMMAND ${CMAKE_COMMAND} -E make_directory ${completions}
  COMMAND sh -c "$1 --completion bash > $2/sculpt && $1 --completion zsh > $2/_sculpt && $1 --completion fish > $2/sculpt.fish"
          generate $<TARGET_FILE:sculpt> ${completions}
  DEPENDS sculpt VERBATIM)
add_custom_target(shell_files ALL DEPENDS ${generated}/sculpt.1 ${generated}/sculpt-ui.1 ${completions}/sculpt)

install(FILES ${generated}/sculpt.1 ${generated}/sculpt-ui.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT Runtime)
install(FILES ${completions}/sculpt DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions COMPONENT Runtime)
install(FILES ${completions}/_sculpt DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions COMPONENT Runtime)
install(FILES ${completions}/sculpt.fish DESTINATION ${CMAKE_INSTALL_DATADIR}/fish/vendor_completions.d COMPONENT Runtime)
