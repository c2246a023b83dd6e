"""FORC files and the Preisach model identified from them: hyst.io.read_micromag_forc (Series 0015
and 0016 layouts) and hyst.fit_preisach_forcs. Expected counts come from the files' provenance
(PROVENANCE.md of the AGM data) and from the construction of the Series 0016 test file
(tests/data/micromag/make_series_0016_forc.py), not from hyst's output."""

from pathlib import Path

import numpy as np
import pytest

import hyst
from hyst import io

VSM_FILE = Path(__file__).resolve().parents[2] / "tests" / "data" / "micromag" / "series_0016.forc"


@pytest.fixture
def agm_file(data_dir):
    return data_dir / "pmagpy_forc_micromag_agm" / "conventional_example.forc"


def test_reads_the_series_0015_agm_file(agm_file):
    forc = io.read_micromag_forc(agm_file)
    assert isinstance(forc, io.MicromagForcFile) and forc.layout == "series_0015"
    assert forc.header["Configuration"] == "AGM" and forc.header_number("HCal") == 0.2350512
    assert forc.columns == ["Field", "Moment"] and forc.units == ["T", "A m\u00b2"]
    # PROVENANCE.md: 120 FORCs after 120 calibration points, 8514 data rows, the first FORC one
    # point at H_r = 0.118 T, the last one 85 points from -0.218 T.
    assert len(forc.curves) == 120 and forc.points == 8514 - 120 and forc.calibration_points == 120
    first, last = forc.curves[0], forc.curves[-1]
    assert len(first) == 1 and first.field[0] == 0.1182822 and first.first_line == 37
    assert len(last.field) == 85 and last.field[0] == -0.218002
    assert first.calibration_moment == 7.842043e-07 and forc.final_calibration is None
    assert isinstance(first, io.MicromagForcCurve) and first.more_columns == []
    assert abs(first.calibration_field - 0.237) < 1e-3
    assert "120 curves" in repr(forc) and "H_r = " in repr(first)
    corrected = io.correct_drift(forc, "multiplicative")
    assert corrected.curves[-1].calibration_moment == first.calibration_moment
    assert not np.array_equal(corrected.curves[-1].moment, last.moment)


def test_reads_the_series_0016_vsm_file():
    forc = io.read_micromag_forc(VSM_FILE)
    assert forc.layout == "series_0016" and forc.header["Configuration"] == "VSM"
    assert forc.columns == ["Field", "Moment", "Normalized Moment"]
    assert forc.units == ["T", "Am\u00b2", "Am\u00b2/kg"]
    # 16 curves of 2, 3, ..., 17 points; a calibration point before each and one after the last.
    assert [len(c) for c in forc.curves] == list(range(2, 18))
    assert forc.points == 152 and forc.calibration_points == 17
    assert forc.final_calibration == (0.3004, 40.194e-6)
    # Normalized moment = moment / mass (2e-5 kg in the header), as written to 7 digits.
    mass = forc.header_number("Mass")
    for curve in forc.curves:
        (normalized,) = curve.more_columns
        np.testing.assert_allclose(normalized, curve.moment / mass, rtol=1e-6)


def test_number_of_segments_without_a_segment_table_and_the_two_line_header():
    # The header of a measured VSM FORC file that was refused: the script's segment count, no
    # segment table. The same text as the C++ reader reads it; counts by hand from the text.
    text = ("MicroMag 2900/3900 Data File (Series 0016.002)\nFirst-order reversal curves\n\n"
            "SCRIPT\nUnits of measure                Cgs\n"
            "Number of segments              100\nNumber of data                  5\n\n"
            "    Field          Moment\n"
            "+3.0E+03,+1.0E-02\n\n+1.0E+03,+5.0E-03\n\n+3.0E+03,+9.0E-03\n\n"
            "-1.0E+03,-5.0E-03\n+0.0E+00,+1.0E-03\nMicroMag 2900/3900 Data File ends\n")
    forc = io.parse_micromag_forc(text, "forc_vsm.001")
    assert forc.layout == "series_0016" and forc.header_number("Number of segments") == 100
    assert forc.units == ["Oe", "emu"] and [len(c) for c in forc.curves] == [1, 2]
    assert list(forc.curves[1].field) == [-1000.0, 0.0] and forc.curves[1].first_line == 16
    old = io.parse_micromag_forc("MicroMag 2900/3900 Data File\nFirst-order reversal curves\n"
                                 "+2.0E-01,+1.0E-06\n\n+1.0E-01,+5.0E-07\n"
                                 "MicroMag 2900/3900 Data File ends\n", "old.frc")
    assert old.layout == "no_header" and old.columns == ["Field", "Moment"]
    assert old.units == ["", ""] and len(old.curves) == 1


def test_magnetic_models_state_their_units():
    ja = hyst.model_entry("jiles_atherton")
    assert (ja.input_unit, ja.output_unit) == ("A/m", "T")
    pi = hyst.model_entry("pi")
    assert (pi.input_unit, pi.output_unit) == ("", "")


def test_reader_errors_name_file_and_line(tmp_path):
    bad = VSM_FILE.read_bytes().replace(b"+2.007000E+00", b"+2.0x7000E+00")
    path = tmp_path / "bad.forc"
    path.write_bytes(bad)
    with pytest.raises(hyst.Error, match=r"bad.forc:60: column 3 \('Normalized Moment'\)"):
        io.read_micromag_forc(path)
    with pytest.raises(hyst.Error, match="truncated"):
        io.parse_micromag_forc(VSM_FILE.read_bytes().decode("latin-1").split("MicroMag 2900/3900 "
                                                                          "Data File ends")[0])


def test_fit_preisach_forcs_from_the_agm_file(agm_file, tmp_path):
    forc = io.read_micromag_forc(agm_file)
    model, report = hyst.fit_preisach_forcs(forc, drift="multiplicative", hold_out_every=4,
                                            intervals=32)
    assert isinstance(model, hyst.Model) and model.name == "tabulated_preisach"
    assert report.model == "tabulated_preisach" and report.status == "converged"
    # Every 4th of 120 curves held out: 30 curves; their points counted from the curves.
    held = sum(len(c) for c in forc.curves[3::4])
    assert report.validation.samples == held and report.fit.samples == forc.points - held
    # The measurement noise is about 0.03 % of the range (docs/results.md).
    assert report.fit.nrmse_percent < 0.1 and report.validation.nrmse_percent < 0.1
    assert len(model.params["levels"]) == 33
    assert model.params["levels"][0] == forc.curves[-1].field[0]  # the lowest field
    # Saved and loaded like any model; a held-out curve predicted from positive saturation.
    hyst.save_model(tmp_path / "forc.json", model)
    loaded = hyst.load_model(tmp_path / "forc.json")
    curve = forc.curves[3]
    predicted = loaded.simulate(np.concatenate(([1.0], curve.field)))[1:]
    assert np.max(np.abs(predicted - curve.moment)) < 0.02 * np.ptp(
        np.concatenate([c.moment for c in forc.curves]))


def test_fit_preisach_forcs_from_arrays_and_the_vsm_file():
    forc = io.read_micromag_forc(VSM_FILE)
    model, report = hyst.fit_preisach_forcs(forc, hold_out_every=4, intervals=8)
    assert report.validation.samples == 5 + 9 + 13 + 17 and report.fit.samples == 108
    # The same curves as (input, output) pairs, the same held-out ones by index.
    pairs = [(c.field, c.moment) for c in forc.curves]
    lower = min(c.field.min() for c in forc.curves)
    upper = max(c.field.max() for c in forc.curves)
    twin, twin_report = hyst.fit_preisach_forcs(pairs, held_out=[3, 7, 11, 15], intervals=8,
                                                lower=lower, upper=upper)
    assert twin.params == model.params
    assert twin_report.validation.samples == report.validation.samples
    with pytest.raises(hyst.Error, match="fewer than cells"):
        hyst.fit_preisach_forcs(forc)
    with pytest.raises(hyst.Error, match="fit options.intervalls: unknown field"):
        hyst.fit_preisach_forcs(forc, intervalls=8)
    with pytest.raises(hyst.Error, match="drift"):
        hyst.fit_preisach_forcs(pairs, drift="multiplicative")
    with pytest.raises(hyst.Error, match=r"curves\[0\] must be a pair"):
        hyst.fit_preisach_forcs([(1.0, 2.0, 3.0)])
    with pytest.raises(hyst.Error, match="every 1st curve"):
        hyst.fit_preisach_forcs(forc, hold_out_every=1)
