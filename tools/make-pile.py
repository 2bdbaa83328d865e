#!/usr/bin/env python3
"""Writes scenarios/pile_100.toml, benchmark S5 of issue 16, to standard output.

Ten layers of ten 2 x 6 x 2 cuboids lying on a long side, in running (stretcher) bond seen end on:
each layer is a row of ten bricks side by side along x, every brick's 6 m axis along z, 0.3 m apart;
odd layers are shifted by half the pitch (1.15 m) so each of their bricks bridges the gap between
two bricks below. Every body starts 0.3 m above the one below (and the lowest layer 0.3 m above the
ground), tilted by an angle uniform in [0, 0.03] rad about a horizontal axis of uniform direction.
The tilts come from Python's Mersenne Twister with a fixed seed (random.random() gives the same
numbers on every platform and version), so running this again reproduces the file exactly:

    python3 tools/make-pile.py > scenarios/pile_100.toml
"""

import math
import random

SEED = 16
LAYERS = 10
PER_LAYER = 10
WIDTH = 2.0  # the brick's x and y extent once lying; its length, 6 m, is along z
GAP = 0.3
MAX_TILT = 0.03  # rad

HEADER = """\
# Benchmark S5 of issue 16 (docs/benchmark.md): a pile of 100 cuboids of 2 x 6 x 2 m and 2 kg.
# Ten layers of ten bricks lying on a long side (the 6 m axis along z), in running bond seen end
# on: each layer is a row of ten bricks side by side along x, 0.3 m apart, and odd layers are
# shifted by half the pitch (1.15 m) so each of their bricks bridges a gap of the layer below.
# Every brick starts 0.3 m above the one below it (the lowest layer 0.3 m above the ground) and
# tilted by up to 0.03 rad about a random horizontal axis, so the layers fall onto each other,
# bounce (e = 0.6) and settle into a pile; the end brick of each odd layer overhangs its support
# and tips off. Contacts approaching slower than 1 m/s do not bounce: Jolt's and Box3D's default,
# which `tumble bench --peers` gives every engine (docs/benchmark.md, "S5 and the restitution
# threshold"). Written by tools/make-pile.py (seed {seed}); edit that and run it again rather than
# editing this file.

[world]
dt = 0.004166666666666667 # 1/240 s
duration = 10.0
sleep = true
restitution_threshold = 1.0 # m/s

[ground]
height = 0.0
"""


def multiply(a, b):
    """Hamilton product of quaternions (w, x, y, z)."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw)


def main():
    draw = random.Random(SEED)
    # a quarter turn about x lays the brick's local y (its 6 m axis) along world z
    lying = (math.sqrt(0.5), math.sqrt(0.5), 0.0, 0.0)
    pitch = WIDTH + GAP
    print(HEADER.format(seed=SEED))
    for layer in range(LAYERS):
        y = round(WIDTH / 2 + GAP + layer * pitch, 9)
        shift = pitch / 2 if layer % 2 == 1 else 0.0
        for i in range(PER_LAYER):
            x = round((i - (PER_LAYER - 1) / 2) * pitch + shift, 9)
            angle = MAX_TILT * draw.random()
            azimuth = 2 * math.pi * draw.random()
            half = angle / 2
            tilt = (math.cos(half), math.sin(half) * math.cos(azimuth), 0.0,
                    math.sin(half) * math.sin(azimuth))
            q = multiply(tilt, lying)
            print("[[body]]")
            print(f'name = "brick{layer * PER_LAYER + i + 1}"')
            print("size = [2, 6, 2]")
            print("mass = 2.0")
            print(f"position = [{x!r}, {y!r}, 0.0]")
            print(f"orientation = [{q[0]!r}, {q[1]!r}, {q[2]!r}, {q[3]!r}]")
            print("elasticity = 0.6")
            print("friction = 0.5")
            print()


if __name__ == "__main__":
    main()
