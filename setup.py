"""The compiled half of the `tribo` package (tribo._tribo) comes from the project's CMake build;
pyproject.toml holds the metadata. The extension is built by CMake for the interpreter running
pip, in pip's build directory — or, with TRIBO_CMAKE_BUILD_DIR set to a configured tribo build
tree, there (a tree already built, as in CI, only has its module copied)."""

import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        tree = os.environ.get("TRIBO_CMAKE_BUILD_DIR") or os.path.join(os.path.abspath(self.build_temp), "cmake")
        if not os.path.exists(os.path.join(tree, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", SOURCE_DIR, "-B", tree, "-DCMAKE_BUILD_TYPE=Release",
                            "-DTRIBO_BUILD_TESTS=OFF", "-DTRIBO_BUILD_BENCH=OFF", "-DTRIBO_BUILD_PYTHON=ON",
                            f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", tree, "--target", "tribo_python", "-j", str(os.cpu_count() or 1)], check=True)
        built_dir = os.path.join(tree, "python", "tribo")
        modules = [f for f in os.listdir(built_dir) if f.startswith("_tribo") and f.endswith(".so")]
        if len(modules) != 1:
            raise RuntimeError(f"tribo: expected one compiled module _tribo*.so in {built_dir}, found {modules}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(built_dir, modules[0]), target)


# setuptools' own build files go to build-pip/, apart from the CMake tree in build/.
BUILD_BASE = os.path.join(SOURCE_DIR, "build-pip")
os.makedirs(BUILD_BASE, exist_ok=True)
setup(ext_modules=[CMakeExtension("tribo._tribo")], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": BUILD_BASE, "build_lib": os.path.join(BUILD_BASE, "lib"),
                         "build_temp": os.path.join(BUILD_BASE, "temp")}, "bdist_wheel": {"bdist_dir": os.path.join(BUILD_BASE, "bdist")},
               "egg_info": {"egg_base": BUILD_BASE}})
