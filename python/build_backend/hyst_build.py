"""The PEP 517 build backend of the Python module `hyst`: `pip install .` and `pip wheel .`.

It lives in the repository (pyproject.toml names it with `backend-path`) and needs nothing but
the standard library, so that pip builds offline with no build requirements to fetch. It drives
CMake: configures a Release build of the module alone in `build-wheel/` of the checkout (kept,
so a second install only relinks), builds the module and its type stubs (target `hyst_python_stubs`) for the interpreter
running pip, and packs the module into a wheel by hand (a zip with the `.dist-info` files of the
wheel format: METADATA, WHEEL, RECORD with sha256 digests). The metadata comes from the
[project] table of pyproject.toml: the requirement numpy (`Requires-Dist: numpy`), the extras
(`Provides-Extra`, `Requires-Dist: matplotlib; extra == "plot"`, ...), the licence and the
project's addresses (`Project-URL`). In a venv made with --system-site-packages Debian's packages
(python3-numpy, ...) satisfy them offline; `pip wheel --no-deps .` makes the wheel alone.

Settings, as `pip install . --config-settings KEY=VALUE` or environment variables:
  build-dir / HYST_WHEEL_BUILD_DIR   the CMake build folder (default: build-wheel)
  jobs / HYST_WHEEL_JOBS             parallel build jobs (default: the number of CPUs)
"""

import base64
import hashlib
import io
import os
import re
import subprocess
import sys
import sysconfig
import tarfile
import zipfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
NAME = "hyst"


def _version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    match = re.search(r"project\(hyst VERSION ([0-9.]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(hyst VERSION x.y.z' line")
    return match.group(1)


def _description():
    text = (SOURCE / "CMakeLists.txt").read_text()
    match = re.search(r'project\(hyst VERSION [0-9.]+ DESCRIPTION "([^"]*)"', text)
    return match.group(1) if match else "Hysteresis models"


def _setting(config_settings, key, variable, default):
    if config_settings and key in config_settings:
        return str(config_settings[key])
    return os.environ.get(variable, default)


def _tag():
    """The wheel tag of the running interpreter, e.g. cp311-cp311-linux_x86_64."""
    interpreter = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{interpreter}-{interpreter}-{platform}"


def _project():
    """The [project] table of pyproject.toml."""
    try:
        import tomllib
    except ModuleNotFoundError:  # Python < 3.11
        try:
            import tomli as tomllib
        except ModuleNotFoundError:
            raise RuntimeError("hyst: reading pyproject.toml needs Python 3.11 (tomllib) or the "
                               "package tomli (Debian: python3-tomli)") from None
    with open(SOURCE / "pyproject.toml", "rb") as file:
        return tomllib.load(file)["project"]


def _metadata():
    """The core metadata (METADATA, PKG-INFO) of the [project] table."""
    project = _project()
    lines = [
        "Metadata-Version: 2.1",
        f"Name: {NAME}",
        f"Version: {_version()}",
        f"Summary: {project.get('description') or _description()}",
        f"Requires-Python: {project['requires-python']}",
        f"License: {project['license']['text']}",
        "License-File: LICENSE",
        "Classifier: License :: OSI Approved :: BSD License",
    ]
    lines += [f"Project-URL: {label}, {url}" for label, url in project.get("urls", {}).items()]
    lines += [f"Requires-Dist: {requirement}" for requirement in project.get("dependencies", [])]
    for extra, requirements in project.get("optional-dependencies", {}).items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {requirement}; extra == "{extra}"'
                  for requirement in requirements]
    readme = project.get("readme")
    if readme:
        lines.append("Description-Content-Type: text/markdown")
        return "\n".join(lines) + "\n\n" + (SOURCE / readme).read_text(encoding="utf-8")
    return "\n".join(lines) + "\n"


def _dist_info():
    return f"{NAME}-{_version()}.dist-info"


def _write_dist_info(folder):
    info = Path(folder) / _dist_info()
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata())
    (info / "LICENSE").write_bytes((SOURCE / "LICENSE").read_bytes())
    return info.name


def _build_module(config_settings):
    """Configures and builds the module; returns the files that go into the wheel."""
    build = Path(_setting(config_settings, "build-dir", "HYST_WHEEL_BUILD_DIR",
                          str(SOURCE / "build-wheel")))
    if not build.is_absolute():
        build = SOURCE / build
    jobs = _setting(config_settings, "jobs", "HYST_WHEEL_JOBS", str(os.cpu_count() or 1))
    configure = [
        "cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
        f"-DHYST_PYTHON_EXECUTABLE={sys.executable}", f"-DPython_EXECUTABLE={sys.executable}",
        "-DHYST_BUILD_TESTS=OFF", "-DHYST_BUILD_BENCHMARKS=OFF", "-DHYST_BUILD_EXAMPLES=OFF",
        "-DHYST_BUILD_PYTHON=ON",
    ]
    # A configured folder is built as it is (e.g. a developer's build/, whose module is built
    # for /usr/bin/python3, the interpreter of a --system-site-packages venv too).
    commands = [] if (build / "CMakeCache.txt").exists() else [configure]
    commands.append(["cmake", "--build", str(build), "--target", "hyst_python_stubs", "-j", jobs])
    # pip's isolated build environment hides the system's site-packages from every Python started
    # with its PYTHONPATH (a sitecustomize there); the stub generator imports the module, which
    # needs Debian's numpy, so the build runs without it.
    environment = {key: value for key, value in os.environ.items()
                   if key not in ("PYTHONPATH", "PYTHONNOUSERSITE")}
    # Progress to standard error: pip shows it with -v and keeps it out of its own output.
    for command in commands:
        result = subprocess.run(command, stdout=sys.stderr, stderr=sys.stderr, check=False,
                                env=environment)
        if result.returncode != 0:
            raise RuntimeError(f"hyst: '{' '.join(command)}' failed with exit status "
                               f"{result.returncode} (the CMake output above says why)")
    package = build / "python" / NAME
    extension = package / f"_core{sysconfig.get_config_var('EXT_SUFFIX')}"
    if not extension.is_file():
        raise RuntimeError(f"hyst: the build made no {extension}")
    # The package as the build laid it out: the extension, the Python files, stubs if any.
    return {f"{NAME}/{path.relative_to(package)}": path.read_bytes()
            for path in sorted(package.rglob("*"))
            if path.is_file() and "__pycache__" not in path.parts}


def _record_line(name, content):
    digest = base64.urlsafe_b64encode(hashlib.sha256(content).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(content)}"


def _write_wheel(wheel_directory, files):
    dist_info = _dist_info()
    files = dict(files)
    files[f"{dist_info}/METADATA"] = _metadata().encode()
    files[f"{dist_info}/LICENSE"] = (SOURCE / "LICENSE").read_bytes()
    files[f"{dist_info}/WHEEL"] = "\n".join([
        "Wheel-Version: 1.0", "Generator: hyst_build", "Root-Is-Purelib: false",
        f"Tag: {_tag()}", ""]).encode()
    files[f"{dist_info}/top_level.txt"] = f"{NAME}\n".encode()
    record_name = f"{dist_info}/RECORD"
    record = [_record_line(name, content) for name, content in files.items()]
    record.append(f"{record_name},,")
    files[record_name] = ("\n".join(record) + "\n").encode()

    wheel_name = f"{NAME}-{_version()}-{_tag()}.whl"
    target = Path(wheel_directory) / wheel_name
    temporary = target.with_name(f".{wheel_name}.tmp.{os.getpid()}")
    with zipfile.ZipFile(temporary, "w", compression=zipfile.ZIP_DEFLATED) as wheel:
        for name, content in files.items():
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if name.endswith(".so") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(info, content)
    os.replace(temporary, target)
    return wheel_name


# The PEP 517 hooks.

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _write_dist_info(metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    return _write_wheel(wheel_directory, _build_module(config_settings))


def build_sdist(sdist_directory, config_settings=None):
    """The tracked files of the checkout (git ls-files) with PKG-INFO, as NAME-VERSION.tar.gz."""
    listed = subprocess.run(["git", "-C", str(SOURCE), "ls-files", "-z"], capture_output=True,
                            check=True).stdout.decode().split("\0")
    base = f"{NAME}-{_version()}"
    name = f"{base}.tar.gz"
    target = Path(sdist_directory) / name
    temporary = target.with_name(f".{name}.tmp.{os.getpid()}")
    with tarfile.open(temporary, "w:gz") as archive:
        for path in filter(None, listed):
            archive.add(SOURCE / path, arcname=f"{base}/{path}", recursive=False)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        content = _metadata().encode()
        info.size = len(content)
        archive.addfile(info, io.BytesIO(content))
    os.replace(temporary, target)
    return name
