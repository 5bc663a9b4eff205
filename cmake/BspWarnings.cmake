# bsp_warnings(<target>): the project's compiler warnings, for the target's own sources only
# (PRIVATE: nothing reaches the package's consumers). Every target that compiles sources calls it.
include_guard(GLOBAL)

function(bsp_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4)
  elseif(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra)
  endif()
endfunction()
