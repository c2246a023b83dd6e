#!/usr/bin/env bash
# Installs hyst from a build tree into a temporary prefix, then configures, builds and runs the
# consumer project against it with find_package(hyst).
# Usage: run_install_test.sh <hyst build dir> <consumer source dir>
set -euo pipefail
build_dir=$1
consumer_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
config=$(find "$work/prefix" -name hystConfig.cmake | head -n 1)
test -n "$config" || { echo "no package config installed"; exit 1; }
cmake -S "$consumer_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/build/consumer"
