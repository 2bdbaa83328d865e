"""tumble.throw: the dice throws of ``tumble throw`` and their statistics as NumPy arrays."""

import os

import numpy as np

from . import _tumble

#: The faces in the order of ThrowResult.counts (CuboidFace order: outward body-frame normals).
FACES = np.array(["+x", "-x", "+y", "-y", "+z", "-z"])


class ThrowResult:
    """The outcome of tumble.throw.

    index: per throw, its index (the throws of an interrupted run are those that finished).
    face_down: per throw, the index in FACES of the face at rest on the ground, -1 when the die
    was not at rest by the scenario's max_time. rest_time: per throw, when it came to rest, s
    (NaN when unsettled). faces: FACES. counts: throws that ended on each face. unsettled: the
    throws not at rest. The same seed gives the same throws as ``tumble throw --seed``.
    """

    def __init__(self, face_down, rest_time, seed, threads, index=None, interrupted=False):
        self.index = np.arange(len(face_down)) if index is None else index
        self.face_down = face_down
        self.rest_time = rest_time
        self.seed = seed
        self.threads = threads
        self.interrupted = interrupted
        self.faces = FACES.copy()
        settled = face_down[face_down >= 0]
        self.counts = np.bincount(settled, minlength=len(FACES)).astype(np.int64)
        self.unsettled = int(np.count_nonzero(face_down < 0))

    @property
    def throws(self):
        """Number of throws."""
        return len(self.face_down)

    @property
    def settled(self):
        """Number of throws that came to rest."""
        return int(self.counts.sum())

    @property
    def probabilities(self):
        """Share of the settled throws on each face (zeros when none settled)."""
        return self.counts / self.settled if self.settled > 0 else np.zeros(len(FACES))

    def wilson(self, confidence=0.95, faces=None):
        """Wilson score intervals of the face probabilities among the settled throws
        (docs/dice.md, (D.1)): a (6, 2) array of [low, high], one row per face of FACES; with
        `faces` (names such as ["+y", "-y"]) the interval of ending on any of them, [low, high].
        [0, 1] when no throw settled."""
        if faces is not None:
            chosen = int(sum(self.counts[list(self.faces).index(face)] for face in faces))
            return np.array(_tumble._wilson_interval(chosen, self.settled, confidence))
        return np.array(
            [_tumble._wilson_interval(int(n), self.settled, confidence) for n in self.counts]
        )

    def chi_square(self):
        """Pearson's chi-square test of equal face probabilities (meaningful for a cube):
        (statistic, p-value) with 5 degrees of freedom (docs/dice.md, (D.2))."""
        return _tumble._chi_square_uniform([int(n) for n in self.counts])

    def __repr__(self):
        counts = ", ".join(f"{f}: {n}" for f, n in zip(self.faces, self.counts))
        return f"<tumble.ThrowResult {self.throws} throws; {counts}; unsettled: {self.unsettled}>"


def throw(scenario, throws=1000, seed=1, threads=0, progress=False, overrides=()):
    """Throws a scenario's die `throws` times, as ``tumble throw`` does, and returns a
    ThrowResult.

    scenario: a path or a tumble.Scenario with a [throw] table. seed: the draws' seed; each
    throw depends only on (seed, index), so the result does not depend on `threads` (0: one per
    core). overrides: "KEY=VALUE" strings, as ``--set``. Releases the GIL; Ctrl-C raises
    KeyboardInterrupt whose ``partial`` attribute is the ThrowResult of the finished throws.
    """
    if isinstance(scenario, (str, os.PathLike)):
        scenario = _tumble.load_scenario(scenario, list(overrides))
    elif overrides:
        raise ValueError("overrides apply to a path; a Scenario is already loaded")
    try:
        face_down, rest_time, used = _tumble._throw_outcomes(
            scenario, throws, seed, threads, progress
        )
    except KeyboardInterrupt as interrupt:
        partial = getattr(interrupt, "partial", None)
        if partial is not None:
            face_down, rest_time, finished = partial
            interrupt.partial = ThrowResult(
                face_down[finished], rest_time[finished], seed, threads,
                index=np.flatnonzero(finished), interrupted=True,
            )
        raise
    return ThrowResult(face_down, rest_time, seed, used)
