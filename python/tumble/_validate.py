"""tumble.validate: the validation suite (``tumble validate``) as NumPy records."""

import numbers

import numpy as np

from . import _tumble

_FIELDS = [
    ("case", object),
    ("section", object),
    ("quantity", object),
    ("dt", np.float64),
    ("exact", np.float64),
    ("value", np.float64),
    ("error", np.float64),
    ("tolerance", np.float64),
    ("passed", np.bool_),
    ("unit", object),
    ("expected_order", np.int64),
]


def validate(dt=1 / 240, progress=False):
    """Runs every validation case (closed-form mechanics, docs/validation.md) at each time step
    and returns the table of ``tumble validate`` as a NumPy record array, one record per checked
    quantity: case, section, quantity, dt, exact, value, error, tolerance, passed, unit,
    expected_order. ``table.passed.all()`` says whether tumble passed.

    dt: a step or a sequence of steps, each 1/n s (the cases compare at whole seconds).
    Releases the GIL; Ctrl-C raises KeyboardInterrupt with the records so far as ``partial``.
    """
    steps = [float(dt)] if isinstance(dt, numbers.Real) else [float(s) for s in dt]
    for step in steps:
        per_second = 1.0 / step if step > 0 else 0.0
        if not step > 0 or abs(per_second - round(per_second)) > 1e-9 * per_second:
            raise ValueError(
                "the validation cases compare at whole seconds, so dt must be 1/n s for a whole "
                f"number n, got {step!r}"
            )
    try:
        rows = _tumble._validation_rows(steps, progress)
    except KeyboardInterrupt as interrupt:
        if getattr(interrupt, "partial", None) is not None:
            interrupt.partial = _records(interrupt.partial)
        raise
    return _records(rows)


def _records(rows):
    return np.rec.fromrecords(rows, dtype=_FIELDS) if rows else np.recarray(0, dtype=_FIELDS)
