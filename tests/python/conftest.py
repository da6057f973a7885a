"""Shared fixtures of the Python tests: the module from the build tree (PYTHONPATH, set by CTest),
this build's CLI, the sources, and models built once per session (building one takes seconds)."""

import os
import pathlib

import numpy as np
import pytest

import emit

SOURCE_DIR = pathlib.Path(os.environ.get("EMIT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE_DIR / "examples" / "sensors"


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("EMIT_CLI")
    if not path:
        pytest.skip("EMIT_CLI is not set (CTest sets it to this build's emit)")
    return path


@pytest.fixture(scope="session")
def sensor():
    return emit.Sensor.load(str(EXAMPLES / "default60.json"))


@pytest.fixture(scope="session")
def twin(sensor):
    # Another mesh than the reconstruction's (the twin's own, seed 3): no inverse crime.
    return emit.Twin(sensor, mesh_seed=3, noise_seed=7)


@pytest.fixture(scope="session")
def reference(twin):
    return twin.frames([[] for _ in range(10)])


@pytest.fixture(scope="session")
def paper(sensor, reference):
    reconstructor = emit.Reconstructor(sensor, method="paper")
    reconstructor.set_reference(reference)
    return reconstructor


def distance_mm(contact, x_mm, y_mm):
    return float(np.hypot(contact.x_mm - x_mm, contact.y_mm - y_mm))
