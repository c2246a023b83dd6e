"""hyst.io's readers of magnetometer files: MicroMag hysteresis loops and MagIC tables."""

import numpy as np
import pytest

import hyst
from hyst import io

SMALL_LOOP = (
    "MicroMag 2900/3900 Data File (Series 0016.002)\n"
    "Direct moment vs. field; Hysteresis loop\n"
    "\n"
    "Units of measure                Hybrid SI\n"
    "Slope correction               +2.000000E-06\n"
    "Number of segments              2\n"
    "Number of data                  3\n"
    "\n"
    "Segment   Averaging\n"
    "0000001,+100.0000E-03\n"
    "0000002,+100.0000E-03\n"
    "\n"
    "    Field         Moment\n"
    "+5.0E-01,+2.0E-06\n"
    "\n"
    "-5.0E-01,-2.0E-06\n"
    "+5.0E-01,+2.0E-06\n"
    "\n"
    "MicroMag 2900/3900 Data File ends\n")


def test_micromag_loop_file(data_dir):
    loop = io.read_micromag_loop(data_dir / "hystlab_vsm_hysteresis_loops" / "fig01" / "CP4Q.hyst")
    assert isinstance(loop, io.MicromagLoopFile)
    assert loop.format == "MicroMag 2900/3900 Data File (Series 0015)"
    assert loop.title == "Direct moment vs. field; Hysteresis loop"
    assert loop.columns == ["Raw Field", "Raw Moment", "Adjusted Field", "Adjusted Moment"]
    assert loop.points == 1602 and loop.segments == 3 and loop.segment_starts == [0, 801]
    assert loop.first_data_line == 80
    assert loop.header["Units of measure"] == "Hybrid SI"
    assert loop.header_number("Slope correction") == -1.278073e-05
    # The adjusted moment is the raw one with the stated slope removed (7 printed digits).
    slope = loop.header_number("Slope correction")
    assert np.allclose(loop.column("Adjusted Moment"), loop.moment + slope * loop.field,
                       rtol=0, atol=1.4e-11)
    table = loop.to_dict()
    assert list(table) == loop.columns and np.array_equal(table["Raw Field"], loop.field)
    assert "1602 points" in repr(loop) and loop.source.endswith("CP4Q.hyst")
    # No units line in Series 0015: the units follow "Hybrid SI"; no initial curve measured.
    assert loop.units == ["T", "A m\u00b2", "T", "A m\u00b2"] and loop.initial_curve_points == 0


def test_micromag_loop_through_hyst_data(data_dir):
    path = data_dir / "hystlab_vsm_hysteresis_loops" / "fig06" / "Conc_40_C3B.hys"
    columns = hyst.data.extract(path, ["Field", "Adjusted Moment"])
    assert list(columns) == ["Field", "Adjusted Moment"] and len(columns["Field"]) == 242


def test_micromag_loop_errors_name_line_and_column():
    parsed = io.parse_micromag_loop(SMALL_LOOP, "small.hys")
    assert list(parsed.field) == [0.5, -0.5, 0.5]
    with pytest.raises(hyst.Error, match=r"small.hys:14: column 2 \('Moment'\): 'x' is not"):
        io.parse_micromag_loop(SMALL_LOOP.replace("+5.0E-01,+2.0E-06\n\n", "+5.0E-01,x\n\n"),
                               "small.hys")
    with pytest.raises(hyst.Error, match="truncated"):
        io.parse_micromag_loop(SMALL_LOOP.replace("MicroMag 2900/3900 Data File ends\n", ""))


def test_magic_table_loops(data_dir):
    table = io.read_magic_table(data_dir / "pmagpy_forc_micromag_agm" /
                                "hysteresis_magic_example.dat")
    assert isinstance(table, io.MagicTable)
    assert table.name == "magic_measurements" and len(table.rows) == 3516
    assert table.row_lines[0] == 3 and table.source.endswith(".dat")
    assert "measurement_magn_moment" in table.columns and "3516 rows" in repr(table)
    loops = io.magic_hysteresis_loops(table)
    assert all(isinstance(loop, io.MagicHysteresisLoop) for loop in loops)
    assert [len(loop.field) for loop in loops] == [283] + [403] * 7
    assert loops[0].specimen == "IS06a-1" and loops[0].experiment == "IS06a-1:LP-HYS"
    assert loops[0].first_line == 3 and loops[0].field[0] == 1.196
    assert loops[0].moment[0] == 62.98 and "283 points" in repr(loops[0])


def test_magic_table_errors():
    table = io.parse_magic_table("tab\tmeasurements\nspecimen\texperiment\tmethod_codes\t"
                                 "meas_field_dc\tmagn_moment\ns\te\tLP-HYS\t1\tq\n", "m.txt")
    with pytest.raises(hyst.Error, match="m.txt:3: column 'magn_moment': 'q' is not a finite"):
        io.magic_hysteresis_loops(table)
    with pytest.raises(hyst.Error, match="not a MagIC table"):
        io.parse_magic_table("a,b\n")
