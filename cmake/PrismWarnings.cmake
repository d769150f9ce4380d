# prism_warnings(TARGET): the warning set every Prism target compiles with.
function(prism_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(PRISM_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
