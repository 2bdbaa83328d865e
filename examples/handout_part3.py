"""Handout part 3 through Python: the 2 x 6 x 2 cuboid thrown onto the ground, sliding on forever
without friction and coming to rest with friction 0.5 (task 4). Plots its height and its energy
against time into handout_part3.png (docs/python.md).

    python3 examples/handout_part3.py [--out DIR]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import tumble  # noqa: E402


def throw_cuboid(friction):
    """Part 3's experiment: the cuboid thrown from 5 m, tumbling, onto the ground."""
    world = tumble.World(gravity=(0, -9.81, 0))
    world.add_ground(height=0.0)
    world.add_body(size=(2, 6, 2), mass=2.0, position=(0, 5, 0), velocity=(1, 0, 0.5),
                   angular_velocity=(1.0, 0.5, 2.0), elasticity=0.6, friction=friction)
    return world.run(duration=10.0, dt=1 / 240)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    out = parser.parse_args().out
    out.mkdir(parents=True, exist_ok=True)

    figure, (height, energy) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    for friction, label in [(0.0, "no friction"), (0.5, "friction 0.5 (task 4)")]:
        traj = throw_cuboid(friction)
        height.plot(traj["time"], traj["y"], label=label)
        energy.plot(traj["time"], traj["kinetic"] + traj["potential"], label=label)
        print(f"{label}: at t = 10 s height {traj['y'][-1]:.4f} m, "
              f"kinetic energy {traj['kinetic'][-1]:.6f} J")
    height.set_ylabel("centre height (m)")
    energy.set_ylabel("kinetic + potential (J)")
    energy.set_xlabel("time (s)")
    height.legend()
    figure.suptitle("Handout part 3: the 2 x 6 x 2 cuboid thrown onto the ground")
    figure.tight_layout()
    path = out / "handout_part3.png"
    figure.savefig(path, dpi=100)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
