"""emit.Reconstructor against the twin's presses, against emit's CLI on the same files, and one
frame against a stack of them."""

import json
import subprocess

import numpy as np
import pytest

import emit
from conftest import distance_mm

PRESSES = [(30.0, 30.0), (15.0, 42.0), (45.0, 18.0), (20.0, 20.0)]


@pytest.fixture(scope="module")
def frames(twin):
    return twin.frames([[emit.Press(x, y, force_N=10)] for x, y in PRESSES])


def test_the_paper_method_places_single_presses(paper, frames):
    for (x, y), frame in zip(PRESSES, frames):
        contacts = paper.reconstruct(frame)
        assert len(contacts) >= 1
        # The README's p95 of the paper method's position error on this sheet is 8.05 mm.
        assert distance_mm(contacts[0], x, y) < 8.05


def test_contact_fitting_places_single_presses(sensor, reference, frames):
    fit = emit.Reconstructor(sensor, method="fit")
    fit.set_reference(reference)
    for (x, y), frame in zip(PRESSES, frames):
        contacts = fit.reconstruct(frame)
        assert len(contacts) == 1
        # The README's p95 of contact fitting's error is 0.13 mm; 0.5 mm leaves room for this
        # twin mesh's seed and noise.
        assert distance_mm(contacts[0], x, y) < 0.5
    # A fit that explains the frame leaves its noise: the ADC's 1 mV on the frame and on the
    # 10-frame reference (sqrt(1.1) mV), with 12-bit quantisation (0.23 mV), 1.08 mV in all;
    # half as much again for the model's error on the twin's other mesh.
    assert fit.fit_rms_misfit_mV is not None and fit.fit_rms_misfit_mV < 1.5 * 1.08


def test_a_stack_gives_each_frames_contacts(paper, frames):
    rows = paper.reconstruct(frames)
    assert rows.dtype == emit.CONTACT_DTYPE
    for f, frame in enumerate(frames):
        single = paper.reconstruct(frame)
        mine = rows[rows["frame"] == f]
        assert len(mine) == len(single)
        for row, contact in zip(mine, single):
            for name, value in contact.as_dict().items():
                assert row[name] == value, name  # the same computation: equal, not close
    # Split over two threads, the same contacts in the same order.
    assert np.array_equal(paper.reconstruct(frames, threads=2), rows)


def test_pressure_images_match_the_contacts(paper, frames):
    rows, images = paper.reconstruct(frames, pressure=True)
    assert images.shape == (len(frames), paper.mesh.triangle_count)
    assert (images >= 0).all()
    for f in range(len(frames)):
        # The image's largest element lies in a contact: it is the strongest contact's peak.
        assert images[f].max() == pytest.approx(rows[rows["frame"] == f]["peak_pressure_N_per_mm2"].max(), rel=1e-12)
    contacts, image = paper.reconstruct(frames[0], pressure=True)
    assert np.array_equal(image, images[0])
    assert np.array_equal(paper.pressure, images[0])


def test_python_gives_the_clis_contacts(cli, paper, reference, frames, tmp_path):
    # The same frames through `emit reconstruct` (files) and through Python (arrays) and its
    # Tracker (the CLI's, at the CLI's 50 frames/s): the same touches to the last digit the CLI writes.
    np.savetxt(tmp_path / "ref.csv", reference.reshape(len(reference), -1), delimiter=",", fmt="%.17g")
    np.savetxt(tmp_path / "frames.csv", frames.reshape(len(frames), -1), delimiter=",", fmt="%.17g")
    subprocess.run(
        [cli, "reconstruct", "--method", "paper", "--reference", tmp_path / "ref.csv", "--frames", tmp_path / "frames.csv",
         "--contacts", tmp_path / "contacts.jsonl", "--cache", tmp_path / "cache"],
        check=True, capture_output=True)
    lines = [json.loads(line) for line in open(tmp_path / "contacts.jsonl")]
    assert len(lines) == len(frames)
    tracker = emit.Tracker()
    for f, (line, frame) in enumerate(zip(lines, frames)):
        mine = tracker.update(paper.reconstruct(frame), f / 50)
        assert line["board_time_s"] == pytest.approx(f / 50, rel=1e-9)
        assert [c["id"] for c in line.get("ended", [])] == [c.id for c in tracker.ended]
        assert len(line["contacts"]) == len(mine)
        for theirs, contact in zip(line["contacts"], mine):
            fields = contact.as_dict()
            assert {"x_mm", "y_mm", "force_N"} <= theirs.keys()
            # The outline's polygon: a (K, 2) array, counter-clockwise, the CLI's vertices.
            outline = theirs.pop("outline_mm")
            assert contact.outline_mm.shape == (len(outline), 2) and len(outline) >= 3
            assert contact.outline_mm == pytest.approx(np.array(outline), rel=1e-5, abs=1e-12)
            x, y = contact.outline_mm.T
            assert np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)) > 0
            assert theirs.pop("phase") == contact.phase in ("down", "move")
            for key, value in theirs.items():
                # The CLI writes 6 significant digits (io/contacts_jsonl).
                assert fields[key] == pytest.approx(value, rel=1e-5, abs=1e-12), key


def test_the_reference_is_averaged_leaving_out_a_touched_frame(sensor, reference, frames):
    # A touched frame among the reference frames is an outlier the average leaves out: the
    # reference is then the untouched one, and a press is found where it was.
    with_glitch = np.concatenate([reference, frames[:1]])
    reconstructor = emit.Reconstructor(sensor, method="paper")
    reconstructor.set_reference(with_glitch)
    x, y = PRESSES[1]
    assert distance_mm(reconstructor.reconstruct(frames[1])[0], x, y) < 8.05
