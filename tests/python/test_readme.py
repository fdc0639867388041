"""The code blocks of README.md and bindings/README.md run as written.

- ```python blocks of both run; those of the top README run in a folder where
  examples/ is the repository's, as if run from the top of the tree;
- the top README's command lines (`build/bin/cvmesh ...` in ```sh blocks) run
  against the built CLI, and every file they name is written and valid;
- its ```c block is an excerpt of examples/c/minimal.c (which check-examples
  builds and runs), line by line and in order;
- its ```poly block is a .poly file that reads and meshes as it says.
The ```fortran block is run by bindings/fortran/check.sh.
"""

import os
import re
import shlex
import subprocess
from pathlib import Path

import pytest

import cvmesh

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "bindings" / "README.md"
TOP = ROOT / "README.md"


def blocks(path, lang):
    return re.findall(r"^```%s\n(.*?)^```" % re.escape(lang), path.read_text(), re.S | re.M)


def python_blocks():
    return blocks(README, "python")


def cli_lines():
    return [line for block in blocks(TOP, "sh") for line in block.splitlines()
            if line.startswith("build/bin/cvmesh ")]


def top_tree(tmp_path):
    """tmp_path with examples/ linked to the repository's; the snippets' cwd."""
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    return tmp_path


def cli_binary():
    """The built CLI: $CVM_CLI, else bin/cvmesh of $CVM_BUILD or $BUILD, else build/."""
    cands = [Path(os.environ["CVM_CLI"])] if os.environ.get("CVM_CLI") else []
    for var in ("CVM_BUILD", "BUILD"):
        if os.environ.get(var):
            cands.append(ROOT / os.environ[var] / "bin" / "cvmesh")
    cands.append(ROOT / "build" / "bin" / "cvmesh")
    for c in cands:
        if c.is_file() and os.access(c, os.X_OK):
            return c
    return None


def test_readme_has_python_snippets():
    assert len(python_blocks()) >= 2


@pytest.mark.parametrize("index", range(len(python_blocks())))
def test_readme_snippet_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)          # snippets may write files
    code = python_blocks()[index]
    exec(compile(code, "%s (python block %d)" % (README, index + 1), "exec"), {})


def test_top_readme_has_every_quick_start():
    assert len(blocks(TOP, "python")) >= 1
    assert len(blocks(TOP, "c")) == 1
    assert len(blocks(TOP, "fortran")) == 1
    assert len(blocks(TOP, "poly")) == 1
    assert len(cli_lines()) >= 3


@pytest.mark.parametrize("index", range(len(blocks(TOP, "python"))))
def test_top_readme_python_block_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(top_tree(tmp_path))
    code = blocks(TOP, "python")[index]
    exec(compile(code, "%s (python block %d)" % (TOP, index + 1), "exec"), {})
    for name in re.findall(r"write(?:_dual)?\(\"([^\"]+)\"\)", code):
        assert (tmp_path / name).stat().st_size > 0, name


@pytest.mark.parametrize("index", range(len(cli_lines())))
def test_top_readme_command_line_runs(index, tmp_path):
    exe = cli_binary()
    if exe is None:
        pytest.skip("no built cvmesh CLI (set CVM_CLI or CVM_BUILD)")
    cwd = top_tree(tmp_path)
    argv = shlex.split(cli_lines()[index])
    argv[0] = str(exe)
    run = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    outputs = {argv[i + 1]: flag for i, flag in enumerate(argv[:-1])
               if flag in ("-o", "--output", "--svg", "--dual")}
    assert outputs, "the README's command writes nothing"
    nverts = None
    for name, flag in sorted(outputs.items(), key=lambda item: item[1] == "--dual"):
        path = cwd / name
        assert path.stat().st_size > 0, name
        if name.endswith(".svg"):
            assert "<svg" in path.read_text()
        elif flag == "--dual":                      # one power cell per vertex of the mesh
            cells = re.search(r'NumberOfCells="(\d+)"', path.read_text())
            assert nverts is not None and cells and int(cells.group(1)) == nverts
        elif name.endswith(".vtu") and argv[1] in ("tetrahedralize", "mesh3"):
            text = path.read_text()                 # a tetrahedral mesh: VTK_TETRA cells only
            cells = re.search(r'NumberOfCells="(\d+)"', text)
            assert cells and int(cells.group(1)) > 0
            types = text.split('Name="types"')[1].split(">", 1)[1].split("<", 1)[0].split()
            assert len(types) == int(cells.group(1)) and set(types) == {"10"}
        elif name.endswith(".vtu"):
            mesh = cvmesh.Mesh.read(str(path))     # read back as the same mesh
            assert len(mesh.triangles) > 0
            assert mesh.check()
            nverts = len(mesh.points)


def test_top_readme_c_block_is_an_excerpt_of_minimal_c():
    src = [line.strip() for line in (ROOT / "examples" / "c" / "minimal.c").read_text().splitlines()]
    (block,) = blocks(TOP, "c")
    i = 0
    for line in filter(None, (x.strip() for x in block.splitlines())):
        while i < len(src) and src[i] != line:
            i += 1
        assert i < len(src), "README.md C line not in examples/c/minimal.c (in order): %s" % line
        i += 1


def test_top_readme_poly_block_is_the_domain_it_describes(tmp_path):
    (text,) = blocks(TOP, "poly")
    path = tmp_path / "square_hole.poly"
    path.write_text(text)
    mesh = cvmesh.Mesh.read(str(path))
    mesh.triangulate()
    assert len(mesh.points) == 8
    assert len(mesh.segments) == 8
    assert mesh.quality().area == pytest.approx(3 * 3 - 1 * 1, abs=1e-12)
