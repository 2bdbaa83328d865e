"""tumble.validate: the validation table of `tumble validate` as NumPy records."""

import re

import numpy as np
import pytest

import tumble


def test_every_case_passes_with_the_clis_values(tumble_cli):
    table = tumble.validate()
    assert len(table) > 10 and table.passed.all()
    assert set(table.dt) == {1 / 240}
    np.testing.assert_allclose(table.error, np.abs(table.value - table.exact), rtol=0, atol=0)
    done = tumble_cli("validate", "--no-study")
    assert done.returncode == 0
    passed = int(re.search(r"^(\d+) passed, 0 failed$", done.stdout, re.M).group(1))
    assert passed == len(table)
    # the printed tumble column is the record's value to 10 significant digits
    for record in table[:5]:
        assert f"{record.value:.10g}" in done.stdout


def test_several_steps_and_bad_steps():
    table = tumble.validate(dt=[1 / 60, 1 / 120])
    assert sorted(set(table.dt)) == [1 / 120, 1 / 60]
    with pytest.raises(ValueError, match="1/n"):
        tumble.validate(dt=0.3)
