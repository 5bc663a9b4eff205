#!/usr/bin/env bash
# README's test command: installs what is missing, builds in float and double precision and
# runs every test (ctest), including the consumer projects built against the install tree and the
# .deb (tests/consumer): float builds the shared library, double the static one, and each builds
# the other kind once more (library only) to install beside it, so all four are consumed; then
# builds float once more with AddressSanitizer + UndefinedBehaviorSanitizer (BSP_SANITIZE=ON)
# and runs the same tests under them. Tests labelled "long" (ctest -L long) are left out here.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tests/install-deps.sh"
jobs="$(nproc 2>/dev/null || echo 2)"
for precision in float double; do
  double=OFF shared=ON
  [ "$precision" = double ] && double=ON shared=OFF
  build="$root/build/$precision"
  echo "=== $precision precision ==="
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBSP_DOUBLE_PRECISION=$double -DBSP_REQUIRE_VIEWER=ON \
    -DBUILD_SHARED_LIBS=$shared -DCMAKE_INSTALL_PREFIX=/usr >/dev/null
  cmake --build "$build" -j "$jobs"
  (cd "$build" && ctest --output-on-failure -j "$jobs" -LE long)
done

echo "=== float precision, ASan + UBSan ==="
build="$root/build/sanitize"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBSP_SANITIZE=ON -DBSP_REQUIRE_VIEWER=ON >/dev/null
cmake --build "$build" -j "$jobs"
# Any finding fails the test that hit it (UBSan is built with -fno-sanitize-recover).
export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
(cd "$build" && ctest --output-on-failure -j "$jobs" -LE long)
