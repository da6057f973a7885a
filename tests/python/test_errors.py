"""Bad input from Python: one clear error each (emit's one-line message, a Python exception of
the right kind), and nothing changed by the call that failed."""

import json
import subprocess
import time

import numpy as np
import pytest

import emit
from conftest import EXAMPLES, distance_mm


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


def test_a_reading_nan_or_inf_is_masked_as_the_cli_masks_it(sensor, paper, twin, reference):
    """A board's lost reading (NaN, inf) in a frame or a reference is masked, not an error, as
    `emit reconstruct` masks it (docs/physics.md, "Bad readings"): the press is placed as in the
    clean frame, to a tenth of the paper method's 3.3 mm error on this sheet."""
    clean = twin.frame([emit.Press(34, 24, force_N=10)])
    [expected] = paper.reconstruct(clean)
    glitched = clean.copy()
    glitched[2, 9] = np.nan
    glitched[11, 4] = np.inf
    glitched[5, 6] = 3.3  # the ADC's top code: clipped
    for frame in (glitched, np.stack([clean, glitched])[1]):
        [contact] = paper.reconstruct(frame)
        assert distance_mm(contact, expected.x_mm, expected.y_mm) < 0.33
    stack = paper.reconstruct(np.stack([clean, glitched]))
    assert len(stack) == 2 and abs(stack[1]["x_mm"] - expected.x_mm) < 0.33
    # A reference whose frames lost a reading: left out of its mean; the press as before.
    lossy = reference.copy()
    lossy[:, 3, 8] = np.nan
    try:
        paper.set_reference(lossy)
        [contact] = paper.reconstruct(clean)
        assert distance_mm(contact, expected.x_mm, expected.y_mm) < 0.33
    finally:
        paper.set_reference(reference)
    # Calibration frames are measurements to fit, not a stream: a NaN there is still refused.
    frames = np.repeat(reference[:1], 3, axis=0)
    frames[2, 4, 7] = np.nan
    with pytest.raises(emit.InvalidInput, match=r"frame 2, value \[4, 7\] is not a finite number \(nan\)"):
        emit.calibrate(sensor, reference, frames, [[emit.Press(30, 30)]] * 3)


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


# What JSON text cannot hold went through json.dumps and came back as the JSON library's
# RuntimeError; now each is emit.InvalidInput naming the key, as Sensor.load names a file's.
@pytest.mark.parametrize("value, shown", [(float("nan"), "nan"), (float("inf"), "inf"), (-float("inf"), "-inf"),
                                          (10**400, "inf"), (-10**400, "-inf")])
def test_a_dict_number_json_cannot_hold_names_its_key(sensor, value, shown):
    description = sensor.to_dict()
    description["shape"]["width_mm"] = value
    with pytest.raises(emit.InvalidInput,
                       match=rf"^sensor dict: shape\.width_mm: must be a finite number, got {shown}$"):
        emit.Sensor.from_dict(description)


def test_a_dict_value_that_is_not_json_names_its_key(sensor):
    def refused(change):
        description = sensor.to_dict()
        change(description)
        with pytest.raises(emit.InvalidInput) as error:
            emit.Sensor.from_dict(description)
        return str(error.value)

    assert refused(lambda d: d.update(name="\ud800")) == \
        r'sensor dict: name: "\ud800" is not Unicode text (a lone surrogate)'
    assert refused(lambda d: d["shape"].update({"\udc80": 1})) == \
        r'sensor dict: shape: the key "\udc80" is not Unicode text (a lone surrogate)'
    assert refused(lambda d: d["shape"].update({3: 1})) == \
        "sensor dict: shape.3: a key must be a string (this one is of type int)"
    assert refused(lambda d: d["adc"].update(bits=object())) == \
        "sensor dict: adc.bits: a value of type object is not JSON (a dict, list, tuple, str, number, bool or None is)"
    nested = []
    for _ in range(100):
        nested = [nested]
    assert refused(lambda d: d.update(name=nested)) == "sensor dict: name" + "[0]" * 64 + ": nested deeper than 64 levels"
    # numpy's scalars and tuples are numbers and lists, as json.dumps took them (or better).
    description = sensor.to_dict()
    description["shape"]["width_mm"] = np.float32(60)
    description["adc"]["bits"] = np.int64(12)
    description["electrodes"] = tuple(description["electrodes"])
    assert emit.Sensor.from_dict(description).electrode_count == 16


def _cli_error(cli, *arguments):
    run = subprocess.run([cli, *arguments], capture_output=True, text=True, timeout=60)
    assert run.returncode in (1, 2), run.stderr
    return run.stderr.strip().splitlines()[-1]


def _write_frames(path, frames):
    np.savetxt(path, np.asarray(frames).reshape(-1, 256), delimiter=",", fmt="%.17g")


# The options' rules are the library's, said in the same words from Python and from the CLI
# (Python took lambda2=nan, -1 or -inf as "automatic" where the CLI refused them in its own words).
@pytest.mark.parametrize("text, value", [("-1", -1.0), ("nan", float("nan")), ("-inf", -float("inf"))])
def test_lambda2_is_refused_as_the_cli_refuses_it(sensor, reference, cli, tmp_path, text, value):
    with pytest.raises(emit.InvalidInput) as error:
        emit.Reconstructor(sensor, method="paper", lambda2=value)
    assert str(error.value) == f"PipelineOptions::lambda2 must be 0 (the method's) or positive, got {text}"
    _write_frames(tmp_path / "ref.csv", reference)
    cli_line = _cli_error(cli, "reconstruct", "--reference", str(tmp_path / "ref.csv"), "--frames",
                          str(tmp_path / "ref.csv"), "--contacts", str(tmp_path / "c.jsonl"), "--lambda2=" + text)
    # The CLI names the option where Python names the field: the rule after it is the same.
    assert cli_line.startswith("emit: --lambda2: " + str(error.value).split(" ", 1)[1]), cli_line
    with pytest.raises(emit.InvalidInput, match=r"^PressCalibrationOptions::lambda2 must be 0 \(the method's\) or "
                                                r"positive, got "):
        emit.calibrate(sensor, reference, reference[:1], [[]], method="paper", lambda2=value)


# Frames in millivolts, or scaled by 1e300, were taken from Python and refused by the CLI: now the
# same check, in the same words after where it is.
@pytest.mark.parametrize("scale", [1e3, 1e300])
def test_frames_no_adc_can_give_are_refused_as_the_cli_refuses_them(paper, twin, reference, cli, tmp_path, scale):
    frame = twin.frame([emit.Press(30, 30)]) * scale
    with pytest.raises(emit.InvalidInput) as error:
        paper.reconstruct(frame)
    message = str(error.value)
    assert message.startswith("frames: ground ") and message.endswith("outside the ADC's 0 to 3.3 V (sensor \"adc\")")
    with pytest.raises(emit.InvalidInput, match=r"^frames: frame 1: ground "):
        paper.reconstruct(np.stack([reference[0], frame]))
    with pytest.raises(emit.InvalidInput, match=r"^reference: ground "):
        paper.set_reference(frame)
    _write_frames(tmp_path / "ref.csv", reference)
    _write_frames(tmp_path / "scaled.csv", frame)
    cli_line = _cli_error(cli, "reconstruct", "--reference", str(tmp_path / "ref.csv"), "--frames",
                          str(tmp_path / "scaled.csv"), "--contacts", str(tmp_path / "c.jsonl"), "--no-cache")
    assert cli_line == "emit: " + str(tmp_path / "scaled.csv") + ":1: " + message[len("frames: "):], cli_line
    assert paper.reconstruct(reference[0]) == []  # the reference held is untouched


# The sizes a user can ask for (core/limits.hpp) are refused before any work, in the CLI's words.
def test_threads_and_frames_beyond_the_limits(sensor, paper, reference):
    start = time.monotonic()
    for threads in (4096, 0, -1):
        with pytest.raises(emit.InvalidInput, match=r"^threads must be a whole number from 1 to 256 \(threads beyond "
                                                    rf"the cores only cost memory\), got {threads}$"):
            paper.reconstruct(reference, threads=threads)
    with pytest.raises(emit.InvalidInput, match=r"^presses: 131073 frames of 16 electrodes, beyond the 131072 a run "
                                                r"holds in memory \(256 MiB of readings\); simulate them in parts$"):
        emit.simulate(sensor, [[]] * 131073)
    assert time.monotonic() - start < 5  # refused, not worked through (4096 threads took 17.6 s)


# A declared contact radius (--contact-radius-mm) is contact fitting's: a linear method's area is
# its image's. Refused before any model is built, in the CLI's words.
def test_a_contact_radius_for_a_linear_method_is_refused(sensor):
    with pytest.raises(emit.InvalidInput) as error:
        emit.Reconstructor(sensor, method="paper", contact_radius_mm=3.0)
    assert str(error.value) == ("a declared contact radius is for contact fitting (fit, shapes), which holds a "
                                "contact's area; paper's comes from its image")
    with pytest.raises(emit.InvalidInput, match=r"^FrameOptions::contact_radius_mm must be 0 or more, got -1"):
        emit.Reconstructor(sensor, method="fit", contact_radius_mm=-1.0)
