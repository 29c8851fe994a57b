"""Builds the swingsim Python package with this project's CMake build (docs/python.md, "pip install").

pip runs this through setuptools (pyproject.toml). It does not compile anything itself: it
configures a CMake build folder if there is none (scripts/configure.sh, Release), builds the
target swingsim_python there and packs what that build put in PYTHON_DIR/swingsim/ (the
extension _swingsim.*.so, __init__.py, its stub and the private modules).

Environment:
  SWINGSIM_BUILD_DIR  the CMake build folder to reuse or make (default: build/ in this folder)
  SWINGSIM_JOBS       parallel build jobs (default: the machine's cores)
"""
import os
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = os.path.dirname(os.path.abspath(__file__))


def build_dir():
    folder = os.environ.get("SWINGSIM_BUILD_DIR") or os.path.join(ROOT, "build")
    return os.path.abspath(folder)


def run(command):
    print("swingsim setup.py:", " ".join(command), flush=True)
    subprocess.check_call(command, cwd=ROOT)


class BuildWithCMake(build_py):
    """build_py that gets the package from the CMake build instead of copying sources."""

    def run(self):
        folder = build_dir()
        if not os.path.exists(os.path.join(folder, "CMakeCache.txt")):
            # The extension must load into the Python running pip: configure for it.
            run(["bash", "scripts/configure.sh", folder, "-DCMAKE_BUILD_TYPE=Release",
                 "-DPython3_EXECUTABLE=" + sys.executable])
        jobs = os.environ.get("SWINGSIM_JOBS") or str(os.cpu_count() or 1)
        run(["cmake", "--build", folder, "--target", "swingsim_python", "-j", jobs])
        package = os.path.join(folder, "python", "swingsim")
        built = sorted(os.listdir(package)) if os.path.isdir(package) else []
        if not any(name.startswith("_swingsim") and name.endswith(".so") for name in built):
            sys.exit(f"swingsim setup.py: {package} has no _swingsim*.so after building swingsim_python "
                     f"(found: {', '.join(built) or 'nothing'}); is {folder} a sanitizer or fuzz build (they leave the module out)?")
        target = os.path.join(self.build_lib, "swingsim")
        os.makedirs(target, exist_ok=True)
        for name in built:
            if name.endswith((".py", ".pyi", ".so")):
                shutil.copy2(os.path.join(package, name), os.path.join(target, name))


class BinaryDistribution(Distribution):
    """The wheel holds a compiled extension: tag it for this platform and Python."""

    def has_ext_modules(self):
        return True


# setuptools' own scratch folders (its default build/ is the CMake build's folder) and its
# metadata go inside the CMake build folder, so an install leaves the source tree as it was.
SCRATCH = os.path.join(build_dir(), "python-package")
os.makedirs(SCRATCH, exist_ok=True)
setup(packages=["swingsim"], package_dir={"swingsim": "python/swingsim"},
      cmdclass={"build_py": BuildWithCMake}, distclass=BinaryDistribution,
      options={"build": {"build_base": SCRATCH}, "egg_info": {"egg_base": SCRATCH}})
