# sculpt_warnings(target): our own code compiles without warnings under -Wall -Wextra.
# Third-party headers are included as SYSTEM so their warnings do not drown ours.
function(sculpt_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
