"""N-point systems from Python: validation messages, and the N-point rate problem against
answers it must reproduce without any N-point closed form (docs/model.md, "N contact points"):
N = 1 gives the one-point answers; a block-diagonal A (points that do not interact) gives the
Cartesian product of the one-point solution sets; the fast direction counts agree with the
full solves."""
import itertools
import math
import os
import pickle

import numpy as np
import pytest

import cpkit
from conftest import SOURCE_DIR


def one_point_system(p, state="b"):
    A = np.array([[p.a11, p.a12], [p.a12, p.a22]])
    return cpkit.ContactSystem(A, [{"state": state, "mu": p.mu, "C_T": p.C_T}])


def random_params(rng):
    a11, a22 = rng.uniform(0.2, 3, 2)
    a12 = rng.uniform(-0.95, 0.95) * math.sqrt(a11 * a22)
    return cpkit.ContactParameters(a11=a11, a12=a12, a22=a22, mu=rng.uniform(0.1, 4),
                                   C_T=float(rng.choice([0.0, rng.uniform(0, 2)])))


def test_one_point_system_is_the_one_point_problem():
    rng = np.random.default_rng(5)
    for _ in range(100):
        p = random_params(rng)
        th = rng.uniform(0, 2 * math.pi)
        dF = np.array([math.cos(th), math.sin(th)])
        one = cpkit.solve_rate_problem(p, "b", dF)
        sys_ = cpkit.solve_rate_problem(one_point_system(p), dF)
        assert sys_.complete and sys_.count == one.count, (p, dF)
        assert sorted(t for s in sys_.solutions for t in s.types) == \
            sorted(s.type for s in one.solutions)
        for a in one.solutions:
            if a.kind != "point":
                continue
            match = [b for b in sys_.solutions if b.types == [a.type]]
            assert match and all(match[0].start[k][0] == pytest.approx(v, abs=1e-9)
                                 for k, v in a.start.items())


def test_block_diagonal_system_is_the_product():
    rng = np.random.default_rng(9)
    for _ in range(40):
        p1, p2 = random_params(rng), random_params(rng)
        A = np.zeros((4, 4))
        A[:2, :2] = [[p1.a11, p1.a12], [p1.a12, p1.a22]]
        A[2:, 2:] = [[p2.a11, p2.a12], [p2.a12, p2.a22]]
        s = cpkit.ContactSystem(A, [{"state": "b", "mu": p1.mu, "C_T": p1.C_T},
                                    {"state": "b", "mu": p2.mu, "C_T": p2.C_T}])
        dF = rng.normal(size=4)
        r1 = cpkit.solve_rate_problem(p1, "b", dF[:2])
        r2 = cpkit.solve_rate_problem(p2, "b", dF[2:])
        r = cpkit.solve_rate_problem(s, dF)
        if r1.infinite or r2.infinite:
            continue
        assert r.count == r1.count * r2.count
        expected = sorted(f"{a.type}/{b.type}" for a, b in itertools.product(r1.solutions, r2.solutions))
        assert sorted("/".join(x.types) for x in r.solutions) == expected
        pickle.loads(pickle.dumps(r))


def test_direction_counts_agree_with_full_solves():
    s = cpkit.ContactSystem.from_file(os.path.join(SOURCE_DIR, "docs", "examples",
                                                   "three_point_punch.json"))
    theta = np.linspace(0, 2 * math.pi, 37)[:-1] + 0.01
    fast = cpkit.system_direction_counts(s, theta)
    e1, e2 = s.patterns
    for j, th in enumerate(theta):
        full = cpkit.solve_rate_problem(s, math.cos(th) * e1 + math.sin(th) * e2)
        assert fast["count"][j] == full.count


def test_system_input_errors():
    with pytest.raises(ValueError, match="point 2: mu"):
        cpkit.ContactSystem(np.eye(4), [{"state": "b", "mu": 1}, {"state": "b", "mu": -1}])
    with pytest.raises(ValueError, match="not positive definite"):
        cpkit.ContactSystem([[1, 2], [2, 1]], [{"state": "b", "mu": 1}])
    with pytest.raises(ValueError, match="need 2N"):
        cpkit.ContactSystem(np.eye(4), [{"state": "b", "mu": 1}])
    with pytest.raises(ValueError, match="unknown key"):
        cpkit.ContactSystem(np.eye(2), [{"state": "b", "mu": 1, "friction": 1}])
    with pytest.raises(ValueError, match="NaN"):
        cpkit.ContactSystem([[np.nan, 0], [0, 1]], [{"state": "b", "mu": 1}])
    s = cpkit.ContactSystem(np.eye(2), [{"state": "b", "mu": 1}])
    with pytest.raises(ValueError):
        cpkit.solve_rate_problem(s, [1.0, 2.0, 3.0])


@pytest.mark.parametrize("name, dF", [
    ("three_point_punch", None),
    ("two_point_system", None),
    ("two_point_system", [0.3, 1.0, -0.2, 1.0]),
])
def test_system_rate_agrees_with_the_cli(name, dF):
    from conftest import run_cli
    path = os.path.join(SOURCE_DIR, "docs", "examples", name + ".json")
    args = ["rate", "--system", path, "--json"]
    if dF is not None:
        args[3:3] = ["--dF", *dF]
    _, cli = run_cli(*args, expect=(0, 1))
    s = cpkit.ContactSystem.from_file(path)
    r = cpkit.solve_rate_problem(s, s.dF if dF is None else np.array(dF))
    assert r.complete == cli["complete"]
    assert (r.count if r.count >= 0 else "inf") == cli["count"]
    assert len(r.solutions) == len(cli["solutions"])
    for mine, theirs in zip(r.solutions, cli["solutions"]):
        assert mine.types == theirs["types"] and mine.kind == theirs["kind"]
        if theirs["kind"] == "point":
            for key, values in theirs["values"].items():
                np.testing.assert_allclose(mine.start[key], values, atol=1e-12)


def test_deeply_nested_file_is_a_value_error(tmp_path):
    # issue 24, item 15: 10^6 nested brackets (2 MB) crashed the interpreter (SIGSEGV)
    deep = "[" * 1_000_000 + "]" * 1_000_000
    for text in (deep, '{"A": ' + deep + '}', '{"dim": 3, "A": ' + deep + '}'):
        path = tmp_path / "deep.json"
        path.write_text(text)
        with pytest.raises(ValueError, match="nesting deeper than 64 levels"):
            cpkit.ContactSystem.from_file(str(path))
