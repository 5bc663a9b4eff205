# Debian's BulletConfig.cmake has relative include paths and lists libraries the package does
# not ship (docs/bullet-facts.md), so Bullet is found through pkg-config and wrapped in one
# imported target, bsp::bullet, for the build only: the installed package does not use it
# (plugin/CMakeLists.txt).
include_guard(GLOBAL)
find_package(PkgConfig REQUIRED)
if(BSP_DOUBLE_PRECISION)
  set(_bsp_bullet_module bullet-float64)
else()
  set(_bsp_bullet_module bullet)
endif()
pkg_check_modules(BSP_BULLET REQUIRED IMPORTED_TARGET GLOBAL ${_bsp_bullet_module})
if(NOT TARGET bsp::bullet)
  add_library(bsp::bullet INTERFACE IMPORTED GLOBAL)
  target_link_libraries(bsp::bullet INTERFACE PkgConfig::BSP_BULLET)
  if(BSP_DOUBLE_PRECISION)
    # Headers must see the precision the library was built with, or the ABI does not match.
    target_compile_definitions(bsp::bullet INTERFACE BT_USE_DOUBLE_PRECISION)
  endif()
endif()
