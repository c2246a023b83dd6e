#!/usr/bin/env bash
# `pip install .` and `pip wheel .` of the checkout, offline, in a fresh venv of Debian's Python
# with its site packages (numpy from Debian), then an example run with the installed module from
# another folder, without PYTHONPATH. The build backend is pointed at the configured build folder
# of this test run (HYST_WHEEL_BUILD_DIR), so that it only checks that the module is up to date
# instead of compiling the library a second time; everything else is what a user's install does.
#
# Usage: pip_install.sh CHECKOUT BUILD_DIR
set -euo pipefail

checkout=$(realpath "$1")
build=$(realpath "$2")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

export HYST_WHEEL_BUILD_DIR="$build" PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_INPUT=1
unset PYTHONPATH

/usr/bin/python3 -m venv --system-site-packages "$scratch/venv"
python="$scratch/venv/bin/python"

# The stubs made out of date, so that the backend makes them again inside pip's isolated build
# environment, as a first install does (that environment hides Debian's numpy from the Pythons it
# starts unless the backend clears it).
touch -d '2000-01-01' "$build/python/hyst/__init__.pyi"

# --no-deps: the wheel alone (its requirement numpy is Debian's here; pip wheel would fetch one).
"$python" -m pip wheel --no-deps "$checkout" --wheel-dir "$scratch/wheels" >"$scratch/wheel.log" 2>&1 ||
  { tail -n 30 "$scratch/wheel.log"; fail "pip wheel failed"; }
wheel=$(ls "$scratch"/wheels/hyst-*.whl) || fail "no wheel in $(ls "$scratch/wheels")"
"$python" - "$wheel" <<'PY' || fail "the wheel is malformed"
import base64, hashlib, sys, zipfile
wheel = zipfile.ZipFile(sys.argv[1])
names = wheel.namelist()
record = next(n for n in names if n.endswith(".dist-info/RECORD"))
assert any(n.startswith("hyst/_core.") and n.endswith(".so") for n in names), names
assert {"hyst/__init__.py", "hyst/batch.py"} <= set(names), names
assert {"hyst/__init__.pyi", "hyst/io.pyi", "hyst/py.typed"} <= set(names), names
for line in wheel.read(record).decode().splitlines():
    name, digest, size = line.split(",")
    if name == record:
        continue
    content = wheel.read(name)
    expected = base64.urlsafe_b64encode(hashlib.sha256(content).digest()).rstrip(b"=").decode()
    assert digest == f"sha256={expected}" and int(size) == len(content), name
assert sorted(l.split(",")[0] for l in wheel.read(record).decode().splitlines()) == sorted(names)
# The licence: named in the metadata, its text beside it.
metadata = wheel.read(next(n for n in names if n.endswith(".dist-info/METADATA"))).decode()
lines = metadata.split("\n\n", 1)[0].splitlines()
assert "License: BSD-3-Clause" in lines, metadata
# The requirement, the extras with their requirements, the project's addresses.
assert "Requires-Dist: numpy" in lines, lines
for extra, requirement in (("plot", "matplotlib"), ("progress", "tqdm"),
                           ("distributed", "distributed")):
    assert f"Provides-Extra: {extra}" in lines, lines
    assert f'Requires-Dist: {requirement}; extra == "{extra}"' in lines, lines
urls = [line for line in lines if line.startswith("Project-URL: ")]
assert {url.split(": ", 1)[1].split(",")[0] for url in urls} >= {"Homepage", "Source", "Issues"}, urls
assert all(url.split(", ", 1)[1].startswith("https://") for url in urls), urls
assert "Description-Content-Type: text/markdown" in lines and "# hyst" in metadata, lines
licence = wheel.read(next(n for n in names if n.endswith(".dist-info/LICENSE"))).decode()
assert licence.startswith("BSD 3-Clause License"), licence[:80]
PY

"$python" -m pip install "$checkout" >"$scratch/install.log" 2>&1 ||
  { tail -n 30 "$scratch/install.log"; fail "pip install failed"; }
# pip sees hyst's declared requirements satisfied (Debian's numpy in the system site packages);
# pip check also reports other Debian packages' gaps, which are not hyst's.
"$python" -m pip check >"$scratch/check.log" 2>&1 || true
! grep -i '^hyst ' "$scratch/check.log" || fail "pip check: hyst's requirements are not met"
"$python" -c "
from importlib.metadata import requires
assert 'numpy' in requires('hyst'), requires('hyst')" || fail "the installed hyst does not require numpy"
cd "$scratch"
location=$("$python" -c "import hyst; print(hyst.__file__)")
case "$location" in
  "$scratch/venv/"*) ;;
  *) fail "hyst was imported from $location, not from the venv" ;;
esac
"$python" "$checkout/examples/02_fit_pi.py" >example.log 2>&1 ||
  { cat example.log; fail "example 02 failed with the installed module"; }
"$python" -m hyst.batch fit --help >batch.log 2>&1 ||
  { cat batch.log; fail "python -m hyst.batch failed with the installed module"; }
"$python" -m pip uninstall -y hyst >/dev/null || fail "pip uninstall failed"
! "$python" -c "import hyst" 2>/dev/null || fail "hyst still importable after uninstall"
echo "pip wheel, pip install, example 02, hyst.batch and pip uninstall in a venv: ok"
