"""The long calls: the GIL is released while they run, Ctrl-C stops them with the partial result,
progress is reported, a world in use by a run refuses other calls, and worlds do not leak."""

import _thread
import gc
import threading
import time

import numpy as np
import pytest

import tumble


def busy_world(bodies=40):
    """Bodies tumbling on the ground that never sleep: every step costs the same."""
    world = tumble.World(allow_sleep=False)
    world.add_ground()
    for i in range(bodies):
        world.add_body(size=(1, 1, 1), position=(3 * i, 2, 0), angular_velocity=(1, 2, 3))
    return world


def test_a_python_thread_keeps_running_during_a_run():
    stamps = []
    stop = threading.Event()

    def count():
        # a time stamp every 1000 turns of a pure-Python loop, which needs the GIL
        n = 0
        while not stop.is_set():
            n += 1
            if n % 1000 == 0:
                stamps.append(time.perf_counter())

    thread = threading.Thread(target=count)
    thread.start()
    while not stamps:
        time.sleep(0.001)
    world = busy_world()
    started = time.perf_counter()
    world.run(duration=40.0)
    ended = time.perf_counter()
    stop.set()
    thread.join()
    assert ended - started > 0.2
    # the thread ran in the middle of the run, not only before and after it (a run holding the
    # GIL leaves no stamps there: the thread gets it back only when the run returns)
    margin = 0.1 * (ended - started)
    inside = [t for t in stamps if started + margin < t < ended - margin]
    assert len(inside) > 20


def interrupt_after(seconds):
    timer = threading.Timer(seconds, _thread.interrupt_main)
    timer.start()
    return timer


def test_ctrl_c_stops_a_run_and_keeps_what_it_computed():
    world = busy_world()
    timer = interrupt_after(0.3)
    started = time.perf_counter()
    with pytest.raises(KeyboardInterrupt) as raised:
        world.run(duration=1000.0, every=240)
    timer.join()
    assert time.perf_counter() - started < 5.0
    partial = raised.value.partial
    assert 0.0 < partial["time"][-1] < 1000.0
    # the world stays where the run stopped, and its last sample is that state
    assert world.time == pytest.approx(partial["time"][-1], abs=1e-6)
    last = partial[partial["time"] == partial["time"][-1]]
    np.testing.assert_array_equal(last["x"], [rb.position[0] for rb in world.bodies])
    # and it can go on
    assert len(world.run(duration=0.1)) > 0


def test_ctrl_c_stops_throws_with_the_finished_ones(scenarios):
    timer = interrupt_after(0.5)
    with pytest.raises(KeyboardInterrupt) as raised:
        tumble.throw(scenarios / "dice_cube.toml", throws=1_000_000, seed=1, threads=2)
    timer.join()
    partial = raised.value.partial
    assert partial.interrupted and 0 < partial.throws < 1_000_000
    assert partial.counts.sum() + partial.unsettled == partial.throws
    # each finished throw is the one an uninterrupted run gives at its index
    again = tumble.throw(scenarios / "dice_cube.toml", throws=64, seed=1, threads=1)
    first = partial.index < 64
    assert first.any()
    np.testing.assert_array_equal(partial.face_down[first], again.face_down[partial.index[first]])
    np.testing.assert_array_equal(partial.rest_time[first], again.rest_time[partial.index[first]])


def test_progress_is_reported():
    seen = []
    world = busy_world(bodies=10)
    world.run(duration=20.0, progress=lambda done, total: seen.append((done, total)))
    assert seen and seen[-1] == (4800, 4800)
    assert all(total == 4800 for _, total in seen)


def test_progress_bar_draws_on_stderr(capfd, scenarios):
    tumble.throw(scenarios / "dice_cube.toml", throws=32, seed=1, threads=1, progress=True)
    err = capfd.readouterr().err
    assert "32/32 throws" in err


def test_a_world_in_a_run_refuses_other_calls():
    world = busy_world()
    errors = []

    def poke():
        time.sleep(0.05)
        try:
            world.add_body()
        except tumble.WorldBusyError as error:
            errors.append(error)

    thread = threading.Thread(target=poke)
    thread.start()
    world.run(duration=40.0)
    thread.join()
    assert len(errors) == 1
    assert len(world.bodies) == 40


def rss_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def test_no_leak_over_a_hundred_thousand_worlds():
    def churn(count):
        for _ in range(count):
            world = tumble.World()
            world.add_ground()
            rb = world.add_body(position=(0, 1, 0))
            world.step(1 / 240)
            del world, rb
        gc.collect()

    churn(10_000)
    before = rss_bytes()
    churn(100_000)
    grown = rss_bytes() - before
    # a World with its bodies and buffers is kilobytes: leaking each would be hundreds of MB
    assert grown < 4 * 1024 * 1024, f"RSS grew by {grown} bytes"
