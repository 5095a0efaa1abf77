"""Systems are passed as parsed objects (issue 25): a ContactSystem / ContactSystem3d is read ONCE
by the C++ reader and every call receives the parsed system. Checked against the `cpkit` program
of the same build (`cpkit rate --system F --json` reads the file itself: an independent route),
after the file has been overwritten (a re-read would see the new file), by counting the
serialisations to JSON text (none per call), and with bad input still a ValueError naming the
field."""
import copy
import json
import os
import pickle

import numpy as np
import pytest

import cpkit
from conftest import SOURCE_DIR, run_cli

EXAMPLES = os.path.join(SOURCE_DIR, "docs", "examples")


def assert_2d_equals_cli(r, cli):
    assert r.complete == cli["complete"]
    assert (r.count if r.count >= 0 else "inf") == cli["count"]
    assert len(r.solutions) == len(cli["solutions"])
    for mine, theirs in zip(r.solutions, cli["solutions"]):
        assert mine.types == theirs["types"] and mine.kind == theirs["kind"]
        if theirs["kind"] == "point":
            for key, values in theirs["values"].items():
                np.testing.assert_allclose(mine.start[key], values, atol=1e-12)


def assert_3d_equals_cli(r, cli):
    assert r.complete == cli["complete"] and r.count == cli["count"] == len(cli["solutions"])
    for mine, theirs in zip(r.solutions, cli["solutions"]):
        assert mine["types"] == theirs["types"]
        for key, values in theirs["values"].items():
            np.testing.assert_allclose([x[key] for x in mine["rates"]], values, atol=1e-10)


def test_2d_from_file_answers_as_the_cli_read_before_the_file_changed(tmp_path):
    # The CLI answer of the original file; then the file is replaced by another system (mu of
    # both points 0.1, so the answer differs: checked) and the object must still answer as the
    # original.
    src = os.path.join(EXAMPLES, "coupled_grazing_points.json")
    path = tmp_path / "system.json"
    path.write_text(open(src).read())
    dF = [1.0, 0.5, -0.3, 1.0]
    _, before = run_cli("rate", "--system", path, "--dF", *dF, "--json", expect=(0, 1))
    s = cpkit.ContactSystem.from_file(path)
    doc = json.loads(open(src).read())
    for p in doc["points"]:
        p["mu"] = 0.1
    path.write_text(json.dumps(doc))
    _, after = run_cli("rate", "--system", path, "--dF", *dF, "--json", expect=(0, 1))
    assert [x["types"] for x in after["solutions"]] != [x["types"] for x in before["solutions"]]
    for _ in range(3):
        assert_2d_equals_cli(cpkit.solve_system_rate(s, np.array(dF)), before)
    # a pickled copy is parsed again from its fields: the same answers
    for other in (pickle.loads(pickle.dumps(s)), copy.deepcopy(s)):
        assert_2d_equals_cli(cpkit.solve_system_rate(other, np.array(dF)), before)


@pytest.mark.parametrize("dF", [[1.0, 0.5, -0.3, 1.0], [-1.0, 0.2, 0.8, 0.3], [0.3, -1.0, 0.1, 0.4]])
def test_2d_object_built_in_python_agrees_with_the_cli(dF):
    doc = json.load(open(os.path.join(EXAMPLES, "coupled_grazing_points.json")))
    s = cpkit.ContactSystem(np.array(doc["A"]), doc["points"], name=doc["name"])
    _, cli = run_cli("rate", "--system", os.path.join(EXAMPLES, "coupled_grazing_points.json"),
                     "--dF", *dF, "--json", expect=(0, 1))
    assert_2d_equals_cli(cpkit.solve_system_rate(s, np.array(dF)), cli)


def test_2d_edits_are_assigned_not_in_place():
    s = cpkit.ContactSystem(np.eye(4), [{"state": "b", "mu": 1}, {"state": "b", "mu": 1}])
    with pytest.raises(ValueError):  # a read-only array: the parsed system would not see it
        s.A[0, 0] = 2.0
    with pytest.raises(TypeError, match="read-only"):
        s.points[1]["mu"] = -1
    with pytest.raises(TypeError, match="read-only"):
        s.points.append({"state": "b", "mu": 1})
    # assigning a field is seen: it is parsed (and validated) at the next call, as before
    s.points = [dict(s.points[0]), dict(s.points[1], mu=-1)]
    with pytest.raises(ValueError, match="point 2: mu"):
        cpkit.solve_system_rate(s, np.ones(4))
    s.points = [dict(s.points[0]), dict(s.points[1], mu=2.0)]
    # identity stiffness, grazing points, dF = (0, 1) per point: each point sticks with
    # dP = dF (hand calculation: dw = 0 satisfies F - P = A w with P = F inside the cone)
    r = cpkit.solve_system_rate(s, np.array([0.0, 1.0, 0.0, 1.0]))
    assert r.complete and r.count == 1 and r.solutions[0].types == ["stick", "stick"]
    np.testing.assert_allclose(r.solutions[0].start["dP_N"], [1.0, 1.0], atol=1e-14)
    assert s.points[1]["mu"] == 2.0


def test_3d_system_is_parsed_once_and_agrees_with_the_cli(tmp_path):
    src = os.path.join(EXAMPLES, "two_point_system_3d.json")
    path = tmp_path / "system3d.json"
    path.write_text(open(src).read())
    _, cli = run_cli("rate", "--system", path, "--facets", 8, "--json", expect=(0, 1))
    s = cpkit.ContactSystem3d.from_file(path)
    assert s.n_points == 2
    path.write_text("{ not a system")  # a re-read would now fail
    for r in (cpkit.solve_system_rate_3d(s, facets=8),
              cpkit.solve_system_rate_3d(cpkit.ContactSystem3d(json.load(open(src))), facets=8),
              cpkit.solve_system_rate_3d(cpkit.ContactSystem3d.from_dict(json.load(open(src))), 8),
              cpkit.solve_system_rate_3d(pickle.loads(pickle.dumps(s)), facets=8),
              cpkit.solve_system_rate_3d(copy.deepcopy(s), facets=8),
              cpkit.solve_system_rate_3d(src, facets=8)):
        assert_3d_equals_cli(r, cli)


def test_3d_maps_take_the_object():
    # the sphere map through the object, the path and the CLI's own reading of the file
    path = os.path.join(EXAMPLES, "sphere_point_3d.json")
    s = cpkit.ContactSystem3d.from_file(path)
    m = cpkit.sphere_map_3d(s, n_beta=5, n_gamma=8)
    _, cli = run_cli("map", "--kind", "sphere", "--system", path, "--n", 5, "--n2", 8, "--json",
                     expect=(0, 1, 5))
    assert cli["cells"] == 40 and cli["incomplete_cells"] == m.incomplete_cells == 0
    assert m.count_cells == {c["count"]: c["cells"] for c in cli["counts"]}
    assert m.type_cells == {c["types"]: c["cells"] for c in cli["types"]}
    assert np.array_equal(cpkit.sphere_map_3d(path, n_beta=5, n_gamma=8).count, m.count)
    q = cpkit.param_direction_map_3d(s, "mu", 1.0, 5.0, n=3, theta_n=8)
    assert np.array_equal(q.count, cpkit.param_direction_map_3d(path, "mu", 1.0, 5.0, n=3,
                                                                theta_n=8).count)


def test_bad_3d_input_names_the_field(tmp_path):
    doc = json.load(open(os.path.join(EXAMPLES, "two_point_system_3d.json")))
    doc["points"][1]["mu"] = -1
    with pytest.raises(ValueError, match="mu"):
        cpkit.ContactSystem3d(doc)
    with pytest.raises(ValueError, match="mu"):
        cpkit.solve_system_rate_3d(doc, facets=8)
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(ValueError, match="mu"):
        cpkit.ContactSystem3d.from_file(path)
    with pytest.raises(TypeError):
        cpkit.ContactSystem3d.from_dict("not a dict")


def test_no_json_text_on_the_call_path(monkeypatch):
    # Before, every call serialised the system (to_json) and C++ parsed the text again; count
    # the serialisations: none per call now, one after a field is assigned (then parsed again).
    calls = []
    to_json = cpkit.ContactSystem.to_json
    monkeypatch.setattr(cpkit.ContactSystem, "to_json", lambda self: calls.append(1) or to_json(self))
    s = cpkit.ContactSystem(np.eye(4), [{"state": "b", "mu": 1}, {"state": "b", "mu": 1}],
                            patterns=(np.eye(4)[0], np.eye(4)[1]))
    assert len(calls) == 1
    for _ in range(5):
        cpkit.solve_system_rate(s, np.ones(4))
        cpkit.solve_rate_problem(s, np.ones(4))
        cpkit.system_direction_counts(s, [0.0, 1.0])
    assert len(calls) == 1
    s.criterion = "35"
    cpkit.solve_system_rate(s, np.ones(4))
    cpkit.solve_system_rate(s, np.ones(4))
    assert len(calls) == 2 and s.criterion == "35"
    # 3-D: the object is never turned back into text; a dict is, once per call
    texts = []
    system_text = cpkit.system.system_text
    monkeypatch.setattr(cpkit.system, "system_text", lambda x: texts.append(1) or system_text(x))
    doc = json.load(open(os.path.join(EXAMPLES, "two_point_system_3d.json")))
    s3 = cpkit.ContactSystem3d(doc)
    assert len(texts) == 1
    for _ in range(3):
        cpkit.solve_system_rate_3d(s3, facets=8)
    assert len(texts) == 1
    cpkit.solve_system_rate_3d(doc, facets=8)
    assert len(texts) == 2
