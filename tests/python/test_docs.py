"""The README's Python section run exactly as written, and examples/python/quickstart.py."""

import csv
import os
import re
import subprocess
import sys

import numpy as np
import pytest

from conftest import SOURCE_DIR


def readme_section(title):
    text = (SOURCE_DIR / "README.md").read_text()
    start = text.index(f"### {title}")
    end = text.find("\n#", start + 1)
    return text[start:end]


# EMIT_INSTALLED: the installed package's module and command (tests/package/package_test.sh runs
# this test so), not the build tree's.
INSTALLED = bool(os.environ.get("EMIT_INSTALLED"))


def test_the_readme_python_section_as_written(cli, tmp_path):
    section = readme_section("Python (`import emit`)")
    blocks = re.findall(r"```(sh|python)\n(.*?)```", section, re.S)
    shell = [code for kind, code in blocks if kind == "sh"]
    python = [code for kind, code in blocks if kind == "python"]
    assert len(shell) == 1 and len(python) == 1
    # The README runs from the repository with the build in build/: here a folder with the
    # examples, and build/ this build's folder (its emit and its python/).
    (tmp_path / "examples").symlink_to(SOURCE_DIR / "examples")
    (tmp_path / "build").symlink_to(os.path.dirname(cli))
    (tmp_path / "contacts.py").write_text(python[0])
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    for line in shell[0].splitlines():
        command = line.split("#")[0].strip()
        if command.startswith("PYTHONPATH="):
            assignment, interpreter, script = command.split()
            # The README's python3 is Debian's (the one the module is built for).
            assert interpreter == "python3"
            if not INSTALLED:
                environment["PYTHONPATH"] = assignment.split("=", 1)[1]
            where = subprocess.run([sys.executable, "-c", "import emit; print(emit.__file__)"], cwd=tmp_path,
                                   env=environment, check=True, capture_output=True, text=True).stdout
            expected = "/usr/lib/python3/dist-packages/emit/" if INSTALLED else str(tmp_path / "build" / "python")
            assert where.startswith(expected), f"emit imported from {where.strip()}, not {expected}"
            result = subprocess.run([sys.executable, script], cwd=tmp_path, env=environment, check=True,
                                    capture_output=True, text=True)
        else:
            subprocess.run(command, shell=True, cwd=tmp_path, check=True, capture_output=True)
    printed = re.findall(r"frame (\d+): \((\S+), (\S+)\) mm, (\S+) N", result.stdout)
    truth = {}
    for row in csv.DictReader(open(tmp_path / "two_presses.csv")):
        truth.setdefault(int(row["frame"]), []).append((float(row["x_mm"]), float(row["y_mm"])))
    assert sorted(truth) == [0, 1, 2, 3]
    # Every press found, each within contact fitting's bound on the twin (README: two presses
    # 12-40 mm apart both found within 2 mm in 100 % of frames), nothing else.
    assert len(printed) == sum(len(p) for p in truth.values())
    for frame, x, y, force in printed:
        nearest = min(np.hypot(float(x) - tx, float(y) - ty) for tx, ty in truth[int(frame)])
        assert nearest < 2.0
        assert float(force) > 0


def test_the_quickstart_draws_its_picture(tmp_path):
    out = tmp_path / "quickstart.png"
    result = subprocess.run([sys.executable, SOURCE_DIR / "examples" / "python" / "quickstart.py", out],
                            check=True, capture_output=True, text=True)
    fit = result.stdout.split("paper (")[0]
    # Forces printed without a calibration say so.
    assert "fit (uncalibrated: forces from the nominal contact law):" in result.stdout
    assert "paper (uncalibrated: forces from the nominal contact law):" in result.stdout
    found = [tuple(map(float, m)) for m in re.findall(r"contact at \(\s*(\S+),\s*(\S+)\) mm", fit)]
    # Contact fitting finds both presses, (18, 40) and (42, 22), within 0.5 mm (README p95: 0.13 mm).
    assert len(found) == 2
    for x, y in [(18, 40), (42, 22)]:
        assert min(np.hypot(fx - x, fy - y) for fx, fy in found) < 0.5
    # A picture, 1100 x 500 pixels at 100 dpi, as the script sets.
    header = out.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n"
    assert (int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")) == (1100, 500)
