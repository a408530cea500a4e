# SPDX-License-Identifier: Apache-2.0
# sculpt_precompile(target HEADERS header... [LIGHT source...]): the third-party headers nearly
# every file of a target includes, parsed once per target instead of once per file (OpenVDB's
# headers cost about six seconds per translation unit, CLI11's five). LIGHT lists the target's
# sources that include no OpenVDB: loading the precompiled header (240 MB) would cost them more
# than it saves. The fuzz build (scripts/fuzz.sh) turns this off, so every header is still
# proven to compile without it.
option(SCULPT_PRECOMPILE_HEADERS "Precompile the heavy third-party headers per target" ON)

function(sculpt_precompile target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "HEADERS;LIGHT")
  if(SCULPT_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${arg_HEADERS})
    if(arg_LIGHT)
      set_source_files_properties(${arg_LIGHT} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endif()
endfunction()
