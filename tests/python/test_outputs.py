"""Outputs from Python follow emit's one rule (core/output_file.hpp): a regular file is replaced
whole through a temporary file; a device is written into, never replaced, and a failed write is
an emit.IoError naming the path. The devices are private nodes in a temporary folder (mknod,
root only), never the machine's own /dev/null or /dev/full."""

import os
import stat

import pytest

import emit

needs_root = pytest.mark.skipif(os.geteuid() != 0, reason="mknod needs root")


def linear_calibration(tmp_path):
    (tmp_path / "linear.json").write_text('{"a1": 0.1, "a2": 0.0, "a3": 0.0}')
    return emit.Calibration.load(str(tmp_path / "linear.json"))


@needs_root
def test_saving_to_a_device_writes_into_it(tmp_path):
    calibration = linear_calibration(tmp_path)
    null = tmp_path / "null"
    os.mknod(null, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
    calibration.save(str(null))
    assert stat.S_ISCHR(os.stat(null).st_mode), "the device node was replaced by a file"
    full = tmp_path / "full"
    os.mknod(full, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
    with pytest.raises(emit.IoError, match=r"^" + str(full) + r": write failed \(No space left on device\)$"):
        calibration.save(str(full))
    assert stat.S_ISCHR(os.stat(full).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["full", "linear.json", "null"]  # no temporary file left
