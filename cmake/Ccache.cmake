# SPDX-License-Identifier: Apache-2.0
# Compiles through ccache when it is installed (scripts/install-deps.sh adds it), so a rebuild
# after a fix, in any of the build trees (build/, build-sanitize/), recompiles only what changed
# since any earlier build. The precompiled headers need ccache's PCH sloppiness to be cached.
option(SCULPT_CCACHE "Compile through ccache when it is installed" ON)

find_program(SCULPT_CCACHE_PROGRAM ccache)
if(SCULPT_CCACHE AND SCULPT_CCACHE_PROGRAM)
  set(CMAKE_CXX_COMPILER_LAUNCHER
      ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
      ${SCULPT_CCACHE_PROGRAM})
  message(STATUS "Compiling through ${SCULPT_CCACHE_PROGRAM}")
endif()
