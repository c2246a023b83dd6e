#!/usr/bin/env bash
# Nothing is lost when writing output files (hyst/io/atomic_file.hpp), through `hyst simulate`:
#
#   killed        SIGKILL in the middle of writing a large output: the previous file under the
#                 final name is intact (byte for byte) and no partial file takes its name.
#   read_only     writing into a read-only folder: one clear error line, the old file intact.
#   repeatable    the same run twice (simulate; fit) gives the same bytes (the same parameters).
#   disk_full     a full disk (a 1 MB tmpfs when this process may mount one in a private mount
#                 namespace; otherwise the file-size limit RLIMIT_FSIZE with SIGXFSZ ignored,
#                 which makes write() fail part-way with EFBIG exactly like ENOSPC does): one
#                 clear error line, the old file intact, no temporary file left behind.
#
#     HYST=build/apps/hyst bash tests/cli/atomic_output.sh killed
#
# Exit status 0 = pass, 1 = fail, 77 = skipped.

set -u
source "$(dirname "${BASH_SOURCE[0]}")/test_support.sh" atomic

# input_csv FILE N: a column v of N samples of a slow sine.
input_csv() {
  awk -v n="$2" 'BEGIN { print "v"; for (i = 0; i < n; i++) printf "%.17g\n", sin(i * 1e-3) }' >"$1"
}

# expect_clean_error TEXT: the last run (stderr in err.txt, status in STATUS) failed with exit
# status 1 and one error line containing TEXT.
expect_clean_error() {
  [ "$STATUS" -eq 1 ] || fail "exit status $STATUS, expected 1: $(head -c 500 err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "expected one error line: $(head -c 500 err.txt)"
  grep -q '^hyst: error: ' err.txt || fail "not an error line: $(head -c 500 err.txt)"
  grep -qF -- "$1" err.txt || fail "error does not contain '$1': $(cat err.txt)"
  echo "error as expected: $(cat err.txt)"
}

# expect_old_intact FOLDER: FOLDER/out.csv is still the old file, and no temporary file is left.
expect_old_intact() {
  cmp -s "$1/out.csv" old.csv || fail "the previous $1/out.csv was changed"
  local left
  left="$(find "$1" -name '.out.csv.tmp.*' | wc -l)"
  [ "$left" -eq 0 ] || fail "$left temporary file(s) left in $1"
}

case_killed() {
  good_model m.json
  printf 'v,y\n1,2\n' >old.csv
  local samples=2000000
  for attempt in 1 2 3 4; do
    input_csv in.csv "$samples"
    rm -rf out && mkdir out && cp old.csv out/out.csv
    "$HYST" simulate --model m.json --input in.csv --out out/out.csv >/dev/null 2>err.txt &
    local pid=$! caught=0
    # Wait for the temporary file to appear and grow, then kill while it is being written.
    while kill -0 "$pid" 2>/dev/null; do
      local temporary
      temporary="$(find out -name '.out.csv.tmp.*' -size +1k 2>/dev/null | head -n 1)"
      if [ -n "$temporary" ]; then
        kill -KILL "$pid"
        caught=1
        break
      fi
      sleep 0.005
    done
    wait "$pid" 2>/dev/null
    if [ "$caught" -eq 1 ]; then
      cmp -s out/out.csv old.csv || fail "out/out.csv is not the previous file after SIGKILL"
      [ "$(find out -type f | wc -l)" -eq 2 ] || fail "unexpected files: $(ls -la out)"
      echo "killed during the write of $temporary ($(stat -c %s "$temporary") bytes written);" \
        "out/out.csv is the previous file; the partial content is only in the temporary file"
      return 0
    fi
    samples=$((samples * 2))  # the write finished before it could be caught: a larger one
  done
  fail "the write was never caught in progress"
}

case_read_only() {
  good_model m.json
  input_csv in.csv 100
  printf 'v,y\n1,2\n' >old.csv
  mkdir ro && cp old.csv ro/out.csv
  if [ "$(id -u)" -ne 0 ]; then
    chmod a-w ro
    "$HYST" simulate --model m.json --input in.csv --out ro/out.csv >/dev/null 2>err.txt
    STATUS=$?
    chmod u+w ro
  elif unshare -rm true 2>/dev/null; then
    # root ignores permission bits: a read-only bind mount in a private mount namespace.
    unshare -rm sh -c 'mount --bind ro ro && mount -o remount,bind,ro ro &&
      exec "$0" simulate --model m.json --input in.csv --out ro/out.csv' "$HYST" \
      >/dev/null 2>err.txt
    STATUS=$?
  else
    echo "skipped: running as root without permission to mount"
    exit 77
  fi
  expect_clean_error "cannot write 'ro/out.csv'"
  expect_old_intact ro
}

case_disk_full() {
  good_model m.json
  input_csv in.csv 200000  # about 8 MB of output
  printf 'v,y\n1,2\n' >old.csv
  mkdir small && cp old.csv small/out.csv
  if unshare -rm sh -c 'mount -t tmpfs -o size=1m tmpfs small' 2>/dev/null; then
    unshare -rm sh -c 'mount -t tmpfs -o size=1m tmpfs small && cp old.csv small/out.csv &&
      "$0" simulate --model m.json --input in.csv --out small/out.csv >/dev/null 2>err.txt;
      status=$?; cmp -s small/out.csv old.csv || exit 90;
      [ -z "$(find small -name ".out.csv.tmp.*")" ] || exit 91; exit $status' "$HYST"
    STATUS=$?
    [ "$STATUS" -eq 90 ] && fail "the previous small/out.csv was changed on the full tmpfs"
    [ "$STATUS" -eq 91 ] && fail "a temporary file was left on the full tmpfs"
    expect_clean_error "No space left on device"
    echo "(a real full disk: 1 MB tmpfs)"
  else
    (trap '' XFSZ && ulimit -f 1024 &&
      exec "$HYST" simulate --model m.json --input in.csv --out small/out.csv >/dev/null 2>err.txt)
    STATUS=$?
    expect_clean_error "File too large"
    expect_old_intact small
    echo "(simulated: RLIMIT_FSIZE 1 MB)"
  fi
  grep -qF "small/out.csv" err.txt || fail "the error does not name the file"
}

case_repeatable() {
  good_model m.json
  input_csv in.csv 5000
  "$HYST" simulate --model m.json --input in.csv --out a.csv >/dev/null || fail "simulate failed"
  "$HYST" simulate --model m.json --input in.csv --out b.csv >/dev/null || fail "simulate failed"
  cmp -s a.csv b.csv || fail "two runs of simulate wrote different files"
  awk -F, 'NR > 1 { print $1 "," $2 * 0.9 + 0.1 * ($2 > 0) }' a.csv | sed '1i v,y' >data.csv
  "$HYST" fit pi --data data.csv --input v --output y --out f1.json >/dev/null || fail "fit failed"
  "$HYST" fit pi --data data.csv --input v --output y --out f2.json >/dev/null || fail "fit failed"
  # The files differ in the fit report's wall time only: compare parameters and state.
  /usr/bin/python3 -c 'import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
sys.exit(0 if (a["params"], a["state"]) == (b["params"], b["state"]) else 1)' f1.json f2.json ||
    fail "two fits of the same data gave different parameters"
  echo "simulate: identical files; fit: identical parameters and state"
}

case "${1:-}" in
  killed) case_killed ;;
  repeatable) case_repeatable ;;
  read_only) case_read_only ;;
  disk_full) case_disk_full ;;
  *) fail "unknown case '${1:-}' (killed, read_only, disk_full, repeatable)" ;;
esac
