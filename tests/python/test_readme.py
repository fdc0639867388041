"""The ```python blocks of bindings/README.md run as written."""

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "bindings" / "README.md"


def python_blocks():
    text = README.read_text()
    return re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)


def test_readme_has_python_snippets():
    assert len(python_blocks()) >= 2


@pytest.mark.parametrize("index", range(len(python_blocks())))
def test_readme_snippet_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)          # snippets may write files
    code = python_blocks()[index]
    exec(compile(code, "%s (python block %d)" % (README, index + 1), "exec"), {})
