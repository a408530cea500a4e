# SPDX-License-Identifier: Apache-2.0
# sculpt_warnings(target): our own code compiles without warnings under -Wall -Wextra -Wpedantic
# -Wshadow; with SCULPT_WERROR (CI turns it on) a warning fails the build. Third-party headers
# are included as SYSTEM, so their warnings do not drown ours.
option(SCULPT_WERROR "Treat warnings in our own code as errors" OFF)

function(sculpt_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  if(SCULPT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
