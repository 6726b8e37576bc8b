"""Errors: bad input raises InputError with the CLI's message (file:line:col:
field: problem), an edited value is validated where it was written, a request
naming what the project lacks names the keyword, a solver failure raises
SolverError."""
import pytest

import spiral
from conftest import DEEPWATER, OC4, run_cli


def broken_copy(tmp_path, old, new):
    text = OC4.read_text()
    assert old in text
    path = tmp_path / "broken.yaml"
    path.write_text(text.replace(old, new, 1).replace("data/hydro", str(OC4.parent / "data" / "hydro")))
    return path


def test_bad_file_raises_with_the_cli_message(tmp_path):
    path = broken_copy(tmp_path, "length: 835.35}", "length: -835.35, colour: red}")
    with pytest.raises(spiral.InputError) as raised:
        spiral.load(path)
    code, _, err = run_cli("validate", path)
    assert code == 2
    assert str(raised.value) == err.strip()
    first = raised.value.issues[0]
    assert first["file"] == str(path) and first["line"] == 54 and first["column"] > 0
    assert str(raised.value).startswith(f"{path}:54:")


def test_missing_file_raises_input_error(tmp_path):
    with pytest.raises(spiral.InputError, match="project file not found"):
        spiral.load(tmp_path / "none.yaml")


def test_edited_value_is_validated_at_its_position():
    p = spiral.load(OC4)
    p.lines["L2"].segments[0].length = -20.0
    with pytest.raises(spiral.InputError) as raised:
        p.statics()
    assert str(raised.value).startswith(f"{OC4}:59:")
    assert "mooring.lines[1].segments[0].length" in str(raised.value) and "-20" in str(raised.value)
    with pytest.raises(spiral.InputError):
        p.save("never-written.yaml")
    p.lines["L2"].segments[0].type = "no-such-type"
    p.lines["L2"].segments[0].length = 835.35
    with pytest.raises(spiral.InputError, match="no-such-type"):
        p.equilibrium()


def test_unknown_case_names_the_keyword(oc4):
    with pytest.raises(spiral.InputError) as raised:
        oc4.equilibrium(case="no-such-case")
    assert str(raised.value).startswith(f"{OC4}: case: ")
    code, _, err = run_cli("equilibrium", OC4, "--case", "no-such-case")
    assert code == 2 and err.strip() == str(raised.value).replace(": case: ", ": --case: ", 1)


def test_unknown_line_is_a_key_error(oc4):
    with pytest.raises(KeyError, match="L1, L2, L3"):
        oc4.lines["L9"]


def test_solver_failure_raises_solver_error(tmp_path):
    p = spiral.load(OC4)
    offset = [2000, 0, 0, 0, 0, 0]  # the fairleads far beyond the lines' reach
    code, _, err = run_cli("statics", OC4, "--offset", ",".join(map(str, offset)))
    assert code == 3, err
    with pytest.raises(spiral.SolverError) as raised:
        p.statics(offset=offset)
    assert err.startswith("solver failure: " + str(raised.value).splitlines()[0])
    assert isinstance(raised.value, spiral.Error) and isinstance(raised.value, RuntimeError)
