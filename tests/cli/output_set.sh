#!/usr/bin/env bash
# Several outputs of one run are published as a whole (hyst/io/output_set.hpp):
#
#   published        hyst compare: every name in --out-dir reads the new file through the set's
#                    link; a run with fewer outputs (--no-plots) drops the other names; one set
#                    folder is left, no temporary file; other files in the folder are untouched.
#   old_plain_files  plain files of an older hyst under the names become links of the set.
#   killed           hyst compare SIGKILLed at several points (at fractions of a whole run, and
#                    while gnuplot draws): the folder holds the complete old set or the complete
#                    new one, never a mix; no temporary file outside the set folders, none in
#                    TMPDIR; no gnuplot process is left; the next run cleans up.
#   actuator_killed  the same for hyst actuator compare --out-dir.
#
#     HYST=build/apps/hyst bash tests/cli/output_set.sh killed
#
# Exit status 0 = pass, 1 = fail, 77 = skipped.

set -u
source "$(dirname "${BASH_SOURCE[0]}")/test_support.sh" set
mkdir tmp
# Temporary files of hyst (and gnuplot) would land here; the marker finds our gnuplot processes.
export TMPDIR="$WORK/tmp" HYST_SET_TEST_MARK="$WORK"

command -v gnuplot >/dev/null || {
  echo "SKIP: gnuplot is not installed"
  exit 77
}

# record FILE AMPLITUDE: v (a sine growing to AMPLITUDE) and y, the PI model's output.
record() {
  awk -v a="$2" 'BEGIN { print "v"; for (i = 0; i < 1000; i++) printf "%.17g\n", a * (i / 1000) * sin(i * 0.05) }' >in.csv
  "$HYST" simulate --model m.json --input in.csv --out "$1" >/dev/null || fail "making $1"
}

NAMES="ranking.md ranking.csv loops.png errors.png report.html"

# compare_cmd DATA: the compare command line (for eval).
compare_cmd() {
  echo "\"$HYST\" compare --data $1 --input v --output y --models pi,gpi --out-dir cmp --html cmp/report.html"
}

# sums FOLDER NAMES...: one checksum (or "missing") per name, through the links.
sums() {
  local folder=$1 name
  shift
  for name in "$@"; do
    if [ -f "$folder/$name" ]; then md5sum <"$folder/$name" | cut -c1-32; else echo missing; fi
  done
}

# our_gnuplots: gnuplot processes started by a hyst of this test (by the marker in their environment).
our_gnuplots() {
  local pid
  for pid in $(pgrep -x gnuplot); do
    tr '\0' '\n' 2>/dev/null <"/proc/$pid/environ" | grep -qx "HYST_SET_TEST_MARK=$WORK" && echo "$pid"
  done
}

# no_leftovers FOLDER: no gnuplot of ours (after at most 2 s), no temporary file outside the set
# folders, nothing in TMPDIR.
no_leftovers() {
  local tries=0
  while [ -n "$(our_gnuplots)" ]; do
    tries=$((tries + 1))
    [ "$tries" -lt 40 ] || fail "gnuplot still runs after hyst was killed: $(our_gnuplots)"
    sleep 0.05
  done
  local stray
  stray="$(find "$1" -name '*.tmp*' -not -path "$1/.hyst-set.*")"
  [ -z "$stray" ] || fail "temporary files outside the set folders: $stray"
  [ -z "$(ls -A tmp)" ] || fail "files left in TMPDIR: $(ls -A tmp)"
}

# check_set FOLDER OLD NEW_STATE_VAR NAMES...: the folder holds the old set (checksums OLD) or a
# complete new one (every name present and different from the old); sets STATE to old or new.
check_set() {
  local folder=$1 old=$2
  shift 2
  local now
  now="$(sums "$folder" "$@" | tr '\n' ' ')"
  if [ "$now" = "$old" ]; then
    STATE=old
    return
  fi
  local k=0 name
  local -a old_list now_list
  read -r -a old_list <<<"$old"
  read -r -a now_list <<<"$now"
  for name in "$@"; do
    [ "${now_list[$k]}" != missing ] || fail "a mixed set: $name is missing: $(ls -la "$folder")"
    [ "${now_list[$k]}" != "${old_list[$k]}" ] ||
      fail "a mixed set: $name is the old file while others are new"
    k=$((k + 1))
  done
  STATE=new
}

case_published() {
  good_model m.json
  record a.csv 1
  mkdir cmp
  printf 'mine\n' >cmp/notes.txt
  eval "$(compare_cmd a.csv)" >/dev/null 2>err.txt || fail "compare failed: $(cat err.txt)"
  local name
  for name in $NAMES; do
    [ -s "cmp/$name" ] || fail "cmp/$name is missing or empty"
    [ "$(readlink "cmp/$name")" = ".hyst-current/$name" ] || fail "cmp/$name is not a set link"
  done
  [ "$(find cmp -maxdepth 1 -name '.hyst-set.*' | wc -l)" -eq 1 ] || fail "not one set folder: $(ls -la cmp)"
  "$HYST" compare --data a.csv --input v --output y --models pi --out-dir cmp --no-plots >/dev/null ||
    fail "compare --no-plots failed"
  for name in loops.png errors.png report.html; do
    [ ! -e "cmp/$name" ] && [ ! -L "cmp/$name" ] || fail "cmp/$name of the old set is still there"
  done
  [ -s cmp/ranking.md ] || fail "no ranking.md"
  [ "$(find cmp -maxdepth 1 -name '.hyst-set.*' | wc -l)" -eq 1 ] || fail "not one set folder: $(ls -la cmp)"
  [ "$(cat cmp/notes.txt)" = mine ] || fail "another file of the folder was touched"
  no_leftovers cmp
}

case_old_plain_files() {
  good_model m.json
  record a.csv 1
  mkdir cmp
  local name
  for name in $NAMES; do printf 'old %s\n' "$name" >"cmp/$name"; done
  eval "$(compare_cmd a.csv)" >/dev/null 2>err.txt || fail "compare failed: $(cat err.txt)"
  for name in $NAMES; do
    [ -L "cmp/$name" ] || fail "cmp/$name is still a plain file"
    grep -q '^old' "cmp/$name" && fail "cmp/$name still has the old content"
  done
  [ "$(find cmp -maxdepth 1 -name '.hyst-set.*' | wc -l)" -eq 1 ] || fail "not one set folder: $(ls -la cmp)"
  # A name that is a link elsewhere is not replaced: refused before any work.
  rm cmp/ranking.csv
  ln -s ../a.csv cmp/ranking.csv
  cp a.csv a.csv.orig
  eval "$(compare_cmd m.json)" >/dev/null 2>err.txt && fail "compare replaced a link elsewhere"
  grep -q "same file as the input\|link elsewhere" err.txt || fail "unexpected message: $(cat err.txt)"
  cmp -s a.csv a.csv.orig || fail "the link's target was changed"
}

# kill_runs FOLDER NAMES CMD_A CMD_B STEPS: run CMD_A once (the old set), then start the other run
# and SIGKILL it after each of STEPS tenths of a whole run, and while gnuplot draws ("gnuplot");
# check after every kill.
kill_runs() {
  local folder=$1 names=$2 cmd_a=$3 cmd_b=$4 steps=$5
  local start end
  start=$(date +%s%N)
  eval "$cmd_a" >/dev/null 2>err.txt || fail "the first run failed: $(cat err.txt)"
  end=$(date +%s%N)
  local whole=$(((end - start) / 1000000))
  echo "a whole run takes ${whole} ms"
  local old
  # shellcheck disable=SC2086
  old="$(sums "$folder" $names | tr '\n' ' ')"
  local current=a olds=0 news=0 gnuplot_kills=0 step
  for step in $steps; do
    local next=b cmd=$cmd_b
    [ "$current" = b ] && next=a cmd=$cmd_a
    # exec: the background job is hyst itself, so that the kill reaches it.
    eval "exec $cmd" >/dev/null 2>&1 &
    local pid=$!
    if [ "$step" = gnuplot ]; then
      # Killed as soon as a gnuplot child is seen (a second look could miss a short plot).
      local waited=0
      while kill -0 "$pid" 2>/dev/null && [ "$waited" -lt 4000 ]; do
        if pgrep -x -P "$pid" gnuplot >/dev/null; then
          gnuplot_kills=$((gnuplot_kills + 1))
          break
        fi
        sleep 0.002
        waited=$((waited + 2))
      done
    else
      sleep "$(awk -v w="$whole" -v k="$step" 'BEGIN { printf "%.3f", w * k / 10000 }')"
    fi
    kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    # shellcheck disable=SC2086
    check_set "$folder" "$old" $names
    no_leftovers "$folder"
    echo "killed at step $step: the $STATE set"
    if [ "$STATE" = new ]; then
      news=$((news + 1))
      current=$next
      # shellcheck disable=SC2086
      old="$(sums "$folder" $names | tr '\n' ' ')"
    else
      olds=$((olds + 1))
    fi
  done
  [ "$olds" -gt 0 ] || fail "no kill fell inside a run"
  [ "$gnuplot_kills" -gt 0 ] || fail "no kill while gnuplot was drawing"
  # The next whole run publishes and removes what the killed runs left.
  eval "$cmd_b" >/dev/null 2>err.txt || fail "the last run failed: $(cat err.txt)"
  [ "$(find "$folder" -maxdepth 1 -name '.hyst-set.*' | wc -l)" -eq 1 ] ||
    fail "set folders of killed runs are left: $(ls -la "$folder")"
  [ -z "$(find "$folder" -name '*.tmp*')" ] || fail "temporary files left"
  echo "$olds kills found the old set, $news the new one"
}

case_killed() {
  good_model m.json
  record a.csv 1
  record b.csv 0.7
  mkdir cmp
  kill_runs cmp "$NAMES" "$(compare_cmd a.csv)" "$(compare_cmd b.csv)" \
    "1 2 3 4 5 6 7 8 9 10 12 15 gnuplot gnuplot"
}

case_actuator_killed() {
  local config="${HYST_EXAMPLE_CONFIG_DIR:?set HYST_EXAMPLE_CONFIG_DIR}/msma_assumed.json"
  [ -f "$config" ] || fail "no $config"
  # Two configurations that differ (the sensor noise seed), so every output differs.
  /usr/bin/python3 - "$config" <<'PY' || fail "making the configurations"
import json, sys
config = json.load(open(sys.argv[1]))
text = json.dumps(config)
open("a.json", "w").write(text)
def change(node):
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "seed" and isinstance(value, int):
                node[key] = value + 1
            else:
                change(value)
    elif isinstance(node, list):
        for value in node:
            change(value)
change(config)
open("b.json", "w").write(json.dumps(config))
PY
  cmp -s a.json b.json && {
    echo "SKIP: the configuration has no seed to vary"
    exit 77
  }
  mkdir out
  "$HYST" actuator compare --config a.json --out-dir out >/dev/null 2>err.txt ||
    fail "actuator compare failed: $(cat err.txt)"
  local names
  names="$(cd out && ls | tr '\n' ' ')"
  kill_runs out "$names" "\"$HYST\" actuator compare --config a.json --out-dir out" \
    "\"$HYST\" actuator compare --config b.json --out-dir out" "4 8 gnuplot"
}

case_name="${1:?usage: output_set.sh published|old_plain_files|killed|actuator_killed}"
"case_$case_name"
echo "PASS: $case_name"
