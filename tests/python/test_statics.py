"""Project.statics against `spiral statics --json`, bit for bit, for the
project as written and after an edit in Python (against the CLI run of the
file the edit was saved to); what save writes."""
import os
import shutil

import numpy as np
import pytest

import spiral
from conftest import DEEPWATER, OC4, assert_same, cli_json


@pytest.mark.parametrize("scenario", [DEEPWATER, OC4], ids=["deepwater", "oc4"])
def test_statics_at_rest_is_the_cli_document(scenario):
    assert_same(spiral.load(scenario).statics(), cli_json("statics", scenario))


def test_statics_at_an_offset_is_the_cli_document(deepwater):
    offset = [10, -5, 0.5, 0.2, -0.3, 1.5]  # m, m, m, deg, deg, deg
    s = deepwater.statics(offset=offset)
    assert_same(s, cli_json("statics", DEEPWATER, "--offset", ",".join(map(str, offset))))
    assert s.offset_6dof[5] == pytest.approx(np.radians(1.5), rel=1e-15)  # the document's rotations are in rad


def test_per_line_columns_are_numpy_arrays(deepwater):
    s = deepwater.statics(offset=[10, 0, 0, 0, 0, 0])
    assert isinstance(s.fairlead_tension_N, np.ndarray) and s.fairlead_tension_N.shape == (len(deepwater.lines),)
    assert list(s.column("lines", "name")) == list(deepwater.lines)
    assert s.fairlead_tension_N[2] == s["lines"][2]["fairlead_tension_N"]
    assert s.hull_force_6dof.shape == (6,)


def test_edited_length_matches_the_cli_run_of_the_saved_file(tmp_path):
    p = spiral.load(DEEPWATER)
    before = p.statics().fairlead_tension_N
    p.lines["L3"].segments[1].length += 2.0
    after = p.statics()
    assert after.fairlead_tension_N[2] < before[2]  # a longer line slackens
    assert np.array_equal(after.fairlead_tension_N[3:], before[3:])  # the other lines are not touched
    variant = tmp_path / "variant.yaml"
    p.save(variant)
    assert_same(after, cli_json("statics", variant))
    assert_same(spiral.load(variant).statics(), after)


def test_save_changes_only_the_edited_value(tmp_path):
    # A copy of the project beside a copy of its data: saved over itself, only the edited value may change.
    shutil.copytree(DEEPWATER.parent / "data", tmp_path / "data")
    copy = tmp_path / "deepwater-fps.yaml"
    shutil.copy(DEEPWATER, copy)
    p = spiral.load(copy)
    p.lines["L3"].segments[1].length += 2.0
    p.lines["L5"].segments[2].type = "chain147"  # as written: no change
    p.save(copy)
    original = DEEPWATER.read_text().splitlines()
    saved = copy.read_text().splitlines()
    assert len(saved) == len(original)
    changed = [(a, b) for a, b in zip(original, saved) if a != b]
    assert len(changed) == 1, changed
    assert changed[0][1] == changed[0][0].replace("length: 2490.0}", "length: 2492.0}")


def test_save_elsewhere_rewrites_relative_file_references(tmp_path):
    p = spiral.load(OC4)
    (tmp_path / "sub").mkdir()
    p.save(tmp_path / "sub" / "copy.yaml")
    text = (tmp_path / "sub" / "copy.yaml").read_text()
    # The reference names the same file from the new folder (absolute, or
    # relative when the sources and the temporary folder share a parent).
    written = next(line.split("radiation_file:")[1].split("#")[0].strip()
                   for line in text.splitlines() if "radiation_file:" in line)
    assert os.path.samefile(tmp_path / "sub" / written, OC4.parent / "data/hydro/oc4-semi/marin_semi.1"), written
    assert written != "data/hydro/oc4-semi/marin_semi.1"  # rewritten, not copied
    assert_same(spiral.load(tmp_path / "sub" / "copy.yaml").statics(), spiral.load(OC4).statics())


def test_an_edit_shared_through_a_yaml_anchor_is_refused(tmp_path):
    text = OC4.read_text()
    first = text.index("segments:")
    # Each line's segment list, given once under an anchor and aliased by the other lines.
    assert "{type: chain76, length: 835.35}" in text
    shared = text.replace("- {type: chain76, length: 835.35}", "- &seg {type: chain76, length: 835.35}", 1)
    shared = shared[:first] + shared[first:].replace("- {type: chain76, length: 835.35}", "- *seg")
    (tmp_path / "shared.yaml").write_text(shared)
    shutil.copytree(OC4.parent / "data", tmp_path / "data")
    p = spiral.load(tmp_path / "shared.yaml")
    p.lines[next(iter(p.lines))].segments[0].length += 1.0
    with pytest.raises(spiral.OutputError, match="YAML anchor"):
        p.save(tmp_path / "out.yaml")
    assert not (tmp_path / "out.yaml").exists()


def test_any_written_value_is_set_by_its_path_like_an_edit_of_the_file(tmp_path):
    p = spiral.load(OC4)
    assert p.get("site.depth") == "200.0"
    # A sea-state edit: the same numbers as the CLI run of the saved file.
    p.set("environments[1].waves.hs", 9.5)
    assert p.get("environments[1].waves.hs") == "9.5"
    p.lines["L1"].segments[0].length -= 1.0  # segment edits and field edits together
    variant = tmp_path / "hs.yaml"
    p.save(variant)
    text = variant.read_text()
    assert "hs: 9.5 " in text and "# m; S (RAFT)" in text  # in place, the comment kept
    assert_same(p.equilibrium(case="intact-raft-jonswap"),
                cli_json("equilibrium", str(variant), "--case", "intact-raft-jonswap"))
    # A value the file does not write, and one that does not read.
    with pytest.raises(KeyError, match="no value of its own"):
        p.set("environments[1].waves.gamma_not_a_key", 1.0)
    with pytest.raises(spiral.InputError, match=r"site\.depth"):
        p.set("site.depth", "deep")
