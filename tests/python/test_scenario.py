"""Scenario files through Python: the handout experiments give `tumble run --csv`'s numbers, and a
bad file raises the CLI's message."""

import csv
import io

import numpy as np
import pytest

import tumble

COLUMNS = ["x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz",
           "kinetic", "potential"]


def cli_csv(tumble_cli, scenario, *extra):
    """The rows of `tumble run SCENARIO --csv - --quiet`, as (body names, float columns)."""
    done = tumble_cli("run", scenario, "--csv", "-", "--quiet", *extra)
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(io.StringIO(done.stdout)))
    names = [row["body"] for row in rows]
    values = {key: np.array([float(row[key]) for row in rows]) for key in ["time"] + COLUMNS}
    return names, values


def assert_same_rows(traj, names, expected, tolerance):
    assert len(traj) == len(names)
    np.testing.assert_allclose(traj["time"], expected["time"], rtol=0, atol=tolerance)
    for key in COLUMNS:
        np.testing.assert_allclose(traj[key], expected[key], rtol=tolerance, atol=tolerance,
                                   err_msg=key)


def test_friction_experiment_built_by_hand_matches_the_cli(tumble_cli, scenarios):
    # handout part 3, task 4, written out with the Python API instead of read from its file
    world = tumble.World(gravity=(0, -9.81, 0))
    world.add_ground(height=0.0)
    world.add_body(size=(2, 6, 2), mass=2.0, position=(0, 5, 0), velocity=(1, 0, 0.5),
                   angular_velocity=(1.0, 0.5, 2.0), elasticity=0.6, friction=0.5, name="rb")
    traj = world.run(duration=10.0, dt=0.004166666666666667, every=1)
    names, expected = cli_csv(tumble_cli, scenarios / "part3_task4_friction.toml")
    assert set(names) == {"rb"}
    assert_same_rows(traj, names, expected, 1e-12)
    # it does what the handout says: it comes to rest lying on a face
    assert traj["kinetic"][-1] == 0.0
    assert traj["y"][-1] == pytest.approx(1.0, abs=1e-3)


@pytest.mark.parametrize("name", [
    "part2_task2_impulses.toml", "part3_task1_impulse.toml", "part3_task2_detection.toml",
    "part3_task3_elastic_spin.toml", "part3_task4_friction.toml", "dice_three_in_tray.toml",
])
def test_scenario_run_gives_the_cli_numbers(tumble_cli, scenarios, name):
    sc = tumble.load_scenario(str(scenarios / name))
    traj = sc.run(every=5)
    names, expected = cli_csv(tumble_cli, scenarios / name, "--every", "5")
    assert [sc.bodies[i] for i in traj["body"]] == names
    assert_same_rows(traj, names, expected, 1e-12)


def test_scenario_world_goes_on_by_hand(scenarios):
    sc = tumble.load_scenario(scenarios / "part3_task4_friction.toml")
    assert sc.dt == pytest.approx(1 / 240) and sc.duration == 10.0 and sc.bodies == ["rb"]
    world = sc.world()
    (rb,) = world.bodies
    assert rb.name == "rb"
    np.testing.assert_allclose(rb.size, (2, 6, 2))
    np.testing.assert_allclose(rb.position, (0, 5, 0))
    assert rb.mass == 2.0 and rb.elasticity == 0.6 and rb.friction == 0.5


def test_overrides_are_the_clis(tumble_cli, scenarios):
    path = scenarios / "part3_task4_friction.toml"
    sc = tumble.load_scenario(path, overrides=["rb.elasticity=0.9", "world.duration=2"])
    assert sc.duration == 2.0
    traj = sc.run()
    names, expected = cli_csv(tumble_cli, path, "--set", "rb.elasticity=0.9", "--duration", "2")
    assert_same_rows(traj, names, expected, 1e-12)


def cli_error(tumble_cli, *args):
    done = tumble_cli(*args)
    assert done.returncode == 2
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("tumble: error: ")
    return line[len("tumble: error: "):]


@pytest.mark.parametrize("text", [
    "[world]\ndt = 0.01\nwobble = 3\n",
    "[world]\ndt = -1\n",
    "[[body]]\nname = \"rb\"\nmass = 0\n",
    "[world\n",
])
def test_bad_files_raise_the_clis_message(tumble_cli, tmp_path, text):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load_scenario(str(path))
    assert str(raised.value) == cli_error(tumble_cli, "run", path)
    assert isinstance(raised.value, ValueError)
    assert str(path) in str(raised.value)


def test_missing_files_and_bad_overrides_raise_the_clis_message(tumble_cli, scenarios, tmp_path):
    missing = tmp_path / "nowhere.toml"
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load_scenario(str(missing))
    assert str(raised.value) == cli_error(tumble_cli, "run", missing)
    path = scenarios / "part3_task4_friction.toml"
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load_scenario(str(path), overrides=["rb.mass=-2"])
    assert str(raised.value) == cli_error(tumble_cli, "run", path, "--set", "rb.mass=-2")
