"""The progress bar of progress=True: one line on sys.stderr, redrawn in place (as the CLI's)."""

import sys
import time

_WIDTH = 30


class ProgressBar:
    """Called as bar(done, total) a few times a second by a long call; close() ends the line."""

    def __init__(self, total, unit, stream=None):
        self.total = total
        self.unit = unit
        self.stream = stream if stream is not None else sys.stderr
        self.start = time.monotonic()
        self.drawn = False

    def __call__(self, done, total):
        elapsed = time.monotonic() - self.start
        fraction = done / total if total > 0 else 1.0
        rate = done / elapsed if elapsed > 0 else 0.0
        left = elapsed * (1.0 - fraction) / fraction if fraction > 0 else 0.0
        filled = int(fraction * _WIDTH)
        bar = "#" * filled + "." * (_WIDTH - filled)
        self.stream.write(
            f"\r[{bar}] {done}/{total} {self.unit}  {rate:.0f} {self.unit}/s  {left:.1f} s left  "
        )
        self.stream.flush()
        self.drawn = True

    def close(self):
        if self.drawn:
            self.stream.write("\n")
            self.stream.flush()
