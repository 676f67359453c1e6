#!/usr/bin/env bash
# Quick-start command 2: install, build, and run every test (GoogleTest via CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
