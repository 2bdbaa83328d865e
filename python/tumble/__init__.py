"""tumble: rigid cuboids falling, bouncing and sliding on a ground plane.

The C++ engine of the ``tumble`` program, for Python (docs/python.md)::

    import tumble
    world = tumble.World(gravity=(0, -9.81, 0))
    world.add_ground(height=0.0)
    rb = world.add_body(size=(2, 6, 2), mass=2.0, position=(0, 5, 0), friction=0.5)
    traj = world.run(duration=10.0, dt=1/240)        # a NumPy structured array
    sc = tumble.load_scenario("scenarios/part3_task4_friction.toml")
    res = tumble.throw("scenarios/dice_cube.toml", throws=10_000, seed=1)
    table = tumble.validate()

Long calls (World.run, Scenario.run, throw, validate) release the GIL, stop on Ctrl-C with
KeyboardInterrupt (carrying what was computed as its ``partial`` attribute) and draw a progress
bar with ``progress=True``.
"""

from ._tumble import (
    __version__,
    Body,
    Collision,
    Scenario,
    ScenarioError,
    StaleBodyError,
    World,
    WorldBusyError,
    load_scenario,
)
from ._throw import FACES, ThrowResult, throw
from ._validate import validate

__all__ = [
    "__version__",
    "Body",
    "Collision",
    "FACES",
    "Scenario",
    "ScenarioError",
    "StaleBodyError",
    "ThrowResult",
    "World",
    "WorldBusyError",
    "load_scenario",
    "throw",
    "validate",
]
