"""Every script in examples/ runs (Matplotlib's Agg backend, no display) and writes its PNG."""

import os
import subprocess
import sys

import pytest

from conftest import REPO

EXAMPLES = {
    "handout_part3.py": ([], "handout_part3.png"),
    "dice_study.py": (["--throws", "40"], "dice_study.png"),
}


def test_every_example_is_tested():
    assert sorted(p.name for p in (REPO / "examples").glob("*.py")) == sorted(EXAMPLES)


@pytest.mark.parametrize("script", sorted(EXAMPLES))
def test_example_writes_its_png(script, tmp_path):
    arguments, png = EXAMPLES[script]
    environment = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run(
        [sys.executable, str(REPO / "examples" / script), "--out", str(tmp_path), *arguments],
        capture_output=True, text=True, env=environment, cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr
    image = tmp_path / png
    assert image.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert image.stat().st_size > 10_000
    assert f"wrote {image}" in done.stdout
