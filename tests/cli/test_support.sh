# Shared start of the command-line test scripts (atomic_output.sh, output_paths.sh,
# output_set.sh): HYST as an absolute path, a scratch folder WORK (removed on exit) as the current
# folder, fail and good_model.
#
#     source "$(dirname "${BASH_SOURCE[0]}")/test_support.sh" NAME   # WORK is hyst-NAME.XXXXXX

: "${HYST:?set HYST to the hyst executable}"
HYST="$(cd "$(dirname "$HYST")" && pwd)/$(basename "$HYST")"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/hyst-$1.XXXXXX")"
trap 'chmod -R u+w "$WORK" 2>/dev/null; rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# good_model FILE: the example model file of the PI model.
good_model() {
  "$HYST" models pi --json |
    /usr/bin/python3 -c 'import json,sys; json.dump(json.load(sys.stdin)["example"], sys.stdout)' >"$1"
}
