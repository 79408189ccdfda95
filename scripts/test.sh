#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (core gtests, node rostests).
# Exits non-zero on any failure; the last line is "N passed, N failed" (test cases).
set -uo pipefail
cd "$(dirname "$0")/.."
export PATH="/usr/bin:$PATH"

scripts/install_deps.sh || { echo "0 passed, 1 failed"; exit 1; }
# Tests are built too (the `tests` target builds every gtest executable).
if ! scripts/build.sh all tests; then
  echo "build failed"
  echo "0 passed, 1 failed"
  exit 1
fi

rm -rf build/test_results
# Each gtest/rostest executable is a ctest; its XML report goes to build/test_results.
( cd build && ctest --output-on-failure -j"${JOBS:-$(nproc)}" )
ctest_status=$?

/usr/bin/python3 scripts/count_test_results.py build/test_results
count_status=$?
if [ $ctest_status -ne 0 ] || [ $count_status -ne 0 ]; then exit 1; fi
exit 0
