#!/usr/bin/env bash
# Installs hyst from a build tree into a temporary prefix, then configures, builds and runs the two
# consumer projects against it with find_package(hyst): consumer_core/ (hyst::core alone, whose
# link line must name neither Ceres nor matio nor zlib) and consumer/ (hyst::hyst).
# Usage: run_install_test.sh <hyst build dir> <folder of the consumer projects>
set -euo pipefail
build_dir=$1
consumers_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
config=$(find "$work/prefix" -name hystConfig.cmake | head -n 1)
test -n "$config" || { echo "no package config installed"; exit 1; }
grep -q '^BSD 3-Clause License' "$work/prefix/share/doc/hyst/LICENSE" ||
  { echo "the licence is not installed as share/doc/hyst/LICENSE"; exit 1; }

# Configures and builds consumer project $1 into $work/$1 (its link line in $work/$1.link); the
# other arguments go to its configuration.
build_consumer() {
  local name=$1
  shift
  cmake -S "$consumers_dir/$name" -B "$work/$name" -DCMAKE_PREFIX_PATH="$work/prefix" "$@" \
    > "$work/$name.configure.log" || { cat "$work/$name.configure.log"; exit 1; }
  cmake --build "$work/$name" --verbose > "$work/$name.build.log" 2>&1 \
    || { cat "$work/$name.build.log"; exit 1; }
  cat "$work/$name"/CMakeFiles/"$name".dir/link.txt > "$work/$name.link"
}

# find_package(hyst COMPONENTS core) finds only what the core needs: with every package of the
# other layers hidden from find_package, the core consumer still configures and builds.
hidden=()
for package in Ceres NLopt nlohmann_json ZLIB PkgConfig; do
  hidden+=("-DCMAKE_DISABLE_FIND_PACKAGE_$package=ON")
done
build_consumer consumer_core "${hidden[@]}"
# ... and hiding them does bite: asking for the fitters' layer then fails, naming Ceres.
mkdir -p "$work/identify_consumer"
cat > "$work/identify_consumer/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(hyst_identify_consumer LANGUAGES CXX)
find_package(hyst REQUIRED COMPONENTS identify)
CMAKE
if cmake -S "$work/identify_consumer" -B "$work/identify_consumer/build" \
  -DCMAKE_PREFIX_PATH="$work/prefix" "${hidden[@]}" > "$work/identify.log" 2>&1; then
  echo "find_package(hyst COMPONENTS identify) configured without Ceres and NLopt"; exit 1
fi
grep -q "Ceres" "$work/identify.log" ||
  { cat "$work/identify.log"; echo "the failure without Ceres does not name it"; exit 1; }
# An unknown component is refused by name.
sed -i 's/COMPONENTS identify/COMPONENTS core nosuch/' "$work/identify_consumer/CMakeLists.txt"
if cmake -S "$work/identify_consumer" -B "$work/identify_consumer/build2" \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/nosuch.log" 2>&1; then
  echo "find_package(hyst COMPONENTS nosuch) succeeded"; exit 1
fi
grep -q "nosuch" "$work/nosuch.log" || { cat "$work/nosuch.log"; echo "nosuch not named"; exit 1; }
grep -q 'libhyst_core\.a' "$work/consumer_core.link" \
  || { echo "consumer_core does not link libhyst_core.a:"; cat "$work/consumer_core.link"; exit 1; }
if grep -E -i 'ceres|matio|libz\.|-lz\b|hyst_(io|identify|registry)' "$work/consumer_core.link"; then
  echo "consumer_core (hyst::core alone) links more than the core layer (line above)"
  exit 1
fi
"$work/consumer_core/consumer_core"

build_consumer consumer
"$work/consumer/consumer"
