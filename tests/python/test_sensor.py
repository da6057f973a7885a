"""emit.Sensor and emit.Mesh: the same sensor from a file, a dict and the built-in one; the mesh
as numpy views of emit's own arrays."""

import json

import numpy as np
import pytest

import emit
from conftest import EXAMPLES


def test_file_dict_and_builtin_sensor_are_the_same(sensor):
    # default60.json describes the built-in sensor (README): all three must agree key for key.
    assert sensor.to_dict() == emit.Sensor.default().to_dict()
    with open(EXAMPLES / "default60.json") as f:
        assert emit.Sensor.from_dict(json.load(f)).to_dict() == sensor.to_dict()
    assert emit.Sensor.from_dict(sensor.to_dict()).to_dict() == sensor.to_dict()
    assert sensor.electrode_count == 16


def test_mesh_covers_the_sheet_and_its_arrays_are_views(sensor):
    mesh = sensor.mesh()
    assert mesh.nodes_mm.shape == (mesh.node_count, 3)
    assert mesh.triangles.shape == (mesh.triangle_count, 3)
    assert mesh.triangles.dtype == np.int32
    # The triangles tile the 60 x 60 mm sheet: their areas add up to 3600 mm^2 (to rounding).
    assert mesh.triangle_areas_mm2.sum() == pytest.approx(3600.0, rel=1e-12)
    assert len(mesh.electrodes) == 16
    for nodes in mesh.electrodes:
        # Each electrode is 3 mm of border: its end nodes are 3 mm apart along one side.
        ends = mesh.nodes_mm[[nodes[0], nodes[-1]]]
        assert np.linalg.norm(ends[1] - ends[0]) == pytest.approx(3.0, abs=1e-9)
    # Views of the C++ mesh, not copies: two reads share memory, and they are read-only.
    assert np.shares_memory(mesh.nodes_mm, mesh.nodes_mm)
    assert not mesh.nodes_mm.flags.writeable
    assert mesh.triangles.max() == mesh.node_count - 1


def test_a_curved_sensor_from_a_file(sensor):
    dome = emit.Sensor.load(str(EXAMPLES / "dome25.json"))
    nodes = dome.mesh().nodes_mm
    # A spherical cap of radius 25 mm: every node is 25 mm from the sphere's centre.
    # Its rim (radius 20 mm) is its lowest ring, sqrt(25^2 - 20^2) = 15 mm above the centre.
    centre_z = nodes[:, 2].min() - 15.0
    centre_xy = (nodes[:, :2].max(axis=0) + nodes[:, :2].min(axis=0)) / 2
    radii = np.linalg.norm(nodes - np.array([*centre_xy, centre_z]), axis=1)
    assert np.abs(radii - 25.0).max() < 1e-6


def test_press_fields():
    press = emit.Press(10, 20, force_N=5, radius_mm=2, profile="spherical")
    assert press.profile == "spherical"
    # The mean pressure over the disc is F / (pi r^2) whatever the profile (README, "Files").
    assert press.pressure_N_per_mm2 == pytest.approx(5 / (np.pi * 4), rel=1e-15)
