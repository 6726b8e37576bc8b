"""Project.equilibrium and Project.stiffness against `spiral equilibrium
--json` and `spiral stiffness --json`, bit for bit (wall times left out)."""
import numpy as np
import pytest

from conftest import DEEPWATER, OC4, assert_same, cli_json


def test_equilibrium_of_a_case_is_the_cli_document(deepwater):
    eq = deepwater.equilibrium(case="lc1-survival-collinear-0deg")
    assert_same(eq, cli_json("equilibrium", DEEPWATER, "--case", "lc1-survival-collinear-0deg"))
    assert eq["risers"] and isinstance(eq.column("risers", "top_tension_N"), np.ndarray)
    assert eq.offset["horizontal_m"] > 0


def test_equilibrium_damaged_is_the_cli_document(oc4):
    line = next(iter(oc4.lines))
    assert_same(oc4.equilibrium(damaged=line), cli_json("equilibrium", OC4, "--damaged", line))


def test_stiffness_is_the_cli_matrix(oc4):
    expected = cli_json("stiffness", OC4, "--case", "intact-raft-jonswap")
    K = oc4.stiffness(case="intact-raft-jonswap")
    assert isinstance(K, np.ndarray) and K.shape == (6, 6)
    assert K.tobytes() == expected["stiffness_6x6"].tobytes()
    assert_same(oc4.stiffness(case="intact-raft-jonswap", full=True), expected)


def test_still_water_is_the_default_case(oc4):
    assert_same(oc4.equilibrium(), cli_json("equilibrium", OC4))
    assert oc4.equilibrium()["case"] == "still-water"
