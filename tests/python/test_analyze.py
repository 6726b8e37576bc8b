"""Project.analyze against `spiral analyze` (summary.json bit for bit but for
wall times; the time series against time_series.csv to the digits the CSV
prints), the progress callback, the GIL released during the run, and
stopping a run: by an exception of the callback and by Ctrl-C (SIGINT), the
project still usable afterwards."""
import csv
import json
import os
import signal
import threading
import time

import numpy as np
import pytest

import spiral
from conftest import OC4, assert_same, run_cli

CASE = "intact-raft-jonswap"
DURATION_S = 600.0  # long enough for the statistics and the MPM fits, short enough for a quick test
# Runs to stop: the default scenario's 3-h storm takes about a second, many progress reports.
LONG_CASE = "lc1-survival-collinear-0deg"


def test_analysis_is_the_cli_run(oc4, tmp_path):
    fractions = []
    ts = oc4.analyze(case=CASE, level="sc", duration=DURATION_S, seed=3, progress=fractions.append)
    code, _, err = run_cli("analyze", OC4, "--case", CASE, "--level", "sc", "--duration", DURATION_S, "--seed", 3,
                           "--out", tmp_path)
    assert code == 0, err
    expected = spiral._results.to_python(json.loads((tmp_path / "summary.json").read_text()))
    summary = {k: v for k, v in ts.items() if k != "time_series"}
    assert_same(spiral.Result(summary), expected)
    with open(tmp_path / "time_series.csv") as f:
        rows = list(csv.reader(f))
    assert list(ts.time_series) == rows[0]
    table = np.array(rows[1:], dtype=float)
    for j, name in enumerate(rows[0]):
        # The CSV prints 6 (motions) or 7 (tensions) significant digits, positions to 0.1 mm.
        np.testing.assert_allclose(ts.time_series[name], table[:, j], rtol=6e-6, atol=6e-5, err_msg=name)
    assert ts.surge_m is ts.time_series["surge_m"]
    assert ts.channel("surge_m")["max"] == pytest.approx(ts.surge_m.max(), rel=1e-12)
    assert fractions[-1] == 1.0 and fractions == sorted(fractions)


def test_an_exception_of_the_callback_stops_the_run(deepwater):
    seen = []

    def stop_early(fraction):
        seen.append(fraction)
        if fraction > 0.1:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        deepwater.analyze(case=LONG_CASE, duration=10800.0, progress=stop_early)
    assert 1.0 not in seen
    assert deepwater.statics()["lines"]  # still usable


def test_ctrl_c_stops_the_run_with_keyboard_interrupt(deepwater, oc4):
    seen = []

    def interrupt_once(fraction):
        seen.append(fraction)
        if len(seen) == 2:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        deepwater.analyze(case=LONG_CASE, duration=10800.0, progress=interrupt_once)
    assert 1.0 not in seen
    assert oc4.analyze(case=CASE, duration=60.0, step=1.0).time_s[-1] == 60.0


def test_a_run_releases_the_gil(deepwater):
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.002)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        start = time.monotonic()
        deepwater.analyze(case=LONG_CASE, duration=3600.0)
        end = time.monotonic()
    finally:
        done.set()
        counter.join()
    during = [t for t in ticks if start < t < end]
    # Another thread runs all along, a tick every few ms; a held GIL would let it in only at the calling
    # thread's polls, every 50 ms. Twice that, to stay clear of a busy machine's scheduling.
    assert len(during) > 2 * (end - start) / 0.05, (len(during), end - start)
