"""hyst.export_c: the generated C, compiled with gcc, reproduces the model and its inverse."""

import subprocess

import numpy as np
import pytest

import hyst

DRIVER = r"""#include <stdio.h>
#include "m.h"
int main(void) {
  double v;
  m_state model;
  m_inverse_state inverse;
  m_init(&model);
  m_inverse_init(&inverse);
  while (scanf("%lf", &v) == 1) {
    const double y = m_step(&m_PARAMS, &model, v);
    printf("%.17g %.17g\n", y, m_inverse_step(&m_INVERSE_PARAMS, &inverse, y));
  }
  return 0;
}
"""


def test_exported_modified_pi_matches_the_library(tmp_path):
    model = hyst.Model("modified_pi", {
        "thresholds": [0.0, 0.3, 0.7, 1.0], "weights": [0.8, 0.5, 0.3, 0.2], "pi_offset": 0.1,
        "dead_zone_thresholds": [-0.8, 0.0, 0.9], "dead_zone_weights": [0.1, 1.0, -0.2],
        "offset": 0.05})
    rng = np.random.default_rng(3)
    # A start state that is not the default.
    _, model.state = model.simulate(np.cumsum(rng.normal(0, 0.1, 200)), return_state=True)
    assert model.state != hyst.Model(model.name, model.params).state
    files = hyst.export_c(model, tmp_path, prefix="m", source="test")
    assert files["has_inverse"] and files["header"].name == "m.h"
    assert "modified Prandtl-Ishlinskii" in files["source"].read_text()

    (tmp_path / "main.c").write_text(DRIVER)
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", "-o",
                    "main", "main.c", "m.c", "-lm"], cwd=tmp_path, check=True)
    v = np.clip(np.cumsum(rng.normal(0, 0.1, 3000)), -2, 2)
    run = subprocess.run(["./main"], cwd=tmp_path, input="".join(f"{x!r}\n" for x in v),
                         capture_output=True, text=True, check=True)
    result = np.array([[float(x) for x in line.split()] for line in run.stdout.splitlines()])

    inverse = model.inverse()  # consistent with the exported state, like m_inverse_init
    y = model.simulate(v)
    assert np.max(np.abs(result[:, 0] - y)) <= 1e-12 * max(1.0, np.max(np.abs(y)))
    back, _ = inverse.invert(y)
    assert np.max(np.abs(result[:, 1] - back)) <= 1e-12 * max(1.0, np.max(np.abs(back)))
    assert np.max(np.abs(back - v)) < 1e-9  # and the inverse inverts


def test_float_export_and_bad_inputs(tmp_path):
    model = hyst.Model("pi", {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5]})
    hyst.export_c(model, tmp_path, prefix="f", float=True, input_min=-1.0, input_max=1.0)
    source = (tmp_path / "f.c").read_text()
    assert "typedef float f_real;" in (tmp_path / "f.h").read_text()
    assert "1.0f" in source and "-1.0f, 1.0f" in source  # the input limits, in float
    with pytest.raises(hyst.Error, match="'kp' is not supported"):
        kp = hyst.Model("kp", {"levels": 4, "lower": 0, "upper": 1, "weights": [1.0] * 10})
        hyst.export_c(kp, tmp_path)
    (tmp_path / "plain").write_text("x")
    with pytest.raises(hyst.Error, match="'.*plain' is not a folder"):
        hyst.export_c(model, tmp_path / "plain" / "ctrl")
    hyst.export_c(model, tmp_path / "new" / "ctrl", prefix="g")  # a missing folder is created
    assert (tmp_path / "new" / "ctrl" / "g.h").is_file()
