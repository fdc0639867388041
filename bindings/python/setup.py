"""Build of the cvmesh Python package: SWIG-generates the wrapper of
include/cvmesh.h and compiles it together with the library's C sources
(lib/*/*.c except lib/cli) into one extension, cvmesh._capi.

The SWIG-generated cvmesh/capi.py is written by build_ext straight into the
build tree (or next to the sources with --inplace), so it is part of the
wheel. Environment:
  CVMESH_SWIG        swig program to use; default: the `swig` wheel of the
                     build environment, else `swig` on PATH.
  CVMESH_SOURCE_DIR  root of the cvmesh sources (holding include/ and lib/);
                     default: ./csrc (in an sdist) or ../.. (in the repository).
  CVMESH_WERROR=1    turn compiler warnings into errors (used by check.sh).
  CVMESH_BUILD_DIR   setuptools' build directory (default ./build).
  CVMESH_OPENMP=0    build without OpenMP (default: with it when the compiler
                     links an OpenMP program, as the Makefile's OPENMP=1).
"""

import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.sdist import sdist

HERE = Path(__file__).resolve().parent


def source_root():
    """Directory holding include/cvmesh.h and lib/."""
    env = os.environ.get("CVMESH_SOURCE_DIR")
    candidates = [Path(env)] if env else [HERE / "csrc", HERE.parent.parent]
    for root in candidates:
        if (root / "include" / "cvmesh.h").is_file() and (root / "lib").is_dir():
            return root.resolve()
    raise SystemExit("cvmesh: cannot find the C sources (include/cvmesh.h and lib/) in %s; "
                     "build from the cvmesh repository or set CVMESH_SOURCE_DIR"
                     % ", ".join(str(c) for c in candidates))


def library_sources(root):
    """The library's C files, sorted: lib/*/*.c without the command-line program."""
    return sorted(str(p) for p in (root / "lib").glob("*/*.c") if p.parent.name != "cli")


def inputs(root):
    """Every file the extension is built from besides cvmesh.i."""
    files = [HERE / "cvmesh_numpy.i", root / "include" / "cvmesh.h"]
    files += sorted((root / "lib").glob("*/*.h")) + [Path(p) for p in library_sources(root)]
    return [str(p) for p in files]


def header_version(root):
    text = (root / "include" / "cvmesh.h").read_text()
    parts = [re.search(r"#define\s+CVM_VERSION_%s\s+(\d+)" % k, text) for k in
             ("MAJOR", "MINOR", "PATCH")]
    if not all(parts):
        raise SystemExit("cvmesh: no CVM_VERSION_MAJOR/MINOR/PATCH in cvmesh.h")
    return ".".join(p.group(1) for p in parts)


def swig_command():
    """(argv prefix, environment) that runs SWIG."""
    env = dict(os.environ)
    program = os.environ.get("CVMESH_SWIG")
    if not program:
        try:
            import swig  # the PyPI wheel: a relocatable SWIG and its library
            program = os.path.join(swig.BIN_DIR, "swig")
            env["SWIG_LIB"] = swig.SWIG_LIB_ENV["SWIG_LIB"]
        except ImportError:
            program = shutil.which("swig") or shutil.which("swig4.0")
    if not program:
        raise SystemExit("cvmesh: SWIG not found; pip install swig, or set CVMESH_SWIG")
    return [program], env


ROOT = source_root()
WERROR = ["-Werror"] if os.environ.get("CVMESH_WERROR") == "1" else []
# The library keeps its own strict flags (those of the Makefile; -UNDEBUG undoes
# Python's -DNDEBUG so assertions are as in `make`), plus -fopenmp when the
# compiler has OpenMP (openmp_flags()); the generated wrapper is compiled with
# the usual warnings.
LIB_CFLAGS = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-fvisibility=hidden",
              "-D_POSIX_C_SOURCE=200809L", "-UNDEBUG"] + WERROR
WRAP_CFLAGS = ["-Wall", "-Wextra", "-Wno-unused-parameter"] + WERROR


OPENMP_FLAGS = ["-fopenmp"]


def openmp_flags(compiler, tmp):
    """["-fopenmp"] when `compiler` compiles and links an OpenMP program with
    it (gcc; clang with libomp), else [] (CVMESH_OPENMP=0 forces [])."""
    if os.environ.get("CVMESH_OPENMP") == "0" or compiler.compiler_type != "unix":
        return []
    src = Path(tmp) / "omp_probe.c"
    src.write_text("#include <omp.h>\nint main(void) { return omp_get_max_threads() < 1; }\n")
    try:
        objs = compiler.compile([str(src)], output_dir=str(tmp), extra_postargs=OPENMP_FLAGS)
        compiler.link_executable(objs, "omp_probe", output_dir=str(tmp),
                                 extra_postargs=OPENMP_FLAGS)
    except Exception:  # CompileError / LinkError: build serial, as OPENMP=0
        return []
    return OPENMP_FLAGS


class BuildExt(build_ext):
    """build_ext that runs SWIG itself (so capi.py lands in the package) and
    compiles the library sources with their own flags."""

    def swig_sources(self, sources, extension):
        interfaces = [s for s in sources if s.endswith(".i")]
        if not interfaces:
            return sources
        (interface,) = interfaces
        outdir = Path(self.get_ext_fullpath(extension.name)).parent
        outdir.mkdir(parents=True, exist_ok=True)
        tmp = Path(self.build_temp)
        tmp.mkdir(parents=True, exist_ok=True)
        wrapper = tmp / "cvmesh_wrap.c"
        argv, env = swig_command()
        cmd = argv + ["-python", "-doxygen", "-I%s" % (ROOT / "include"), "-I%s" % HERE,
                      "-outdir", str(outdir), "-o", str(wrapper), interface]
        self.announce("swigging %s: %s" % (interface, " ".join(cmd)), level=2)
        subprocess.run(cmd, check=True, env=env)
        return [s for s in sources if not s.endswith(".i")] + [str(wrapper)]

    def build_extension(self, ext):
        # build_ext decides "up to date" from ext.sources + ext.depends before
        # SWIG runs; every input is in them (see inputs()), so a change to the
        # typemaps, the header or any library source rebuilds the extension.
        target = Path(self.get_ext_fullpath(ext.name))
        if not self.force and target.exists() and all(
                Path(p).stat().st_mtime <= target.stat().st_mtime
                for p in ext.sources + ext.depends):
            self.announce("skipping %s (up to date)" % ext.name, level=2)
            return
        unix = self.compiler.compiler_type == "unix"
        with tempfile.TemporaryDirectory() as tmp:
            omp = openmp_flags(self.compiler, tmp)
        self.announce("cvmesh: OpenMP %s" % ("on: " + " ".join(omp) if omp else "off"), level=2)
        objects = self.compiler.compile(
            library_sources(ROOT), output_dir=self.build_temp,
            include_dirs=[str(ROOT / "include"), str(ROOT / "lib")],
            extra_postargs=LIB_CFLAGS + omp if unix else [], debug=self.debug)
        ext.extra_objects = list(ext.extra_objects or []) + objects
        import numpy
        ext.include_dirs = list(ext.include_dirs or []) + [str(ROOT / "include"),
                                                           numpy.get_include()]
        ext.extra_compile_args = WRAP_CFLAGS if unix else []
        if unix:
            ext.libraries = list(ext.libraries or []) + ["lbfgs", "z", "m"]
            ext.extra_link_args = list(ext.extra_link_args or []) + omp
        super().build_extension(ext)


class Sdist(sdist):
    """sdist that carries the C sources in csrc/, so it builds on its own."""

    def make_release_tree(self, base_dir, files):
        super().make_release_tree(base_dir, files)
        dest = Path(base_dir) / "csrc"
        shutil.copytree(ROOT / "include", dest / "include")
        shutil.copytree(ROOT / "lib", dest / "lib",
                        ignore=lambda d, names: [n for n in names if n == "cli"])


setup(
    version=header_version(ROOT),
    options={"build": {"build_base": os.environ["CVMESH_BUILD_DIR"]}}
    if os.environ.get("CVMESH_BUILD_DIR") else {},
    ext_modules=[Extension("cvmesh._capi", sources=["cvmesh.i"], depends=inputs(ROOT))],
    cmdclass={"build_ext": BuildExt, "sdist": Sdist},
)
