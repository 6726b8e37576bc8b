"""What the Python API tests share: where the CLI and the scenarios are, a
run of the CLI, and the comparison of a Python result with the CLI's JSON.

The oracle is the `spiral` binary of the same build: the API calls the same
design functions with the same defaults, so every number must be equal to
the last bit (the JSON text round-trips doubles exactly). Only wall-clock
times differ between two runs; they are left out of the comparison."""
import json
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import spiral

SOURCE_DIR = pathlib.Path(os.environ.get("SPIRAL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
EXECUTABLE = os.environ.get("SPIRAL_EXECUTABLE", str(SOURCE_DIR / "build" / "app" / "spiral"))
DEEPWATER = SOURCE_DIR / "scenarios" / "deepwater-fps.yaml"
OC4 = SOURCE_DIR / "scenarios" / "oc4-semisubmersible.yaml"

# Keys that hold wall-clock time: they differ between any two runs.
TIMING_KEYS = {"wall_time_s", "wall_s", "equilibrium_wall_s", "stiffness_wall_s", "zone_wall_s", "check_wall_s",
               "time_per_solve_s", "timing_s"}


def run_cli(*args, cwd=None):
    """`spiral ARGS...`: (exit code, stdout, stderr)."""
    done = subprocess.run([EXECUTABLE, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    return done.returncode, done.stdout, done.stderr


def cli_json(*args, cwd=None):
    """The JSON document `spiral ARGS... --json` prints, as the API returns documents."""
    code, out, err = run_cli(*args, "--json", cwd=cwd)
    assert code == 0, err
    return spiral._results.to_python(json.loads(out))


def assert_same(actual, expected, path="document"):
    """`actual` equals `expected` bit for bit (NaN equal to NaN), timing keys left out."""
    if isinstance(expected, dict):
        assert isinstance(actual, dict), f"{path}: {type(actual).__name__} instead of a dict"
        keys = set(expected) - TIMING_KEYS
        assert set(actual) - TIMING_KEYS == keys, f"{path}: keys differ: {sorted(set(actual) ^ set(expected))}"
        for key in keys:
            assert_same(actual[key], expected[key], f"{path}.{key}")
    elif isinstance(expected, np.ndarray):
        assert isinstance(actual, np.ndarray) and actual.shape == expected.shape, f"{path}: shape differs"
        assert actual.dtype == expected.dtype and actual.tobytes() == expected.tobytes(), f"{path}: values differ"
    elif isinstance(expected, list):
        assert isinstance(actual, list) and len(actual) == len(expected), f"{path}: length differs"
        for i, (a, e) in enumerate(zip(actual, expected)):
            assert_same(a, e, f"{path}[{i}]")
    elif isinstance(expected, float) and math.isnan(expected):
        assert isinstance(actual, float) and math.isnan(actual), f"{path}: {actual} instead of NaN"
    elif isinstance(expected, float):
        same_bits = actual == expected and math.copysign(1.0, actual) == math.copysign(1.0, expected)
        assert type(actual) is float and same_bits, f"{path}: {actual!r} instead of {expected!r}"
    else:
        assert type(actual) is type(expected) and actual == expected, f"{path}: {actual!r} instead of {expected!r}"


@pytest.fixture(scope="session")
def deepwater():
    return spiral.load(DEEPWATER)


@pytest.fixture(scope="session")
def oc4():
    return spiral.load(OC4)
