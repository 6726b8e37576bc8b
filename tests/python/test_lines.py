"""Project.lines_under_motion against `spiral lines` (summary.json equal but for wall
times, the time series against time_series.csv to the digits it prints), a
motion given as arrays against the same motion from its file, and a bad
motion file named with its line and column."""
import csv
import json

import numpy as np
import pytest

import spiral
from conftest import OC4, assert_same, run_cli

SURGE = OC4.parent.parent / "tests" / "data" / "motion" / "oc4-two-tone-surge.csv"
CASE = "intact-still-water"


def test_lines_is_the_cli_run(oc4, tmp_path):
    fractions = []
    run = oc4.lines_under_motion(CASE, SURGE, lines=["L1", "L2"], progress=fractions.append)
    code, _, err = run_cli("lines", OC4, "--motion", SURGE, "--case", CASE, "--lines", "L1,L2", "--out", tmp_path)
    assert code == 0, err
    expected = spiral._results.to_python(json.loads((tmp_path / "summary.json").read_text()))
    summary = {k: v for k, v in run.items() if k != "time_series"}
    assert_same(spiral.Result(summary), expected)
    with open(tmp_path / "time_series.csv") as f:
        rows = list(csv.reader(f))
    assert list(run.time_series) == rows[0]
    table = np.array(rows[1:], dtype=float)
    for j, name in enumerate(rows[0]):
        np.testing.assert_allclose(run.time_series[name], table[:, j], rtol=6e-6, atol=6e-4, err_msg=name)
    assert fractions and max(fractions) == pytest.approx(1.0)


def test_a_motion_as_arrays_is_the_same_motion_as_its_file(oc4):
    with open(SURGE) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    table = np.array(rows[1:], dtype=float)
    assert rows[0][:7] == ["time_s", "surge_m", "sway_m", "heave_m", "roll_deg", "pitch_deg", "yaw_deg"]
    from_arrays = oc4.lines_under_motion(CASE, (table[:, 0], table[:, 1:7]), lines=["L1"])
    from_file = oc4.lines_under_motion(CASE, SURGE, lines=["L1"])
    np.testing.assert_array_equal(from_arrays.time_series["fairlead_tension_L1_N"],
                                  from_file.time_series["fairlead_tension_L1_N"])
    assert from_arrays["motion_file"] == "<arrays>"


def test_a_bad_motion_file_names_its_line_and_column(oc4, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("time,surge,sway,heave,roll,pitch,yaw\n0,0,0,0,0,0,0\n1,x,0,0,0,0,0\n")
    with pytest.raises(spiral.InputError, match=r"bad.csv:3:3: surge"):
        oc4.lines_under_motion(CASE, bad)
    with pytest.raises(spiral.InputError, match="--lines|lines"):
        oc4.lines_under_motion(CASE, SURGE, lines=["L9"])
