"""Project.optimize against `spiral optimize --json`, bit for bit but for wall
times, on a copy of the OC4 project (the CLI writes the optimized project
beside the one it is given); the payouts applied in Python and saved."""
import json

import spiral
from conftest import OC4, assert_same, run_cli


def test_optimization_is_the_cli_run(tmp_path):
    p = spiral.load(OC4)
    copy = tmp_path / "oc4.yaml"
    p.save(copy)
    fractions = []
    opt = p.optimize(objective="min_max_offset", progress=fractions.append)
    code, out, err = run_cli("optimize", copy, "--objective", "min_max_offset", "--json", "--out", tmp_path / "out")
    assert code in (0, 3), err
    expected = spiral._results.to_python(json.loads(out))
    expected["history"] = [{k: v for k, v in row.items() if k != "wall_s"} for row in expected["history"]]
    opt["history"] = [{k: v for k, v in row.items() if k != "wall_s"} for row in opt["history"]]
    assert_same(opt, expected)
    assert fractions and fractions[-1] == 1.0

    # The optimized top segments set in Python give the project the CLI wrote beside the copy.
    for line in opt["lines"]:
        p.lines[line["name"]].segments[-1].length = line["top_segment_after_m"]
    if opt["status"] == "optimal":
        written = spiral.load(tmp_path / "oc4.optimized.yaml")
        for name, line in p.lines.items():
            assert abs(written.lines[name].segments[-1].length - line.segments[-1].length) <= 0.5e-4  # 0.1 mm print
