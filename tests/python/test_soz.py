"""Project.soz against `spiral soz --json` (catenary screening model, so that
the test stays quick), bit for bit but for wall times; the zones as arrays."""
import numpy as np

import spiral
from conftest import DEEPWATER, assert_same, cli_json


def test_soz_is_the_cli_document(deepwater):
    fractions = []
    z = deepwater.soz(model="catenary", step_deg=15, progress=fractions.append)
    assert_same(z, cli_json("soz", DEEPWATER, "--model", "catenary", "--step-deg", "15"))
    assert z.directions_deg.shape == (24,) and z.platform["allowable_offset_m"].shape == (24,)
    assert len(z.platform["governing_criterion"]) == 24
    assert fractions and fractions[-1] == 1.0 and fractions == sorted(fractions)


def test_soz_of_a_case_without_check_is_the_cli_document(deepwater):
    z = deepwater.soz(case="lc5-operating-45deg", model="catenary", step_deg=30, check=False)
    assert_same(z, cli_json("soz", DEEPWATER, "--case", "lc5-operating-45deg", "--model", "catenary", "--step-deg",
                            "30", "--no-check"))
    assert np.all(z.platform["allowable_offset_m"] > 0)


def test_a_bad_option_names_the_keyword(deepwater):
    try:
        deepwater.soz(model="catenary", step_deg=7, check=False)
    except spiral.InputError as error:
        assert str(error).startswith(f"{DEEPWATER}: step_deg: "), str(error)
        assert error.issues[0]["path"] == "step_deg"
    else:
        raise AssertionError("a step that does not divide 360 must raise")
    try:
        deepwater.soz(model="beam")
    except spiral.InputError as error:
        assert str(error) == f"{DEEPWATER}: model: expected one of 'fe', 'catenary', got 'beam'"
    else:
        raise AssertionError("an unknown model must raise")
