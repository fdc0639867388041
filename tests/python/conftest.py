"""Fixtures of the cvmesh binding tests: small inputs and data directories."""

import os
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]


def domain_dir():
    """The example domains: examples/data of the repository, or CVM_DATA_DIR."""
    return Path(os.environ.get("CVM_DATA_DIR") or ROOT / "examples" / "data")


@pytest.fixture
def square_pslg():
    """Unit square: 4 points, 4 segments."""
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.float64)
    segs = np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.int32)
    return pts, segs


@pytest.fixture
def random_points():
    """200 points in general position in the unit square (fixed seed)."""
    return np.random.default_rng(12345).random((200, 2))


@pytest.fixture
def poly_file():
    """Path of the unit square domain, examples/data/square.poly."""
    path = domain_dir() / "square.poly"
    assert path.is_file(), "%s is missing" % path
    return path
