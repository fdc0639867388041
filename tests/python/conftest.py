"""Fixtures of the cvmesh binding tests: small inputs and data directories."""

import os
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]


def shared_data_dir():
    """shared/data of the project (beside the repository), or CVM_SHARED_DIR/data."""
    env = os.environ.get("CVM_SHARED_DIR")
    for d in ([Path(env)] if env else []) + [ROOT.parent / "shared", ROOT / "shared"]:
        if (d / "data").is_dir():
            return d / "data"
    return None


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
    """Path of a .poly file from shared/data, or skip."""
    d = shared_data_dir()
    if d is None or not (d / "square.poly").is_file():
        pytest.skip("shared/data/square.poly not found (set CVM_SHARED_DIR)")
    return d / "square.poly"
