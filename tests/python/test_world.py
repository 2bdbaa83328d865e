"""tumble.World through Python: closed forms, handles, impulses, inputs and collisions."""

import pathlib

import numpy as np
import pytest

import tumble

G = 9.81


def test_version_is_the_projects():
    text = (pathlib.Path(__file__).parents[2] / "CMakeLists.txt").read_text()
    assert f"project(tumble VERSION {tumble.__version__} " in text


@pytest.mark.parametrize("dt", [1 / 60, 1 / 240, 1 / 1000])
def test_free_fall_matches_the_closed_form(dt):
    # the exact integrator moves the centre under gravity exactly: y = y0 + v0 t - g t^2 / 2
    world = tumble.World(gravity=(0, -G, 0))
    rb = world.add_body(position=(0, 100, 0), velocity=(1, 3, 0), angular_velocity=(0, 0, 0.5))
    traj = world.run(duration=2.0, dt=dt, every=1)
    t = traj["time"]
    assert t[-1] == pytest.approx(2.0, abs=1e-12)
    np.testing.assert_allclose(traj["y"], 100 + 3 * t - 0.5 * G * t**2, rtol=0, atol=1e-11)
    np.testing.assert_allclose(traj["x"], t, rtol=0, atol=1e-12)
    np.testing.assert_allclose(traj["vy"], 3 - G * t, rtol=0, atol=1e-11)
    # no torque: the spin and the kinetic plus potential energy stay as they were
    np.testing.assert_allclose(traj["wz"], 0.5, rtol=0, atol=1e-12)
    energy = traj["kinetic"] + traj["potential"]
    np.testing.assert_allclose(energy, energy[0], rtol=1e-12)
    assert rb.position[1] == traj["y"][-1]


def test_run_samples_like_the_cli_csv():
    world = tumble.World()
    world.add_body(position=(0, 10, 0))
    world.add_body(size=(1, 1, 1), position=(5, 0, 0), motion="static")
    traj = world.run(duration=1.0, dt=0.01, every=30)
    # before the first step, every 30 steps, and the final state: one row per dynamic body
    np.testing.assert_allclose(traj["time"], [0.0, 0.3, 0.6, 0.9, 1.0], atol=1e-12)
    assert set(traj["body"]) == {0}
    assert traj.dtype.names == ("time", "body", "x", "y", "z", "qw", "qx", "qy", "qz", "vx",
                                "vy", "vz", "wx", "wy", "wz", "kinetic", "potential")
    # a duration that is not a whole number of steps ends on a shortened step
    world = tumble.World()
    world.add_body()
    assert world.run(duration=0.025, dt=0.01)["time"][-1] == 0.025


def test_inverse_inertia_is_rotated_with_the_body():
    world = tumble.World()
    angle = 0.7
    q = (np.cos(angle / 2), 0, 0, np.sin(angle / 2))
    rb = world.add_body(size=(2, 6, 2), mass=2.0, orientation=q)
    w, h, d, m = 2.0, 6.0, 2.0, 2.0
    body_inverse = np.diag([12 / (m * (h * h + d * d)), 12 / (m * (w * w + d * d)),
                            12 / (m * (w * w + h * h))])
    c, s = np.cos(angle), np.sin(angle)
    rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    np.testing.assert_allclose(rb.inverse_inertia_world, rotation @ body_inverse @ rotation.T,
                               atol=1e-14)
    np.testing.assert_allclose(rb.inverse_inertia_world @ rb.inertia_world, np.eye(3), atol=1e-12)
    np.testing.assert_allclose(rb.orientation, q, atol=1e-15)


def test_impulse_changes_velocity_and_spin_as_the_handout_says():
    world = tumble.World(gravity=(0, 0, 0))
    rb = world.add_body(size=(2, 6, 2), mass=2.0, position=(0, 5, 0))
    impulse, offset = np.array([-4.0, 0, 0]), np.array([0, -1.0, 0])
    world.apply_impulse(rb, impulse=impulse, offset=offset)
    np.testing.assert_allclose(rb.velocity, impulse / 2.0, atol=1e-15)
    np.testing.assert_allclose(rb.angular_velocity,
                               rb.inverse_inertia_world @ np.cross(offset, impulse), atol=1e-15)


def test_a_stale_handle_raises_instead_of_crashing():
    world = tumble.World()
    rb = world.add_body(name="gone")
    kept = world.add_body()
    world.remove_body(rb)
    assert not rb.alive and kept.alive
    assert world.bodies == [kept]
    for read in (lambda: rb.position, lambda: rb.inverse_inertia_world, lambda: rb.energy):
        with pytest.raises(tumble.StaleBodyError, match="gone"):
            read()
    with pytest.raises(tumble.StaleBodyError):
        world.apply_impulse(rb, impulse=(1, 0, 0))
    with pytest.raises(tumble.StaleBodyError):
        world.remove_body(rb)
    # the freed slot is reused by a new body; the old handle stays stale
    world.add_body()
    with pytest.raises(tumble.StaleBodyError):
        rb.velocity = (1, 0, 0)
    # a handle keeps its world alive after the World object is gone
    del world
    assert kept.world.bodies[0] == kept


@pytest.mark.parametrize("kwargs, message", [
    ({"mass": -1.0}, "mass"),
    ({"mass": float("nan")}, "mass"),
    ({"size": (1, 0, 1)}, "size"),
    ({"position": (0, float("inf"), 0)}, "position"),
    ({"orientation": (0, 0, 0, 0)}, "orientation"),
    ({"elasticity": 1.5}, "elasticity"),
    ({"friction": -0.1}, "friction"),
    ({"motion": "wobbly"}, "motion"),
    ({"motion": "static", "velocity": (1, 0, 0)}, "static"),
])
def test_bad_bodies_raise_value_errors(kwargs, message):
    with pytest.raises(ValueError, match=message):
        tumble.World().add_body(**kwargs)


def test_unknown_arguments_and_static_bodies_are_refused():
    world = tumble.World()
    with pytest.raises(TypeError):
        world.add_body(colour="red")
    wall = world.add_body(size=(0.1, 1, 4), position=(2, 0.5, 0), motion="static")
    assert wall.motion == "static"
    with pytest.raises(ValueError, match="static"):
        wall.velocity = (1, 0, 0)
    with pytest.raises(ValueError, match="static"):
        world.apply_impulse(wall, impulse=(1, 0, 0))
    with pytest.raises(ValueError):
        world.run(duration=1.0, dt=0.0)


def test_collisions_report_the_last_steps_impact():
    world = tumble.World()
    world.add_ground(height=0.0)
    rb = world.add_body(position=(0, 1.5, 0), elasticity=0.5, friction=0.5)
    for _ in range(240):
        world.step(1 / 240)
        if world.collisions:
            break
    (hit,) = world.collisions
    assert hit.body == rb and hit.other is None and hit.plane is None
    np.testing.assert_allclose(hit.normal, (0, 1, 0))
    assert hit.points.shape == (4, 3)
    np.testing.assert_allclose(hit.points[:, 1], 0.0, atol=2e-2)
    assert hit.approach_speed > 0 and hit.normal_impulse[1] > 0
    assert hit.kinetic_energy_after < hit.kinetic_energy_before
    # a flat face hitting flat ground bounces straight up at e times the approach speed, then
    # gravity acts for the rest of the step after the time of impact
    after = 0.5 * hit.approach_speed - 9.81 * (world.time - hit.time)
    assert rb.velocity[1] == pytest.approx(after, rel=1e-9)


def test_a_plane_and_a_wall_stop_a_sliding_box():
    world = tumble.World()
    world.add_ground()
    index = world.add_plane(point=(3, 0, 0), normal=(-2, 0, 0))
    assert index == 0
    rb = world.add_body(position=(0, 1, 0), velocity=(6, 0, 0), friction=0.0, elasticity=0.0)
    world.run(duration=3.0)
    assert rb.position[0] == pytest.approx(2.0, abs=1e-2)


def test_the_soft_solver_is_chosen_by_name_and_stacks_on_its_springs():
    # docs/physics/12-soft-step.md (12.2a): two unit cubes of mass 1 on the ground; the ground's
    # 60 Hz corner springs (effective mass 1/4, four corners) hold their weight 2 g at a depth
    # of 2 g / (4 * 1/4 * (2 pi 60)^2)
    with pytest.raises(ValueError, match="solver"):
        tumble.World(solver="squishy")
    world = tumble.World(solver="soft", allow_sleep=False)
    world.add_ground()
    bottom = world.add_body(size=(1, 1, 1), mass=1.0, position=(0, 0.5, 0), elasticity=0.0)
    world.add_body(size=(1, 1, 1), mass=1.0, position=(0, 1.5, 0), elasticity=0.0)
    world.run(duration=3.0, dt=1 / 60)
    depth = 2 * 9.81 / (4 * 0.25 * (2 * np.pi * 60) ** 2)
    assert 0.5 - bottom.position[1] == pytest.approx(depth, rel=0.02)


def test_gravity_and_help_are_there():
    world = tumble.World(gravity=(0, -1.62, 0))
    np.testing.assert_allclose(world.gravity, (0, -1.62, 0))
    world.gravity = (0, -9.81, 0)
    np.testing.assert_allclose(world.gravity, (0, -9.81, 0))
    assert "add_body" in tumble.World.__dict__
    assert "orientation" in tumble.World.add_body.__doc__
    assert "KeyboardInterrupt" in tumble.World.run.__doc__
