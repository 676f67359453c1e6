#!/usr/bin/env bash
# Quick-start command 1: install, build, and run the main job `tribo demo` (writes out/demo/).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh
build/apps/tribo demo --out out/demo
