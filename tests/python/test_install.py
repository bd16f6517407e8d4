"""`pip install --no-build-isolation ./python` with Debian's pip and
setuptools and no package index: the package lands in a virtual environment
(which sees Debian's packages), built by the project's own build folder."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE


def test_pip_installs_the_module_built_by_make(tmp_path):
    build = os.environ.get("SOFTGLASS_BUILD_DIR")
    if not build:
        pytest.skip("SOFTGLASS_BUILD_DIR not set: run through CTest")
    # A copy of python/, so that pip's build files stay out of the checkout.
    package = tmp_path / "python"
    shutil.copytree(SOURCE / "python", package,
                    ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__"))
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip",
                    str(venv)], check=True)
    python = str(venv / "bin" / "python")
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    environment.update(SOFTGLASS_SOURCE_DIR=str(SOURCE), SOFTGLASS_BUILD_DIR=build)
    done = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index",
                           "--no-cache-dir", str(package)], env=environment, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    check = subprocess.run(
        [python, "-c", "import softglass; print(softglass.__file__); "
         f"print(softglass.load_law('{SOURCE}/cases/bridge_law_paper_sweep.prm').phi[0])"],
        cwd=tmp_path, env=environment, capture_output=True, text=True)
    assert check.returncode == 0, check.stderr
    installed, phi = check.stdout.split()
    assert pathlib.Path(installed).is_relative_to(venv)
    assert float(phi) == 0.7
