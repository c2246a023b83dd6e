#!/usr/bin/env python3
"""Writes series_0016.forc: a small MicroMag FORC file in the Series 0016 (VSM) layout.

No measured Series 0016 FORC file is at hand, so this one is built from the description of the
layout (hyst/io/micromag_forc.hpp) and the header of the Series 0016 loop files of
../shared/data/hystlab_vsm_hysteresis_loops (A4.hys): sections of "key   value" entries, column
titles stacked over three lines (a qualifier line, the names, the units with "Am" + the Latin-1
byte 0xB2), a third column "Normalized Moment" (moment / mass), a drift-calibration point at HCal
before every curve (in its own blank-line separated block) and a final one, CRLF line ends,
numbers as the instrument writes them (+443.9182E-06).

The moments come from a population of relays (a Preisach model) with Gaussian weights, measured
with a calibration moment that drifts down by 1 % over the run (multiplicative). Contents:
16 FORCs, reversal fields H_r = +0.07, +0.06, ..., -0.08 T, each measured up from H_r to +0.08 T
in steps of 10 mT, so FORC k (0-based) has k + 2 points: 2 + 3 + ... + 17 = 152 points, plus
17 calibration points (16 before the curves, 1 after the last): 169 data rows.
Run: python3 make_series_0016_forc.py (writes next to itself).
"""

import math
import pathlib

HSAT = 0.5       # T
HCAL = 0.3       # T
STEP = 0.01      # T
TOP = 0.08       # T, end of every curve
MASS = 2.0e-5    # kg
CURVES = 16
DRIFT = 0.01     # the calibration moment falls by 1 % over the run

# Relays (alpha >= beta) on a grid with Gaussian weights around a coercive field of 30 mT.
RELAYS = []
for i in range(-12, 13):
    for j in range(-12, 13):
        alpha, beta = 0.0075 * i, 0.0075 * j
        if alpha < beta:
            continue
        hc, hu = (alpha - beta) / 2, (alpha + beta) / 2
        weight = math.exp(-((hc - 0.03) / 0.015) ** 2 - (hu / 0.02) ** 2)
        RELAYS.append((alpha, beta, weight))
TOTAL = sum(w for _, _, w in RELAYS)
MS = 4.0e-5  # A m^2 at saturation


def forc_moment(h_r, h):
    """Moment after positive saturation, down to h_r, up to h (h >= h_r)."""
    total = 0.0
    for a, b, w in RELAYS:
        state = 1.0
        if h_r <= b:
            state = -1.0
        if state < 0 and h >= a:
            state = 1.0
        total += w * state
    return MS * total / TOTAL + 2.0e-6 * h  # a small reversible slope


def eng(value):
    """+443.9182E-06: 7 significant digits, exponent a multiple of 3 (as the VSM writes)."""
    if value == 0:
        return " 0.000000E+00"
    exponent = int(math.floor(math.log10(abs(value)) / 3) * 3)
    mantissa = value / 10 ** exponent
    digits = 6 - len(str(int(abs(mantissa))))
    text = f"{abs(mantissa):.{digits + 1}f}"
    return f"{'-' if value < 0 else '+'}{text}E{'-' if exponent < 0 else '+'}{abs(exponent):02d}"


def row(field, moment):
    return f"{eng(field)},{eng(moment)},{eng(moment / MASS)}"


rows = []
calibrations = CURVES + 1
for k in range(calibrations):
    gain = 1.0 - DRIFT * k / CURVES
    rows.append([row(HCAL + 0.0004 * ((-1) ** k), gain * forc_moment(HSAT, HCAL))])
    if k == CURVES:
        break
    h_r = round(0.07 - STEP * k, 6)
    count = round((TOP - h_r) / STEP) + 1
    curve = []
    for n in range(count):
        h = round(h_r + STEP * n, 6)
        curve.append(row(h + 0.00003 * ((-1) ** n), gain * forc_moment(h_r, h)))
    rows.append(curve)
data_rows = sum(len(block) for block in rows)

HEADER = f"""MicroMag 2900/3900 Data File (Series 0016.002)
First-order reversal curves

INSTRUMENT
Configuration                   VSM
Temperature control             None
Hardware version                0004
Software version                03/06/2013
Units of measure                Hybrid SI
Temperature in                  Kelvin

SAMPLE
Mass                           {eng(MASS)}
Volume                          N/A
Demagnetizing factor            N/A

SETTINGS
Field range                     N/A
Moment range                   +100.0000E-06
Averaging time                 +100.0000E-03
Orientation                     0.000000E+00
Vibration amplitude             1.0
Calibration factor             +4.039237E+00
Operating frequency            +83.00000E+00

MEASUREMENT
Description                    "synthetic test file, hyst"
Averages (completed)            1
Measured on                     03/14/2024  09:26
Elapsed time                   +412.5000E+00

PROCESSING
Background subtraction          No
Normalization                   Mass
Normalization factor           {eng(MASS)}
Slope correction                No

SCRIPT
Averaging time                 +100.0000E-03
Hb1                            -80.00000E-03
Hb2                            +80.00000E-03
Hc1                             0.000000E+00
Hc2                            +75.00000E-03
HCal                           {eng(HCAL)}
HNcr                           {eng(STEP)}
HSat                           {eng(HSAT)}
NForc                           {CURVES}
PauseCal                       +1.000000E+00
PauseNtl                       +1.000000E+00
PauseSat                       +1.000000E+00
SlewRate                       +1.000000E+00
Smoothing                       3
Number of data                  {data_rows}

                                            Normalized
    Field          Moment                     Moment
     (T)           (Am\u00b2)                       (Am\u00b2/kg)
"""

lines = HEADER.split("\n")[:-1]
for index, block in enumerate(rows):
    if index:
        lines.append("")
    lines.extend(block)
lines.append("")
lines.append("MicroMag 2900/3900 Data File ends")
text = "\r\n".join(lines) + "\r\n"
path = pathlib.Path(__file__).with_name("series_0016.forc")
path.write_bytes(text.encode("latin-1"))
print(f"wrote {path}: {len(text)} bytes, {CURVES} curves, {data_rows} data rows")
