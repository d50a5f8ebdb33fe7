# Warnings used for every edyn target; -Werror when EDYN_WERROR is on (CI).
function(edyn_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(EDYN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
