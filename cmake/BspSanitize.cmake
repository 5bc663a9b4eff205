# BSP_SANITIZE=ON builds every target of this project with AddressSanitizer (with LeakSanitizer)
# and UndefinedBehaviorSanitizer, per target and never through CMAKE_CXX_FLAGS: each target that
# the project builds calls bsp_sanitize(<target>). GCC and Clang only.
#
# Libraries pass the link option on (PUBLIC): an instrumented static library needs the
# sanitizer runtimes in whatever links it, the installed package's consumers included.
# -fno-sanitize-recover makes the first UBSan finding abort the test like an ASan finding does.
include_guard(GLOBAL)

if(BSP_SANITIZE AND NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  message(FATAL_ERROR "BSP_SANITIZE needs GCC or Clang (compiler is ${CMAKE_CXX_COMPILER_ID})")
endif()

set(BSP_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)

function(bsp_sanitize target)
  if(NOT BSP_SANITIZE)
    return()
  endif()
  get_target_property(type ${target} TYPE)
  target_compile_options(${target} PRIVATE ${BSP_SANITIZE_FLAGS})
  if(type STREQUAL "EXECUTABLE")
    target_link_options(${target} PRIVATE ${BSP_SANITIZE_FLAGS})
  else()
    target_link_options(${target} PUBLIC ${BSP_SANITIZE_FLAGS})
  endif()
endfunction()
