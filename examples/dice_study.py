"""A dice study through Python: how often does a square cuboid die (edges 2 cm, 2k cm, 2 cm) end
on one of its two square faces, against k? Error bars are 95% Wilson intervals. Writes
dice_study.png (docs/python.md; tools/dice-study.sh is the same study with the CLI).

    python3 examples/dice_study.py [--throws N] [--out DIR]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tumble  # noqa: E402

SCENARIO = pathlib.Path(__file__).resolve().parents[1] / "scenarios" / "dice_cube.toml"
EDGE = 0.02


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--throws", type=int, default=2000, help="throws per k")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    ks = np.array([0.5, 0.75, 1.0, 1.25, 1.5, 2.0])
    share, low, high = [], [], []
    for k in ks:
        size = f"die.size=[{EDGE}, {k * EDGE!r}, {EDGE}]"
        result = tumble.throw(SCENARIO, throws=args.throws, seed=1, overrides=[size])
        square = result.counts[[2, 3]].sum() / result.settled  # +y and -y
        interval = result.wilson(0.95, faces=["+y", "-y"])
        share.append(square)
        low.append(square - interval[0])
        high.append(interval[1] - square)
        print(f"k = {k:4.2f}: square face {square:.3f} "
              f"[{interval[0]:.3f}, {interval[1]:.3f}] of {result.settled} settled")

    figure, axes = plt.subplots(figsize=(7, 4.5))
    axes.errorbar(ks, share, yerr=[low, high], fmt="o-", capsize=4,
                  label=f"tumble, {args.throws} throws per k")
    axes.axhline(1 / 3, color="grey", linestyle=":", label="1/3 (a cube)")
    axes.set_xlabel("k (height / width of the die)")
    axes.set_ylabel("P(square face down)")
    axes.set_title("Square cuboid dice: probability of a square face")
    axes.legend()
    figure.tight_layout()
    path = args.out / "dice_study.png"
    figure.savefig(path, dpi=100)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
