"""Every Python writer keeps what it must not replace (hyst/io/output_paths.hpp): a device node
(as root, made with mknod in a temporary folder) and a FIFO are written through, a link keeps
pointing at its target, which gets the new content, and an output that is the input (also through
a link or a hard link) or another output is refused with hyst.Error naming both."""

import contextlib
import os
import shutil
import stat
import threading
from pathlib import Path

import numpy as np
import pytest

import hyst

needs_gnuplot = pytest.mark.skipif(shutil.which("gnuplot") is None, reason="gnuplot not installed")


def example_model():
    return hyst.Model("pi", hyst.model_entry("pi").example_params)


def record(tmp_path: Path) -> Path:
    path = tmp_path / "record.csv"
    v = np.sin(np.linspace(0.0, 12.0, 300)) * np.linspace(0.2, 1.0, 300)
    hyst.io.write_csv(path, {"v": v, "y": example_model().simulate(v)})
    return path


def comparison(v, y):
    return hyst.compare(v, y, ["pi"], timing_seconds=0.0)


def write_plots(tmp_path: Path, path: Path):
    columns = hyst.io.read_csv(record(tmp_path))
    comparison(columns["v"], columns["y"]).write_plots(
        columns["v"], columns["y"], path, tmp_path / "errors.png")


# Every writer of one file: name -> (write(tmp_path, path), a check of what a reader got).
WRITERS = {
    "save_model": (lambda tmp, path: hyst.save_model(path, example_model()),
                   lambda data: b'"model": "pi"' in data),
    "io.write_csv": (lambda tmp, path: hyst.io.write_csv(path, {"v": [1.0, 2.0]}),
                     lambda data: data.startswith(b"v\n1")),
    "io.write_mat_vectors": (lambda tmp, path: hyst.io.write_mat_vectors(path, {"v": [1.0, 2.0]}),
                             lambda data: data.startswith(b"MATLAB")),
    "data.extract": (lambda tmp, path: hyst.data.extract(record(tmp), ["y"], out=path),
                     lambda data: data.startswith(b"y\n")),
    "ModelComparison.write_plots": (write_plots, lambda data: data.startswith(b"\x89PNG")),
}


def writer_params():
    for name in WRITERS:
        marks = [needs_gnuplot] if name == "ModelComparison.write_plots" else []
        yield pytest.param(name, marks=marks, id=name)


@pytest.mark.parametrize("name", writer_params())
def test_device_node_is_written_through(name, tmp_path):
    if os.geteuid() != 0:
        pytest.skip("mknod needs root")
    node = tmp_path / "null"
    try:
        os.mknod(node, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
    except OSError as error:
        pytest.skip(f"mknod failed: {error}")
    WRITERS[name][0](tmp_path, node)
    assert stat.S_ISCHR(os.lstat(node).st_mode), "the device node was replaced"
    assert not [p for p in tmp_path.iterdir() if ".tmp." in p.name]


@pytest.mark.parametrize("name", writer_params())
def test_fifo_is_written_through(name, tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    try:
        WRITERS[name][0](tmp_path, fifo)
    finally:
        # A writer that wrote and closed lets the reader finish on its own: wait for that first,
        # else the reader may be between its last read and storing the bytes.
        reader.join(2)
        if stat.S_ISFIFO(os.lstat(fifo).st_mode) and reader.is_alive():
            # Unblocks the reader if the writer never opened the FIFO (the test fails below);
            # ENXIO: the reader has closed it meanwhile, nothing to unblock.
            with contextlib.suppress(OSError):
                with open(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK), "wb"):
                    pass
        reader.join(10)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode), "the FIFO was replaced"
    assert got and WRITERS[name][1](got[0]), got[:1]


@pytest.mark.parametrize("name", writer_params())
def test_link_is_kept_and_its_target_replaced(name, tmp_path):
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "target"
    target.write_bytes(b"old")
    link = tmp_path / "link"
    link.symlink_to(Path("real") / "target")
    WRITERS[name][0](tmp_path, link)
    assert link.is_symlink() and os.readlink(link) == str(Path("real") / "target")
    assert WRITERS[name][1](target.read_bytes())
    assert not [p for p in (tmp_path / "real").iterdir() if ".tmp." in p.name]


def test_extract_refuses_its_input_as_output(tmp_path):
    path = record(tmp_path)
    before = path.read_bytes()
    alias = tmp_path / "alias.csv"
    os.link(path, alias)
    link = tmp_path / "link.csv"
    link.symlink_to(path)
    for out in (path, alias, link):
        with pytest.raises(hyst.Error, match=r"out '.*' is the same file as the input path '.*record\.csv'"):
            hyst.data.extract(path, ["v"], out=out)
    assert path.read_bytes() == before


def test_refuses_a_folder_and_a_file_as_folder_and_creates_a_missing_folder(tmp_path):
    with pytest.raises(hyst.Error, match="it is a folder, not a file"):
        hyst.io.write_csv(tmp_path, {"v": [1.0]})
    (tmp_path / "plain").write_text("x")
    with pytest.raises(hyst.Error, match="'.*plain' is not a folder"):
        hyst.save_model(tmp_path / "plain" / "m.json", example_model())
    hyst.save_model(tmp_path / "new" / "sub" / "m.json", example_model())
    assert (tmp_path / "new" / "sub" / "m.json").is_file()


@needs_gnuplot
def test_write_plots_refuses_two_equal_outputs(tmp_path):
    columns = hyst.io.read_csv(record(tmp_path))
    v, y = columns["v"], columns["y"]
    (tmp_path / "x").mkdir()
    with pytest.raises(hyst.Error, match="loop_png '.*same.png' and error_png '.*same.png' are the same file"):
        comparison(v, y).write_plots(v, y, tmp_path / "same.png", tmp_path / "x" / ".." / "same.png")


def test_export_c_follows_links_and_writes_through(tmp_path):
    folder = tmp_path / "ctrl"
    folder.mkdir()
    (tmp_path / "kept.h").write_text("old")
    (folder / "m.h").symlink_to(tmp_path / "kept.h")
    os.mkfifo(folder / "m.c")
    got = []
    reader = threading.Thread(target=lambda: got.append((folder / "m.c").read_bytes()))
    reader.start()
    hyst.export_c(example_model(), folder, prefix="m")
    reader.join(10)
    assert (folder / "m.h").is_symlink() and "m_init" in (tmp_path / "kept.h").read_text()
    assert stat.S_ISFIFO(os.lstat(folder / "m.c").st_mode)
    assert got and b"m_step" in got[0]


@needs_gnuplot
def test_actuator_plots_are_published_as_one_set(tmp_path):
    config_dir = Path(__file__).resolve().parents[2] / "examples" / "config"
    msma = hyst.load_actuator_config(config_dir / "msma_assumed.json")
    (tmp_path / "notes.txt").write_text("mine")
    msma.compare(plot_folder=tmp_path)
    plots = sorted(p.name for p in tmp_path.iterdir() if p.name.endswith(".png"))
    assert "tracking_step.png" in plots
    for name in plots:
        assert os.readlink(tmp_path / name) == f".hyst-current/{name}"
        assert (tmp_path / name).read_bytes()[:4] == b"\x89PNG"
    assert len([p for p in tmp_path.iterdir() if p.name.startswith(".hyst-set.")]) == 1
    assert (tmp_path / "notes.txt").read_text() == "mine"


def test_check_outputs_refuses_an_output_that_is_an_input(tmp_path):
    record = tmp_path / "r.csv"
    record.write_text("v,y\n1,2\n")
    link = tmp_path / "link.csv"
    os.link(record, link)
    hyst.io.check_outputs([(str(record), "--data")], [(str(tmp_path / "m.json"), "--out")])
    with pytest.raises(hyst.Error, match="same file"):
        hyst.io.check_outputs([(str(record), "--data")], [(str(link), "--out")])


def test_output_set_publishes_all_names_at_once_or_leaves_the_previous_set(tmp_path):
    folder = tmp_path / "out"
    with hyst.io.OutputSet(folder, ["a.txt", "b.txt"]) as first:
        for name in ("a.txt", "b.txt"):
            Path(first.staged(name)).write_text(f"first {name}")
        first.publish()
        assert Path(first.published("b.txt")) == folder / "b.txt"
    assert (folder / "a.txt").read_text() == "first a.txt"
    assert os.path.islink(folder / "a.txt")
    # A second run that stages a new set but never publishes it (discarded): the first stays.
    second = hyst.io.OutputSet(folder, ["a.txt", "b.txt"])
    Path(second.staged("a.txt")).write_text("second a.txt")
    staging = Path(second.staged())
    second.discard()
    assert not staging.exists()
    assert (folder / "a.txt").read_text() == "first a.txt"
    assert (folder / "b.txt").read_text() == "first b.txt"
    with pytest.raises(hyst.Error, match="discarded"):
        second.staged("a.txt")
