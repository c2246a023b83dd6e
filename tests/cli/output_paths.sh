#!/usr/bin/env bash
# An output never replaces what it must not (hyst/io/output_paths.hpp), through the command line:
#
#   device       as root: --out naming a character device made with mknod in a temporary folder
#                (never the system's /dev) is written through; the node stays a device. A full
#                device (like /dev/full) gives one error line.
#   fifo         --out naming a FIFO is written through (a reader gets the CSV); it stays a FIFO.
#   symlink      --out naming a link: the target is replaced, the link kept (also a dangling one).
#   hard_link    --out a hard link of the input: refused before any work, naming both paths.
#   same_file    for every command, an output equal to one of its inputs, and two equal outputs
#                (--report = --out), are refused with one error line naming both; inputs intact.
#   not_a_file   --out naming a folder or a socket is refused.
#   stdout       '-' writes a text output to standard output (messages go to standard error);
#                refused for an image; compare --html - prints the page.
#
#     HYST=build/apps/hyst bash tests/cli/output_paths.sh device
#
# Exit status 0 = pass, 1 = fail, 77 = skipped.

set -u
source "$(dirname "${BASH_SOURCE[0]}")/test_support.sh" outputs

# A column v of 400 samples of a sine with growing amplitude (loops to fit).
input_csv() {
  awk 'BEGIN { print "v"; for (i = 0; i < 400; i++) printf "%.17g\n", (i / 400) * sin(i * 0.1) }' >"$1"
}

# run CMD...: status in STATUS, standard output in out.txt, standard error in err.txt.
run() {
  "$@" >out.txt 2>err.txt
  STATUS=$?
}

expect_ok() {
  run "$@"
  [ "$STATUS" -eq 0 ] || fail "'$*' failed ($STATUS): $(head -c 500 err.txt)"
}

# expect_refused TEXT... -- CMD...: exit status 1, one error line containing every TEXT.
expect_refused() {
  local texts=()
  while [ "$1" != "--" ]; do
    texts+=("$1")
    shift
  done
  shift
  run "$@"
  [ "$STATUS" -eq 1 ] || fail "'$*': exit status $STATUS, expected 1: $(head -c 500 err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*': expected one error line: $(head -c 500 err.txt)"
  grep -q '^hyst: error: ' err.txt || fail "not an error line: $(cat err.txt)"
  local text
  for text in "${texts[@]}"; do
    grep -qF -- "$text" err.txt || fail "'$*': error does not contain '$text': $(cat err.txt)"
  done
  echo "refused as expected: $(cat err.txt)"
}

# unchanged FILE: FILE still has the content saved in FILE.orig.
unchanged() {
  cmp -s "$1" "$1.orig" || fail "$1 was changed"
}

setup() {
  good_model m.json
  input_csv in.csv
  "$HYST" simulate --model m.json --input in.csv --out data.csv >/dev/null || fail "setup"
  local file
  for file in m.json in.csv data.csv; do cp "$file" "$file.orig"; done
}

case_device() {
  [ "$(id -u)" -eq 0 ] || {
    echo "SKIP: mknod needs root"
    exit 77
  }
  setup
  mknod nul c 1 3 || {
    echo "SKIP: mknod failed (no device nodes on this file system?)"
    exit 77
  }
  expect_ok "$HYST" simulate --model m.json --input in.csv --out nul
  [ -c nul ] || fail "the device node nul was replaced: $(ls -l nul)"
  expect_ok "$HYST" fit pi --data data.csv --input v --output y --out nul --report m.txt
  [ -c nul ] || fail "fit replaced the device node"
  expect_ok "$HYST" plot --data data.csv --x v --y y --kind loop --out nul
  [ -c nul ] || fail "plot replaced the device node"
  expect_ok "$HYST" data extract data.csv --columns v --out nul
  [ -c nul ] || fail "data extract replaced the device node"
  expect_ok "$HYST" invert --model m.json --target data.csv --column y --out nul
  [ -c nul ] || fail "invert replaced the device node"
  mkdir cmp
  expect_ok "$HYST" compare --data data.csv --input v --output y --models pi --out-dir cmp \
    --no-plots --html nul
  [ -c nul ] || fail "compare --html replaced the device node"
  # Inside a set folder a device is refused: the names of a set are links hyst manages.
  rm -f cmp/ranking.csv
  mknod cmp/ranking.csv c 1 3 || fail "mknod cmp/ranking.csv"
  expect_refused "cmp/ranking.csv': it is not a regular file" -- \
    "$HYST" compare --data data.csv --input v --output y --models pi --out-dir cmp --no-plots
  [ -c cmp/ranking.csv ] || fail "compare replaced the device node in its folder"
  [ "$(find . -name '.nul*' | wc -l)" -eq 0 ] || fail "temporary files left: $(ls -la)"
  # A device that refuses the data (like /dev/full): one error line, the node kept.
  mknod full c 1 7 || fail "mknod full"
  expect_refused "cannot write 'full': No space left on device (writing)" -- \
    "$HYST" simulate --model m.json --input in.csv --out full
  [ -c full ] || fail "the device node full was replaced"
}

case_fifo() {
  setup
  mkfifo pipe
  cat pipe >got.csv &
  local reader=$!
  run "$HYST" simulate --model m.json --input in.csv --out pipe
  if [ ! -p pipe ]; then
    kill "$reader" 2>/dev/null
    fail "the FIFO was replaced: $(ls -l pipe)"
  fi
  [ "$STATUS" -eq 0 ] || fail "writing into the FIFO failed: $(cat err.txt)"
  wait "$reader"
  head -n 1 got.csv | grep -qx 'v,y' || fail "the reader got no CSV: $(head -c 200 got.csv)"
  [ "$(wc -l <got.csv)" -eq 401 ] || fail "the reader got $(wc -l <got.csv) lines, expected 401"
}

case_symlink() {
  setup
  mkdir -p real
  printf 'old\n' >real/target.csv
  ln -s real/target.csv link.csv
  expect_ok "$HYST" simulate --model m.json --input in.csv --out link.csv
  [ -L link.csv ] || fail "the link was replaced by a file"
  [ "$(readlink link.csv)" = real/target.csv ] || fail "the link changed: $(readlink link.csv)"
  head -n 1 real/target.csv | grep -qx 'v,y' || fail "the target was not written"
  [ "$(find . -name '*.tmp.*' | wc -l)" -eq 0 ] || fail "temporary files left"
  # A dangling link: its target is created, the link kept.
  ln -s real/new.json model_link.json
  expect_ok "$HYST" fit pi --data data.csv --input v --output y --out model_link.json
  [ -L model_link.json ] && [ -s real/new.json ] || fail "dangling link: $(ls -l . real)"
  # A link to a link to the input is still the input.
  ln -s data.csv data_link.csv
  ln -s data_link.csv data_link2.csv
  expect_refused "--out 'data_link2.csv' is the same file as the input --data 'data.csv'" -- \
    "$HYST" fit pi --data data.csv --input v --output y --out data_link2.csv
  unchanged data.csv
}

case_hard_link() {
  setup
  ln in.csv alias.csv
  expect_refused "--out 'alias.csv'" "--input 'in.csv'" "same file" -- \
    "$HYST" simulate --model m.json --input in.csv --out alias.csv
  unchanged in.csv
  ln data.csv data_alias.csv
  expect_refused "--report 'data_alias.csv'" "--data 'data.csv'" -- \
    "$HYST" fit pi --data data.csv --input v --output y --out m2.json --report data_alias.csv
  unchanged data.csv
  [ ! -e m2.json ] || fail "fit wrote m2.json although it was refused"
}

case_same_file() {
  setup
  expect_refused "--out 'in.csv' is the same file as the input --input 'in.csv'" -- \
    "$HYST" simulate --model m.json --input in.csv --out in.csv
  expect_refused "--out 'm.json' is the same file as the input --model 'm.json'" -- \
    "$HYST" simulate --model m.json --input in.csv --out m.json
  expect_refused "--out 'data.csv' is the same file as the input --data 'data.csv'" -- \
    "$HYST" fit pi --data data.csv --input v --output y --out data.csv
  expect_refused "--report './data.csv' is the same file as the input --data 'data.csv'" -- \
    "$HYST" fit pi --data data.csv --input v --output y --out m2.json --report ./data.csv
  expect_refused "--out 'r.txt' and --report 'r.txt' are the same file" -- \
    "$HYST" fit pi --data data.csv --input v --output y --out r.txt --report r.txt
  expect_refused "--out 'x/../r.txt' and --report 'r.txt' are the same file" -- \
    bash -c "mkdir -p x && \"$HYST\" fit pi --data data.csv --input v --output y --out x/../r.txt --report r.txt"
  expect_refused "--out 'in.csv' is the same file as the input --target 'in.csv'" -- \
    "$HYST" invert --model m.json --target in.csv --column v --out in.csv
  expect_refused "--out 'data.csv' is the same file as the input --data 'data.csv'" -- \
    "$HYST" plot --data data.csv --x v --y y --out data.csv
  expect_refused "--out 'm.json' is the same file as the input --model 'm.json'" -- \
    "$HYST" plot --data data.csv --x v --y y --kind loop --model m.json --out m.json
  expect_refused "--out 'data.csv' is the same file as the input FILE 'data.csv'" -- \
    "$HYST" data extract data.csv --columns v --out data.csv
  mkdir -p ctrl
  cp m.json ctrl/p.h
  cp m.json ctrl/p.h.orig
  expect_refused "--out 'ctrl/p.h' is the same file as the input --model 'ctrl/p.h'" -- \
    "$HYST" export --model ctrl/p.h --out ctrl --prefix p
  unchanged ctrl/p.h
  mkdir -p cmp
  cp data.csv cmp/ranking.csv
  expect_refused "--out-dir 'cmp/ranking.csv' is the same file as the input --data 'cmp/ranking.csv'" -- \
    "$HYST" compare --data cmp/ranking.csv --input v --output y --models pi --out-dir cmp
  expect_refused "--html 'data.csv' is the same file as the input --data 'data.csv'" -- \
    "$HYST" compare --data data.csv --input v --output y --models pi --out-dir cmp --html data.csv
  expect_refused "--out-dir 'cmp/loops.png' and --html 'cmp/loops.png' are the same file" -- \
    "$HYST" compare --data data.csv --input v --output y --models pi --out-dir cmp \
    --html cmp/loops.png
  printf 'reference\n0\n1e-6\n' >ref.csv
  cp ref.csv ref.csv.orig
  expect_refused "--out 'ref.csv' is the same file as the input --reference 'ref.csv'" -- \
    "$HYST" actuator simulate --config "${HYST_EXAMPLE_CONFIG_DIR:-/nonexistent}/msma_assumed.json" \
    --reference ref.csv --out ref.csv
  for file in m.json in.csv data.csv ref.csv; do unchanged "$file"; done
  [ "$(find . -name '.*.tmp.*' | wc -l)" -eq 0 ] || fail "temporary files left"
}

case_not_a_file() {
  setup
  mkdir folder
  expect_refused "--out 'folder': it is a folder, not a file" -- \
    "$HYST" simulate --model m.json --input in.csv --out folder
  /usr/bin/python3 -c 'import socket; socket.socket(socket.AF_UNIX).bind("sock")' ||
    fail "cannot make a socket"
  expect_refused "--out 'sock': it is a socket" -- \
    "$HYST" simulate --model m.json --input in.csv --out sock
  [ -S sock ] || fail "the socket was replaced"
  printf 'x\n' >plain
  expect_refused "--out 'plain/o.csv': 'plain' is not a folder" -- \
    "$HYST" simulate --model m.json --input in.csv --out plain/o.csv
  expect_ok "$HYST" simulate --model m.json --input in.csv --out new/sub/o.csv
  [ -s new/sub/o.csv ] || fail "no output in the created folder new/sub"
}

case_stdout() {
  setup
  expect_ok "$HYST" simulate --model m.json --input in.csv --out -
  head -n 1 out.txt | grep -qx 'v,y' || fail "no CSV on standard output: $(head -c 200 out.txt)"
  [ "$(wc -l <out.txt)" -eq 401 ] || fail "standard output has more than the CSV"
  grep -q '^wrote -' err.txt || fail "the message did not go to standard error: $(cat err.txt)"
  [ ! -e ./- ] || fail "a file named '-' was written"
  expect_ok "$HYST" data extract data.csv --columns y --out -
  head -n 1 out.txt | grep -qx 'y' || fail "data extract: no CSV on standard output"
  expect_ok "$HYST" fit pi --data data.csv --input v --output y --out - --report r.txt
  /usr/bin/python3 -c 'import json,sys; assert json.load(open("out.txt"))["model"] == "pi"' ||
    fail "fit --out -: standard output is not the model file: $(head -c 300 out.txt)"
  expect_refused "--out '-' and --report '-' are the same file" -- \
    "$HYST" fit pi --data data.csv --input v --output y --out - --report -
  expect_refused "--out '-': standard output is for text outputs only" -- \
    "$HYST" plot --data data.csv --x v --y y --out -
  if command -v gnuplot >/dev/null; then
    mkdir cmp
    expect_ok "$HYST" compare --data data.csv --input v --output y --models pi --out-dir cmp \
      --no-plots --html -
    head -n 1 out.txt | grep -qx '<!DOCTYPE html>' || fail "compare --html -: no page: $(head -c 200 out.txt)"
    grep -q '| 1 | pi |' err.txt || fail "compare --html -: the table did not go to standard error"
    [ -s cmp/ranking.csv ] || fail "compare --html -: no ranking.csv"
  fi
  [ ! -e ./- ] || fail "a file named '-' was written"
}

case_name="${1:?usage: output_paths.sh device|fifo|symlink|hard_link|same_file|not_a_file|stdout}"
"case_$case_name"
echo "PASS: $case_name"
