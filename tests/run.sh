#!/usr/bin/env bash
# README's test command: installs what is missing, builds in float and double precision and
# runs every test (ctest), including a consumer project built against the install tree.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tests/install-deps.sh"
jobs="$(nproc 2>/dev/null || echo 2)"
for precision in float double; do
  double=OFF
  [ "$precision" = double ] && double=ON
  build="$root/build/$precision"
  echo "=== $precision precision ==="
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBSP_DOUBLE_PRECISION=$double >/dev/null
  cmake --build "$build" -j "$jobs"
  (cd "$build" && ctest --output-on-failure -j "$jobs")
done
