# SPDX-License-Identifier: Apache-2.0
# The build's version for `--version` and bug reports: the project's version and the git commit
# it was configured from ("unknown" outside a git checkout, unless -DSCULPT_COMMIT=... says it, as
# the container recipe does), in a generated header that the programs include through the
# sculpt_version interface target.
find_package(Git QUIET)
set(SCULPT_COMMIT "" CACHE STRING "The commit a build outside a git checkout is of (empty: asked of git)")
set(SCULPT_GIT_COMMIT "unknown")
if(SCULPT_COMMIT)
  set(SCULPT_GIT_COMMIT "${SCULPT_COMMIT}")
elseif(GIT_FOUND)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --short=12 HEAD
                  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" OUTPUT_VARIABLE commit
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
  if(NOT failed AND commit)
    set(SCULPT_GIT_COMMIT "${commit}")
  endif()
endif()
configure_file("${PROJECT_SOURCE_DIR}/cmake/sculpt_version.h.in" "${PROJECT_BINARY_DIR}/generated/sculpt_version.h" @ONLY)
add_library(sculpt_version INTERFACE)
target_include_directories(sculpt_version INTERFACE "${PROJECT_BINARY_DIR}/generated")
