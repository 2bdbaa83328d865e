"""Builds the tumble Python module with the project's own CMake (pyproject.toml).

setuptools drives CMake: it configures a build with only the libraries and the module
(TUMBLE_BUILD_PYTHON, for the Python running this script), builds the _tumble target and puts the
extension next to the pure-Python files of python/tumble.
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version in the top-level CMakeLists.txt: one number for the C++ and Python sides."""
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(tumble VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    """An extension CMake builds: no sources of its own for setuptools to compile."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        subprocess.run(
            ["cmake", "-S", str(ROOT), "-B", str(build_dir), *generator,
             "-DCMAKE_BUILD_TYPE=Release",
             f"-DPython3_EXECUTABLE={sys.executable}",
             "-DTUMBLE_BUILD_PYTHON=ON",
             "-DTUMBLE_BUILD_CLI=OFF",
             "-DTUMBLE_BUILD_TESTS=OFF",
             "-DTUMBLE_BUILD_VIEWER=OFF",
             "-DTUMBLE_BUILD_BENCH=OFF",
             "-DTUMBLE_BUILD_PEERS=OFF",
             "-DTUMBLE_BUILD_MPI=OFF"],
            check=True,
        )
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_tumble"], check=True)
        built = next((build_dir / "python" / "tumble").glob("_tumble*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    packages=["tumble"],
    package_dir={"tumble": os.path.join("python", "tumble")},
    ext_modules=[CMakeExtension("tumble._tumble")],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' build folder apart from CMake's build/ of tools/run-tests.sh
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
