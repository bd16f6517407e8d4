"""What the Python tests share: the source tree, the built tools (passed by
CTest in SOFTGLASS_*_EXECUTABLE, tests/python/CMakeLists.txt) and the shared
rheometry folder, which is absent on some machines."""

import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("SOFTGLASS_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SHARED = pathlib.Path(os.environ.get("SOFTGLASS_SHARED_DIR", SOURCE.parent / "shared"))
RHEOMETRY = SHARED / "data" / "rheometry"
BUNDLED_LAW = SOURCE / "cases" / "bridge_law_paper_sweep.prm"
CASTOR_OIL = RHEOMETRY / "castoroil85_couette_flow_sweep.csv"


def tool(name):
    """The built command `name` (micro, bridge, macro); the test is skipped
    when CTest did not say where it is."""
    path = os.environ.get(f"SOFTGLASS_{name.upper()}_EXECUTABLE")
    if not path:
        pytest.skip(f"SOFTGLASS_{name.upper()}_EXECUTABLE not set: run through CTest")
    return path


def run_tool(name, *arguments, cwd=None):
    """Runs a built tool, failing the test with its stderr when it fails."""
    done = subprocess.run([tool(name), *map(str, arguments)], cwd=cwd, capture_output=True,
                          text=True)
    assert done.returncode == 0, f"{name} {' '.join(map(str, arguments))}: {done.stderr}"
    return done.stdout


@pytest.fixture
def castor_oil():
    """The measured castor-oil flow sweep of ../shared/data/rheometry."""
    if not CASTOR_OIL.exists():
        pytest.skip(f"{CASTOR_OIL} absent: the shared rheometry data are not on this machine")
    return CASTOR_OIL
