# Warnings used for every edyn target; -Werror when EDYN_WERROR is on (CI).
function(edyn_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(EDYN_SANITIZE AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC's flow analysis reports false "may be used uninitialized" warnings in code that the
    # sanitizers instrument (std::variant moves of compound shapes); the normal build keeps it.
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
  if(EDYN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
