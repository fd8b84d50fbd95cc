# Builds the extension symmetry_transform._core with CMake (python/CMakeLists.txt) from the headers
# of this checkout, then installs the package:
#   /usr/bin/python3 -m venv --system-site-packages VENV && VENV/bin/pip install --no-build-isolation ./python
import os
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        destination = Path(self.get_ext_fullpath(ext.name)).resolve().parent
        build = Path(self.build_temp).resolve()
        configure = ["cmake", "-S", str(HERE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPYTHON_EXECUTABLE={sys.executable}",
                     f"-DCMAKE_LIBRARY_OUTPUT_DIRECTORY={destination}"]
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "-j", jobs], check=True)


setup(
    name="symmetry_transform",
    version="0.1.0",
    description="Planar reflective and point symmetry transforms of 3D shapes (CGAL Symmetry_transform)",
    license="GPL-3.0-or-later",
    packages=["symmetry_transform"],
    package_data={"symmetry_transform": ["py.typed", "_core.pyi"]},
    ext_modules=[CMakeExtension("symmetry_transform._core")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    extras_require={"cluster": ["distributed"]},
    zip_safe=False,
)
