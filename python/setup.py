"""Builds the compiled module of softglass with the project's CMake build.

pip runs this in python/ of a softglass checkout (or, with
$SOFTGLASS_SOURCE_DIR naming the checkout, in a copy of python/): the module
is the target softglass_python of the checkout's build folder (build/, or
$SOFTGLASS_BUILD_DIR), configured here only when it is not yet, so that after
`make` nothing is compiled again. $CMAKE_BUILD_PARALLEL_LEVEL sets the
build's jobs.
"""

import os
import pathlib
import shutil
import subprocess
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(os.environ.get("SOFTGLASS_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parent.parent))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not (SOURCE / "CMakeLists.txt").exists():
            raise RuntimeError(
                f"{SOURCE} is not a softglass checkout: install from python/ of the repository"
            )
        build = pathlib.Path(os.environ.get("SOFTGLASS_BUILD_DIR", SOURCE / "build"))
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build),
                            "-DCMAKE_BUILD_TYPE=Release"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "softglass_python"], check=True)
        # The module is built for the build's interpreter (its Python_EXECUTABLE,
        # Debian's /usr/bin/python3 by default): it must be this one's ABI.
        name = "_softglass" + sysconfig.get_config_var("EXT_SUFFIX")
        built = build / "python" / "softglass" / name
        if not built.exists():
            raise RuntimeError(
                f"{built} was not built: the build's Python (Python_EXECUTABLE in "
                f"{build}/CMakeCache.txt) is not of this interpreter's version"
            )
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(ext_modules=[Extension("softglass._softglass", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
