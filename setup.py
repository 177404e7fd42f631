# SPDX-License-Identifier: GPL-3.0-or-later
"""pip's way into the CMake build: the extension module roughcontact is the CMake target of the
same name (src/python), built with this interpreter and copied where pip wants it.

Where it builds: ROUGHCONTACT_CMAKE_BUILD (an existing CMake build folder of this project, e.g.
build/ after ./Allwmake: only the module is brought up to date there), else a folder of its own
under build/pip/ (configured with the tests, benchmarks and OpenFOAM parts off). The version is
the CMake project's. Nothing is downloaded: CMake finds Debian's pybind11, FFTW, libzip, pugixml
and OpenSSL as for the rest of the project.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

TOP = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (TOP / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(roughContact VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("ROUGHCONTACT_CMAKE_BUILD")
        if build:
            build = pathlib.Path(build).resolve()
        else:
            build = TOP / "build" / "pip"
            subprocess.run(
                ["cmake", "-S", str(TOP), "-B", str(build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                 "-DROUGHCONTACT_BUILD_TESTS=OFF", "-DROUGHCONTACT_BUILD_BENCHMARKS=OFF",
                 "-DROUGHCONTACT_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}",
                 f"-DPYTHON_EXECUTABLE={sys.executable}"],
                check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "roughcontact"], check=True)
        built = sorted((build / "python").glob("roughcontact*.so"))
        if not built:
            raise RuntimeError(f"setup.py: CMake built no roughcontact*.so in {build / 'python'}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[-1], target)


setup(
    version=project_version(),
    ext_modules=[Extension("roughcontact", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
