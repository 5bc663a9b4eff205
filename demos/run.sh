#!/usr/bin/env bash
# README's first command: installs what is missing, builds, and runs the main demo: the
# 200-piece running-bond wall for 10 s under stock Bullet (10 and 100 iterations) and under shock
# propagation (10 iterations), side by side, printing the comparison table.
# Extra arguments go to bsp_demo (try --help, --list). Needs only Bullet and a compiler: it
# configures its own build directory (build/demo) with the tests, the viewer, the Eigen reference
# and the benchmarks off, so GoogleTest, Eigen and Google Benchmark are not needed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tests/install-deps.sh" --demo
build="$root/build/demo"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBSP_BUILD_TESTS=OFF -DBSP_BUILD_VIEWER=OFF \
  -DBSP_BUILD_REFERENCE=OFF -DBSP_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" --target bsp_demo
if [ $# -eq 0 ]; then
  set -- --scene wall --solvers si,sp --iterations 10,100
fi
"$build/demos/bsp_demo" "$@"
