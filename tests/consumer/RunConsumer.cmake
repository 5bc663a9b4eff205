# ctest driver of the consumer tests (tests/CMakeLists.txt): install the plugin into a scratch
# prefix, build tests/consumer against it as an outside app would, with CMake (find_package) and
# with a plain Makefile (pkg-config --cflags --libs), run it (a five-box tower, main.cpp) and check
# that it linked the kind of library (shared or static) it should have.
#
# MODE this       this build tree's install (its own kind): CMake and Makefile consumer.
# MODE bothkinds  the library alone built again as the other kind (in OTHER_BUILD_DIR), both kinds
#                 installed into one prefix: CMake consumer taking the default (shared) and with
#                 BulletShockPropagation_USE_STATIC_LIBS=ON (static).
# MODE package    cpack -G DEB of the shared tree (SHARED_BUILD_DIR), both .deb unpacked into a
#                 scratch root with dpkg -x: CMake and Makefile consumer against root/usr.
#
# Other inputs: BUILD_DIR (this tree), KIND (its kind: shared|static), PRECISION (float|double),
# SANITIZE (ON: this tree is sanitized; the Makefile consumer gets the sanitizer flags pkg-config
# cannot carry), SOURCE_DIR (tests/consumer), PROJECT_DIR, WORK_DIR, INSTALL_PREFIX, LIBDIR,
# BUILD_TYPE, CXX_COMPILER.
cmake_minimum_required(VERSION 3.21)  # policies of today (quoted strings are not variables)
if(PRECISION STREQUAL "double")
  set(cmake_package BulletShockPropagation-float64)
  set(module bullet-shock-propagation-float64)
else()
  set(cmake_package BulletShockPropagation)
  set(module bullet-shock-propagation)
endif()
find_program(READELF readelf REQUIRED)

# Runs a command; stops the test with <what> if it fails.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${what} failed (${rc})")
  endif()
endfunction()

# Fails unless <exe> needs our shared library (expect shared) or does not (expect static).
function(check_kind exe expect)
  execute_process(COMMAND ${READELF} -d "${exe}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "readelf -d ${exe} failed")
  endif()
  if(dynamic MATCHES "NEEDED[^\n]*lib${cmake_package}\\.so")
    set(kind shared)
  else()
    set(kind static)
  endif()
  if(NOT kind STREQUAL expect)
    message(FATAL_ERROR "${exe} linked the ${kind} library, expected the ${expect} one")
  endif()
  message(STATUS "${exe}: ${kind} ${cmake_package}")
endfunction()

# CMake consumer in WORK_DIR/<name> against <prefix>; extra arguments go to its configure.
function(cmake_consumer name prefix expect)
  set(dir "${WORK_DIR}/${name}")
  run("configuring the CMake consumer ${name}" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${dir}"
    "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
    -DCONSUMER_PACKAGE=${cmake_package} ${ARGN})
  run("building the CMake consumer ${name}" ${CMAKE_COMMAND} --build "${dir}")
  run("the CMake consumer ${name}'s tower" "${dir}/consumer" ${PRECISION})
  check_kind("${dir}/consumer" ${expect})
endfunction()

# Makefile consumer in WORK_DIR/<name> against <prefix> (its pkg-config directory first).
function(make_consumer name prefix expect)
  set(dir "${WORK_DIR}/${name}")
  file(MAKE_DIRECTORY "${dir}")
  set(flags "")
  if(SANITIZE)
    set(flags "CXXFLAGS=-fsanitize=address,undefined")
  endif()
  set(ENV{PKG_CONFIG_PATH} "${prefix}/${LIBDIR}/pkgconfig")
  run("building the Makefile consumer ${name}" make -s -C "${dir}" -f "${SOURCE_DIR}/Makefile"
    "SRC=${SOURCE_DIR}/main.cpp" PKG=${module} "CXX=${CXX_COMPILER}" ${flags})
  set(ENV{LD_LIBRARY_PATH} "${prefix}/${LIBDIR}")
  run("the Makefile consumer ${name}'s tower" "${dir}/consumer" ${PRECISION})
  unset(ENV{LD_LIBRARY_PATH})
  check_kind("${dir}/consumer" ${expect})
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
if(MODE STREQUAL "this")
  run("installing ${BUILD_DIR}" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
  cmake_consumer(cmake "${WORK_DIR}/prefix" ${KIND})
  make_consumer(make "${WORK_DIR}/prefix" ${KIND})

elseif(MODE STREQUAL "bothkinds")
  # The library alone (no tests, no demos), same precision and install layout, the other kind.
  if(KIND STREQUAL "shared")
    set(other_shared OFF)
  else()
    set(other_shared ON)
  endif()
  if(PRECISION STREQUAL "double")
    set(double ON)
  else()
    set(double OFF)
  endif()
  run("configuring the other kind" ${CMAKE_COMMAND} -S "${PROJECT_DIR}" -B "${OTHER_BUILD_DIR}"
    -DBSP_BUILD_TESTS=OFF -DBSP_BUILD_DEMOS=OFF -DBUILD_SHARED_LIBS=${other_shared}
    -DBSP_DOUBLE_PRECISION=${double}
    "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
    "-DCMAKE_INSTALL_PREFIX=${INSTALL_PREFIX}" "-DCMAKE_INSTALL_LIBDIR=${LIBDIR}")
  run("building the other kind" ${CMAKE_COMMAND} --build "${OTHER_BUILD_DIR}" --parallel 2)
  run("installing ${BUILD_DIR}" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
  run("installing ${OTHER_BUILD_DIR}" ${CMAKE_COMMAND} --install "${OTHER_BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
  cmake_consumer(cmake-default "${WORK_DIR}/prefix" shared)
  cmake_consumer(cmake-static "${WORK_DIR}/prefix" static -DBulletShockPropagation_USE_STATIC_LIBS=ON)

elseif(MODE STREQUAL "package")
  run("cpack -G DEB" ${CMAKE_COMMAND} -E chdir "${SHARED_BUILD_DIR}" cpack -G DEB -B "${WORK_DIR}/debs")
  file(GLOB debs "${WORK_DIR}/debs/*.deb")
  list(LENGTH debs count)
  if(NOT count EQUAL 2)
    message(FATAL_ERROR "cpack made ${count} .deb packages, expected runtime and -dev: ${debs}")
  endif()
  foreach(deb IN LISTS debs)
    execute_process(COMMAND dpkg-deb -f "${deb}" Package Depends OUTPUT_VARIABLE fields)
    message(STATUS "${fields}")
    # The runtime package needs Bullet's runtime package, the -dev package Bullet's -dev package.
    if(fields MATCHES "Package: [^\n]*-dev\n")
      set(needed "libbullet-dev")
    else()
      set(needed "libbullet3.24")
    endif()
    if(NOT fields MATCHES "Depends:[^\n]*${needed}")
      message(FATAL_ERROR "${deb} does not depend on ${needed}")
    endif()
    run("dpkg -x ${deb}" dpkg -x "${deb}" "${WORK_DIR}/root")
  endforeach()
  cmake_consumer(cmake "${WORK_DIR}/root/usr" shared)
  make_consumer(make "${WORK_DIR}/root/usr" shared)

else()
  message(FATAL_ERROR "MODE must be this, bothkinds or package")
endif()
