#!/usr/bin/env bash
# Every bad input the command line may meet, through `hyst`: the committed corpus
# tests/data/bad/ (what each file is run through, and what its error must name, is listed in
# tests/data/bad/expected.tsv), larger or binary files generated here, and bad variants of every
# registered model's example file (tests/cli/mutate_model_file.py; models added to the registry
# are covered without changes here).
#
#     HYST=build/apps/hyst bash tests/cli/bad_input_corpus.sh tests/data/bad
#
# Each run is bounded (timeout 10 s) and must end with exit status 1 or 2 and exactly one line on
# standard error, "hyst: error: ...", naming the file and the place (line, column, field). A
# crash, a sanitizer report, a hang or a second line fails the test.

set -u
: "${HYST:?set HYST to the hyst executable}"
HYST="$(cd "$(dirname "$HYST")" && pwd)/$(basename "$HYST")"
BAD="$(cd "${1:?usage: bad_input_corpus.sh BAD_FOLDER}" && pwd)"
HERE="$(cd "$(dirname "$0")" && pwd)"
PYTHON="${PYTHON:-/usr/bin/python3}"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/hyst-bad-inputs.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

TRIED=0
FAILURES=0

# check_error FILE TEXT CMD...: CMD must fail cleanly with one error line naming FILE and TEXT.
check_error() {
  local file="$1" text="$2"
  shift 2
  TRIED=$((TRIED + 1))
  timeout 10 "$@" >"$WORK/stdout" 2>"$WORK/stderr"
  local status=$? lines
  lines="$(wc -l <"$WORK/stderr")"
  local problem=""
  if [ "$status" -eq 124 ]; then
    problem="did not finish within 10 s"
  elif [ "$status" -ne 1 ] && [ "$status" -ne 2 ]; then
    problem="exit status $status (expected 1 or 2)"
  elif [ "$lines" -ne 1 ]; then
    problem="$lines lines on standard error (expected 1)"
  elif ! grep -q '^hyst: error: ' "$WORK/stderr"; then
    problem="standard error does not start with 'hyst: error: '"
  elif ! grep -qF -- "$(basename "$file")" "$WORK/stderr"; then
    problem="the error does not name the file '$(basename "$file")'"
  elif ! grep -qF -- "$text" "$WORK/stderr"; then
    problem="the error does not contain '$text'"
  fi
  if [ -n "$problem" ]; then
    FAILURES=$((FAILURES + 1))
    echo "FAIL: $file: $problem" >&2
    echo "  command: $*" >&2
    echo "  stderr: $(head -c 1000 "$WORK/stderr")" >&2
  else
    printf '%-45s %s\n' "$(basename "$file")" "$(cut -c1-150 "$WORK/stderr")"
  fi
}

# check FILE HOW TEXT: runs FILE the way HOW says (see tests/data/bad/expected.tsv).
check() {
  local file="$1" how="$2" text="$3"
  case "$how" in
    data) check_error "$file" "$text" "$HYST" simulate --model good.json --input "$file" \
            --column v --out out.csv ;;
    fit) check_error "$file" "$text" "$HYST" fit pi --data "$file" --input v --output y \
           --out fitted.json ;;
    model) check_error "$file" "$text" "$HYST" simulate --model "$file" --input good.csv \
             --column v --out out.csv ;;
    *) echo "FAIL: unknown way '$how' for $file" >&2; FAILURES=$((FAILURES + 1)) ;;
  esac
}

# Valid companions: a model file and an input file.
"$HYST" models pi --json >pi_schema.json || exit 1
"$PYTHON" -c 'import json,sys; json.dump(json.load(open(sys.argv[1]))["example"], open(sys.argv[2], "w"))' \
  pi_schema.json good.json || exit 1
printf 'v,y\n0,0\n0.5,0.4\n1,0.9\n0.2,0.5\n' >good.csv

# 1. The committed corpus.
listed=0
while IFS=$'\t' read -r name how text; do
  case "$name" in '' | '#'*) continue ;; esac
  [ -e "$BAD/$name" ] || { echo "FAIL: $name is listed but missing" >&2; FAILURES=$((FAILURES + 1)); }
  listed=$((listed + 1))
  check "$BAD/$name" "$how" "$text"
done <"$BAD/expected.tsv"
for file in "$BAD"/*; do
  [ "$(basename "$file")" = expected.tsv ] && continue
  grep -q "^$(basename "$file")	" "$BAD/expected.tsv" ||
    { echo "FAIL: $file is not listed in expected.tsv" >&2; FAILURES=$((FAILURES + 1)); }
done

# 2. Generated files: binary noise (fixed seed), a long file with a bad last line, a single
# huge field, a header of 300001 columns with a repeated name, a cut MAT file.
awk 'BEGIN { srand(13); for (i = 0; i < 4096; i++) printf "%c", int(rand() * 256) }' </dev/null >noise.bin
cp noise.bin binary.csv
cp noise.bin binary.json
cp noise.bin binary.mat
check binary.csv data "binary.csv"
check binary.json model "binary.json"
check binary.mat data "not a MAT file"
awk 'BEGIN { print "v,y"; for (i = 0; i < 1000000; i++) print i % 7 "," i % 5; print "3,nan" }' >long.csv
check long.csv data "long.csv:1000002"
awk 'BEGIN { printf "v,y\n"; for (i = 0; i < 1000000; i++) printf "9999999999"; printf ",1\n" }' >huge_field.csv
check huge_field.csv data "huge_field.csv:2"
awk 'BEGIN { for (i = 0; i < 300000; i++) printf "c%d,", i; print "c0"; print "1" }' >wide.csv
check wide.csv data "wide.csv:1: column 300001 ('c0') has the same name as column 1"
head -c 150 "$BAD/mismatched_lengths.mat" >cut.mat
check cut.mat data "cut.mat"

# 2b. Limits (include/hyst/io/limits.hpp): JSON nesting through every JSON entry point (a model
# file's "info" 100 000 levels deep used to overflow the stack of `hyst info`), duplicate keys,
# an endless stream, a MAT variable inflating far beyond its file, resampling steps whose sample
# count overflows an integer.
"$PYTHON" - <<'PY' || exit 1
import json
good = json.load(open("good.json"))
text = json.dumps(good)
open("deep_info_100000.json", "w").write(
    text[:-1] + ', "info": ' + '{"a": ' * 100000 + "1" + "}" * 100000 + "}")
PY
check_error deep_info_100000.json "deep_info_100000.json:1:" "$HYST" info deep_info_100000.json
check_error deep_info_100000.json "JSON nesting deeper than 256 levels" "$HYST" info --json \
  deep_info_100000.json
awk 'BEGIN { print "v,y"; for (i = 0; i < 400; i++) print sin(i / 20) "," 0.8 * sin(i / 20) }' >sine.csv
check_error options "--options:1:257: JSON nesting deeper than 256 levels" "$HYST" fit pi \
  --data sine.csv --input v --output y --out fitted.json \
  --options "$(printf '%0.s[' $(seq 300))"
check_error options "--options:1:18: duplicate key 'operators'" "$HYST" fit pi --data sine.csv \
  --input v --output y --out fitted.json --options '{"operators": 5, "operators": 6}'
check_error option "--option 'pi.operators=" "$HYST" compare --data sine.csv --input v \
  --output y --out-dir . --models pi --option "pi.operators=$(printf '%0.s[' $(seq 300))"
CONFIG="$HERE/../../examples/config/msma_assumed.json"
"$PYTHON" - "$CONFIG" <<'PY' || exit 1
import sys
text = open(sys.argv[1]).read()
brace = text.index("{")
open("config_duplicate.json", "w").write(text[:brace + 1] + '"x": 1, "x": 2, ' + text[brace + 1:])
open("config_deep.json", "w").write(
    text[:brace + 1] + '"x": ' + "[" * 1000 + "]" * 1000 + ", " + text[brace + 1:])
open("config_lead_in.json", "w").write(text.replace('"lead_in": 0.05', '"lead_in": 1e300'))
PY
printf 't,r\n0,0\n0.001,0.1\n' >reference.csv
check_error config_duplicate.json "config_duplicate.json:1:10: duplicate key 'x'" "$HYST" \
  actuator simulate --config config_duplicate.json --reference reference.csv --out out.csv
check_error config_deep.json "JSON nesting deeper than 256 levels" "$HYST" actuator simulate \
  --config config_deep.json --reference reference.csv --out out.csv
mkdir -p compare_out
check_error config_lead_in.json "scenarios.lead_in = 1e+300 s is" "$HYST" actuator compare \
  --config config_lead_in.json --out-dir compare_out --no-plots
# An endless stream: a FIFO fed from /dev/zero stops at the 256 MiB input limit.
mkfifo endless.csv
timeout 20 sh -c 'cat /dev/zero >endless.csv' 2>/dev/null &
check_error endless.csv "holds more than 268435456 bytes, the limit of one input" "$HYST" \
  simulate --model good.json --input endless.csv --column v --out out.csv
wait
# A 0.77 MB v5 file whose compressed variable inflates to 800 MB (100 million zeros; made in
# about 3 s).
"$PYTHON" - <<'PY' || exit 1
import struct, zlib
n = 100_000_000
body = (struct.pack("<II", 6, 8) + struct.pack("<II", 6, 0)           # array flags: double
        + struct.pack("<II", 5, 8) + struct.pack("<ii", 1, n)          # dimensions 1 x n
        + struct.pack("<HH", 1, 1) + b"v\0\0\0"                       # name 'v' (small element)
        + struct.pack("<II", 9, 8 * n))                                # the doubles follow
matrix = struct.pack("<II", 14, len(body) + 8 * n) + body
packer = zlib.compressobj(9)
compressed = packer.compress(matrix)
zeros = bytes(1 << 23)
for _ in range(8 * n // len(zeros)):
    compressed += packer.compress(zeros)
compressed += packer.flush()
header = b"MATLAB 5.0 MAT-file, inflating".ljust(116, b" ") + bytes(8) + struct.pack("<H", 0x0100) + b"IM"
open("inflating.mat", "wb").write(header + struct.pack("<II", 15, len(compressed)) + compressed)
PY
check_error inflating.mat "inflates to more than" "$HYST" simulate --model good.json \
  --input inflating.mat --column v --out out.csv
for step in input-grid:1e-6 input-grid:1e-17 arc-length:1e-300; do
  check_error sine.csv "--resample $step): " "$HYST" fit pi --data sine.csv --input v \
    --output y --out fitted.json --resample "$step"
done

# 2c. Counts a user gives to the dynamic models (fit-system, evaluate, fit --tables), each
# bounded before it costs anything, and their messages.
awk 'BEGIN { print "u,y"; for (k = 0; k < 128; k++) { u = sin(k * 0.3); print u "," 0.5 * u } }' >lag.csv
LAG="--data lag.csv --input u --output y --samples-per-period 64"
for order in 101 500 1500; do
  check_error order "--order $order: the order must be in 1..100 (the limit of a fit's order)" \
    "$HYST" fit-system $LAG --sample-time 1 --order "$order" --out x.json
done
for ts in 0 -1 inf nan; do
  check_error sample-time "the sample time must be finite and > 0 s" "$HYST" fit-system $LAG \
    --sample-time "$ts" --out x.json
done
check_error thresholds "--thresholds: 101 thresholds are above the limit of 100" "$HYST" \
  fit-system --model hammerstein $LAG --sample-time 1 --out x.json \
  --thresholds "0$(seq -s, 1 100 | sed 's/^/,/')"
check_error feedback-channels "--feedback-channels 65: above the limit of 64 channels" "$HYST" \
  fit-system --model hysteretic_lfr $LAG --sample-time 1 --out x.json --feedback-channels 65
check_error tables "--tables: 5001 tables, more than the limit of 1000 records of one fit" \
  "$HYST" fit modified_pi_creep --data sine.csv --input v --output y --out fitted.json \
  --tables "$(seq -s, 1 5001)"
check_error tables "--tables: table 1 is given twice" "$HYST" fit modified_pi_creep \
  --data sine.csv --input v --output y --out fitted.json --tables 1,2,1
"$PYTHON" - <<'PY' || exit 1
import json
def linear(a, b, c, d):
    return {"sample_time": 1.0, "a": a, "b": b, "c": c, "d": d}
def write(name, model, params):
    json.dump({"model": model, "version": 1, "params": params}, open(name, "w"))
n = 501
write("dense_501.json", "state_space",
      linear([[0.0] * n for _ in range(n)], [[0.0]] * n, [[0.0] * n], [[1.0]]))
# A first row of 10^6 numbers, then 10^6 empty rows: once a matrix of 10^12 entries was
# allocated before the second row was looked at.
with open("ragged_rows.json", "w") as f:
    f.write('{"model": "state_space", "version": 1, "params": {"sample_time": 1, "a": [['
            + ",".join(["0"] * 1000000) + "]" + ",[]" * 1000000
            + '], "b": [[0]], "c": [[0]], "d": [[1]]}}')
# One state, one input, one output and one hysteresis channel: z = x, x' = 0.5 x + u + w.
lfr = linear([[0.5]], [[1.0, 1.0]], [[1.0], [1.0]], [[0.0, 0.0], [0.0, 0.0]])
plays = 1001
write("lfr_many_plays.json", "hysteretic_lfr",
      {"inputs": 1, "linear": lfr, "feedback": [{"model": "pi", "params": {
          "thresholds": [k / plays for k in range(plays)], "weights": [0.001] * plays,
          "offset": 0.0}}]})
n = 101
write("lfr_101_states.json", "hysteretic_lfr",
      {"inputs": 1, "linear": linear([[0.0] * n for _ in range(n)], [[0.0, 0.0]] * n,
                                     [[0.0] * n] * 2, [[0.0, 0.0], [0.0, 0.0]]),
       "feedback": [{"model": "pi", "params": {"thresholds": [0.0], "weights": [1.0]}}]})
# w = -50 z: the loop's pole at 0.5 - 50 lies far outside the unit circle.
write("lfr_negative_weight.json", "hysteretic_lfr",
      {"inputs": 1, "linear": lfr, "feedback": [{"model": "pi", "params": {
          "thresholds": [0.0, 0.5], "weights": [-50.0, 0.1], "offset": 0.0}}]})
PY
check_error dense_501.json "order n = 501 is above the limit of 500 states" "$HYST" evaluate \
  --model dense_501.json $LAG
check_error ragged_rows.json "params.a[1]: 0 numbers, but row 0 has 1000000" "$HYST" evaluate \
  --model ragged_rows.json $LAG
check_error lfr_many_plays.json "feedback[0] has 1002 parameters, more than the limit of 1000" \
  "$HYST" evaluate --model lfr_many_plays.json $LAG --periodic
check_error lfr_101_states.json "the linear block has 101 states, more than the limit of 100" \
  "$HYST" evaluate --model lfr_101_states.json $LAG
# (A score's errors do not name the model file yet: the label is the message's own subject.)
check_error "hysteretic LFR" "the loop diverges: in period 1 of the search for the periodic" \
  "$HYST" evaluate --model lfr_negative_weight.json $LAG --periodic

# 3. Bad variants of every registered model's example file.
models="$("$HYST" models --json | "$PYTHON" -c 'import json,sys; print(" ".join(m["name"] for m in json.load(sys.stdin) if m.get("kind") != "dynamic"))')" ||
  exit 1
[ -n "$models" ] || { echo "FAIL: no models listed" >&2; exit 1; }
for model in $models; do
  "$HYST" models "$model" --json >"schema_$model.json" || exit 1
  while IFS=$'\t' read -r name text; do
    check "mutated/$name" model "$text"
  done < <("$PYTHON" "$HERE/mutate_model_file.py" "schema_$model.json" mutated)
done

echo "bad inputs tried: $TRIED (listed in expected.tsv: $listed; models: $models); failures: $FAILURES"
[ "$FAILURES" -eq 0 ]
