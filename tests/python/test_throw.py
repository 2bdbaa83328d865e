"""tumble.throw: the same throws as `tumble throw` for the same seed, and its statistics."""

import csv
import json
import re

import numpy as np
import pytest

import tumble

THROWS = 96


@pytest.fixture(scope="module")
def result(scenarios):
    return tumble.throw(str(scenarios / "dice_cube.toml"), throws=THROWS, seed=7, threads=2)


def test_throws_are_the_clis(result, tumble_cli, scenarios, tmp_path):
    done = tumble_cli("throw", scenarios / "dice_cube.toml", "--throws", THROWS, "--seed", 7,
                      "--csv", tmp_path / "throws.csv", "--summary-json", tmp_path / "sum.json")
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader((tmp_path / "throws.csv").open()))
    faces = [tumble.FACES[i] if i >= 0 else "unsettled" for i in result.face_down]
    assert faces == [row["face"] for row in rows]
    rest = [float(row["rest_time"]) if row["rest_time"] else np.nan for row in rows]
    np.testing.assert_array_equal(result.rest_time, rest)
    summary = json.loads((tmp_path / "sum.json").read_text())
    assert summary["throws"] == result.throws == THROWS
    assert [summary["faces"][f] for f in result.faces] == list(result.counts)
    assert summary["unsettled"] == result.unsettled
    # the console table's intervals and chi-square test are the result's
    table = dict(re.findall(r"^(\S\S)\s+\d+\s+\S+\s+(\[.*\])$", done.stdout, re.M))
    for face, (low, high) in zip(result.faces, result.wilson(0.95)):
        assert table[face] == f"[{low:.6f}, {high:.6f}]"
    statistic, p = result.chi_square()
    assert f"X^2 = {statistic:.4f}, p = " in done.stdout


def test_threads_do_not_change_the_throws(result, scenarios):
    again = tumble.throw(tumble.load_scenario(scenarios / "dice_cube.toml"), throws=THROWS,
                         seed=7, threads=1)
    np.testing.assert_array_equal(again.face_down, result.face_down)
    np.testing.assert_array_equal(again.rest_time, result.rest_time)
    other = tumble.throw(scenarios / "dice_cube.toml", throws=THROWS, seed=8, threads=1)
    assert not np.array_equal(other.rest_time, result.rest_time)


def test_statistics(result):
    assert result.counts.sum() + result.unsettled == THROWS
    intervals = result.wilson(0.95)
    assert intervals.shape == (6, 2)
    assert np.all(intervals[:, 0] <= result.probabilities)
    assert np.all(result.probabilities <= intervals[:, 1])
    # a wider confidence gives a wider interval
    assert np.all(np.diff(result.wilson(0.99), axis=1) > np.diff(intervals, axis=1))
    statistic, p = result.chi_square()
    expected = result.settled / 6
    assert statistic == pytest.approx(((result.counts - expected) ** 2 / expected).sum())
    assert 0.0 <= p <= 1.0


def test_a_scenario_without_throw_raises_the_clis_message(tumble_cli, scenarios):
    path = scenarios / "part3_task4_friction.toml"
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.throw(str(path), throws=10)
    done = tumble_cli("throw", path, "--throws", 10)
    assert done.stderr.strip() == "tumble: error: " + str(raised.value)
    with pytest.raises(ValueError):
        tumble.throw(str(path.with_name("dice_cube.toml")), throws=0)
