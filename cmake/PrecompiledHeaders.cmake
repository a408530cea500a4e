# sculpt_precompile_openvdb(target): parse <openvdb/openvdb.h> once per target instead of once per
# translation unit (it costs about 2.5 s of CPU each, and most of our files include it).
# Measured on 2 cores, clean build of everything: see the README's build figures.
option(SCULPT_PCH "Precompile the OpenVDB header for each of our targets" ON)

function(sculpt_precompile_openvdb target)
  if(SCULPT_PCH)
    target_precompile_headers(${target} PRIVATE <openvdb/openvdb.h>)
  endif()
endfunction()
