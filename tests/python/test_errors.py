"""Bad input from Python: one clear error each (emit's one-line message, a Python exception of
the right kind), and nothing changed by the call that failed."""

import json

import numpy as np
import pytest

import emit
from conftest import EXAMPLES


def test_errors_are_python_exceptions_of_their_kind():
    assert issubclass(emit.InvalidInput, emit.Error) and issubclass(emit.InvalidInput, ValueError)
    assert issubclass(emit.IoError, emit.Error) and issubclass(emit.IoError, OSError)
    assert issubclass(emit.SolverError, emit.Error) and issubclass(emit.SolverError, RuntimeError)


def test_a_wrong_shaped_array(paper):
    with pytest.raises(emit.InvalidInput, match=r"^frames: expected an \(N, N\) or \(frames, N, N\) array with "
                                                r"N = 16, got shape \(15, 16\)$"):
        paper.reconstruct(np.zeros((15, 16)))
    with pytest.raises(emit.InvalidInput, match=r"got shape \(256,\)$"):
        paper.reconstruct(np.zeros(256))
    with pytest.raises(emit.InvalidInput, match=r"expected numbers \(float64\), got dtype <U1"):
        paper.reconstruct(np.full((16, 16), "a"))


def test_nan_names_the_frame_and_reading(paper, reference):
    frames = np.repeat(reference[:1], 3, axis=0)
    frames[2, 4, 7] = np.nan
    with pytest.raises(emit.InvalidInput, match=r"^frames: frame 2, value \[4, 7\] is not a finite number \(nan\)$"):
        paper.reconstruct(frames)
    frame = reference[0].copy()
    frame[1, 2] = np.inf
    with pytest.raises(emit.InvalidInput, match=r"^frames: value \[1, 2\] is not a finite number \(inf\)$"):
        paper.reconstruct(frame)
    # The reference the reconstructor holds is untouched by the refused call.
    with pytest.raises(emit.InvalidInput, match=r"^reference: "):
        paper.set_reference(frames)
    assert paper.reconstruct(reference[0]) == []


def test_a_dict_with_an_unknown_key(sensor):
    description = sensor.to_dict()
    description["colour"] = "blue"
    with pytest.raises(emit.InvalidInput, match=r"^sensor dict: colour: unknown key"):
        emit.Sensor.from_dict(description)
    description = sensor.to_dict()
    description["shape"]["width_mm"] = -5
    with pytest.raises(emit.InvalidInput, match=r"^sensor dict: shape\.width_mm: "):
        emit.Sensor.from_dict(description)


def test_a_missing_file_and_an_unknown_method(sensor, tmp_path):
    with pytest.raises(emit.IoError, match=str(tmp_path / "missing.json")):
        emit.Sensor.load(str(tmp_path / "missing.json"))
    with pytest.raises(emit.IoError, match="missing.csv"):
        emit.load_frames(str(tmp_path / "missing.csv"), sensor)
    with pytest.raises(emit.InvalidInput, match=r"unknown method \"magic\""):
        emit.Reconstructor(sensor, method="magic")
    with pytest.raises(emit.InvalidInput, match="sim:nowhere"):
        emit.LiveStream("sim:nowhere", sensor)


def test_a_current_injection_skin_is_not_modelled_as_an_emit_sheet():
    # The hydrogel skin is read (its "excitation" says how it is measured), but the EMIT models
    # refuse it, as the CLI's commands do, before any meshing.
    hydrogel = emit.Sensor.load(str(EXAMPLES / "hydrogel_hardman.json"))
    for build in (lambda: emit.Reconstructor(hydrogel, method="paper"), lambda: emit.Twin(hydrogel)):
        with pytest.raises(emit.InvalidInput, match=r'^sensor "[^"]*": is a current-injection skin'):
            build()


def test_a_bad_frames_file_names_its_line(sensor, tmp_path):
    (tmp_path / "bad.csv").write_text(",".join(["1"] * 256) + "\n" + ",".join(["1"] * 255) + ",x\n")
    with pytest.raises(emit.InvalidInput, match=r"bad\.csv:2: "):
        emit.load_frames(str(tmp_path / "bad.csv"), sensor)


def test_no_reference_yet(sensor, reference):
    reconstructor = emit.Reconstructor(sensor, method="paper")
    with pytest.raises(emit.InvalidInput, match=r"^no reference frame yet: call set_reference"):
        reconstructor.reconstruct(reference[0])


def test_a_calibration_of_the_wrong_kind(sensor, tmp_path):
    (tmp_path / "fit.json").write_text('{"alpha_ohm_mm2": 2000, "gamma": -1.2}')
    calibration = emit.Calibration.load(str(tmp_path / "fit.json"))
    assert calibration.kind == "fit"
    with pytest.raises(emit.InvalidInput, match=r"a calibration for contact fitting"):
        emit.Reconstructor(sensor, method="paper", calibration=calibration)
    with pytest.raises(emit.InvalidInput, match=r"unknown key"):
        (tmp_path / "bad.json").write_text('{"a1": 1, "colour": 2}')
        emit.Calibration.load(str(tmp_path / "bad.json"))


def test_saving_into_a_missing_folder_writes_nothing(tmp_path):
    (tmp_path / "linear.json").write_text('{"a1": 0.1, "a2": 0.0, "a3": 0.0}')
    calibration = emit.Calibration.load(str(tmp_path / "linear.json"))
    assert calibration.kind == "linear" and calibration.rms_N_per_mm2 is None
    with pytest.raises(emit.IoError):
        calibration.save(str(tmp_path / "no" / "such" / "folder" / "c.json"))
    assert not (tmp_path / "no").exists()
    # Saved and read back, the same coefficients (to the digits JSON keeps).
    calibration.save(str(tmp_path / "again.json"))
    assert json.loads((tmp_path / "again.json").read_text()) == pytest.approx({"a1": 0.1, "a2": 0.0, "a3": 0.0})
