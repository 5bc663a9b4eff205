# cpack -G DEB: Debian packages of a shared build (-DBUILD_SHARED_LIBS=ON), named as Debian names
# Bullet's (libbullet3.24, libbullet-dev):
#   libbulletshockpropagation0.1            the shared library and LICENSE (component Runtime)
#   libbulletshockpropagation-dev           headers, .so link, CMake package, .pc, README (Development)
# and libbulletshockpropagation-float64-0.1 / libbulletshockpropagation-float64-dev for a
# BSP_DOUBLE_PRECISION build. The float and float64 packages share no file, so both install together.
# Configure with -DCMAKE_INSTALL_PREFIX=/usr for Debian's multiarch library directory.
include_guard(GLOBAL)

if(BSP_DOUBLE_PRECISION)
  set(_bsp_deb_base libbulletshockpropagation-float64)
  set(_bsp_deb_runtime ${_bsp_deb_base}-${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
else()
  set(_bsp_deb_base libbulletshockpropagation)
  set(_bsp_deb_runtime ${_bsp_deb_base}${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ${_bsp_deb_base})
set(CPACK_PACKAGE_VENDOR "BulletShockPropagation contributors")
set(CPACK_PACKAGE_CONTACT "BulletShockPropagation contributors <bulletshockpropagation@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "velocity-based shock propagation for Bullet (Erleben 2007)")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# One package per component; Runtime and Development are the install components of plugin/.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL Runtime Development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/bulletphysics/bullet3")

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME ${_bsp_deb_runtime})
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION libs)
# Dependencies from the library's NEEDED entries (dpkg-shlibdeps: libbullet3.24 with its version,
# libc6, libstdc++6, libgcc-s1); without dpkg-dev, the same packages by name.
find_program(BSP_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(BSP_DPKG_SHLIBDEPS)
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
else()
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "libbullet3.24, libc6, libstdc++6, libgcc-s1")
endif()

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME ${_bsp_deb_base}-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
  "${_bsp_deb_runtime} (= ${PROJECT_VERSION}), libbullet-dev (>= 3.24)")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
  "BulletShockPropagation: stacks that stand in Bullet with few solver iterations (shared library)")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
  "BulletShockPropagation: headers, CMake package and pkg-config file")

include(CPack)
