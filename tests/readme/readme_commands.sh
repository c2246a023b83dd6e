#!/usr/bin/env bash
# Runs the command blocks (```sh) of the README as written, in order, in one shell: later blocks
# use the files and variables of earlier ones, as a reader going down the page would. The scratch
# folder is laid out like a checkout beside the shared data (hyst/ with links to the checkout's
# files and hyst/build to the build folder, shared/data), so that `build/apps/hyst` and
# `../shared/data/...` resolve as in the README. The block of the set-up commands (make demo /
# make test) is left out: it is what runs this. `pip install .` is pointed at the build folder
# (HYST_WHEEL_BUILD_DIR) so that it does not compile the library again.
# A block fails the test when one of its commands fails; the files the README names are checked.
# The ```cpp blocks are compiled against the installed library and run first.
#
# Usage: readme_commands.sh README.md BUILD_DIR SHARED_DATA_DIR
set -euo pipefail

readme=$(realpath "$1")
build=$(realpath "$2")
data=$(realpath "$3")
checkout=$(dirname "$readme")

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/shared" "$scratch/hyst"
ln -s "$data" "$scratch/shared/data"
for entry in "$checkout"/*; do
  case "$(basename "$entry")" in build* | out | venv) continue ;; esac
  ln -s "$entry" "$scratch/hyst/$(basename "$entry")"
done
ln -s "$build" "$scratch/hyst/build"
cd "$scratch/hyst"
export HYST_WHEEL_BUILD_DIR="$build" PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_INPUT=1
unset PYTHONPATH

# Every ```cpp block is a whole program: installed with the library (cmake --install) and built
# as a user's project would (find_package(hyst COMPONENTS core), hyst::core), then run.
cmake --install "$build" --prefix "$scratch/prefix" >"$scratch/install.log" ||
  { cat "$scratch/install.log"; echo "FAIL: cmake --install of $build"; exit 1; }
awk -v dir="$scratch/cpp" '
  /^```cpp$/ { inside = 1; ++blocks; file = sprintf("%s/block%d.cpp", dir, blocks)
               system("mkdir -p " dir); printf "" > file; next }
  /^```$/ && inside { inside = 0; close(file); next }
  inside { print > file }
  END { if (blocks < 1) { print "no cpp block found" > "/dev/stderr"; exit 1 } }
' "$readme"
for source in "$scratch"/cpp/block*.cpp; do
  name=$(basename "$source" .cpp)
  # What a block uses it includes itself (not through another header), e.g. hyst::Error.
  if grep -q 'hyst::Error' "$source" && ! grep -q '#include "hyst/core/error.hpp"' "$source"; then
    echo "FAIL: the README's C++ $name uses hyst::Error without #include \"hyst/core/error.hpp\""
    exit 1
  fi
  mkdir -p "$scratch/cpp/$name.project"
  cp "$source" "$scratch/cpp/$name.project/main.cpp"
  cat >"$scratch/cpp/$name.project/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project($name LANGUAGES CXX)
find_package(hyst REQUIRED COMPONENTS core)
add_executable($name main.cpp)
target_link_libraries($name PRIVATE hyst::core)
CMAKE
  if ! { cmake -S "$scratch/cpp/$name.project" -B "$scratch/cpp/$name.build" \
           -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_BUILD_TYPE=Release &&
         cmake --build "$scratch/cpp/$name.build"; } >"$scratch/cpp/$name.log" 2>&1; then
    echo "FAIL: the README's C++ block $name does not compile as written:"
    tail -n 40 "$scratch/cpp/$name.log"
    exit 1
  fi
  "$scratch/cpp/$name.build/$name" >"$scratch/cpp/$name.out" 2>&1 ||
    { cat "$scratch/cpp/$name.out"; echo "FAIL: the README's C++ block $name failed"; exit 1; }
  echo "README C++ $name: $(cat "$scratch/cpp/$name.out")"
done

# Every ```sh block but the set-up commands, each announced with its line in the README.
awk '
  /^```sh$/ { inside = 1; start = NR; text = ""; next }
  /^```$/ && inside {
    inside = 0
    if (text !~ /(^|\n)make (demo|test)/) {
      printf "echo \"== README.md line %d\" >&2\n%s", start, text
      ++blocks
    }
    next
  }
  inside { text = text $0 "\n" }
  END { if (blocks < 5) { print "only " blocks " command blocks found" > "/dev/stderr"; exit 1 } }
' "$readme" >"$scratch/blocks.sh"

if ! bash -euo pipefail "$scratch/blocks.sh" >"$scratch/stdout" 2>"$scratch/stderr"; then
  echo "FAIL: a README command failed; the last block and its output:"
  tail -n 40 "$scratch/stderr"
  exit 1
fi
if grep -q "error" "$scratch/stderr"; then
  echo "FAIL: a README command reported an error:"
  grep "error" "$scratch/stderr"
  exit 1
fi

# What the README says the commands write.
for file in m.json m10.json fit.txt v.csv y.csv v_back.csv ctrl/piezo.h ctrl/piezo.c loop.png \
  r.csv o.csv results/comparison.md p.csv p.json creep.json b.json strain.csv v_strain.csv \
  forc.json forc.txt cmp/ranking.md venv/bin/python fits/a250.json fits/batch.md; do
  [ -s "$file" ] || { echo "FAIL: the README's commands did not write $file"; exit 1; }
done
grep -q "NRMSE" fit.txt || { echo "FAIL: fit.txt has no NRMSE"; exit 1; }
echo "$(grep -c '^== README.md line' "$scratch/stderr") README command blocks ran"
