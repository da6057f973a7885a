#!/usr/bin/env python3
"""emit from Python in one page: simulate two presses on the built-in sensor, reconstruct them by
contact fitting and by the paper's method, and draw contact fitting's pressure map and the paper
method's image (eq. 7) with the contacts each found.

    PYTHONPATH=build/python python3 examples/python/quickstart.py [quickstart.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")  # files, no window
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

import emit

out = sys.argv[1] if len(sys.argv) > 1 else "quickstart.png"

sensor = emit.Sensor.default()  # the paper's 60 x 60 mm sheet, 16 electrodes
twin = emit.Twin(sensor, mesh_seed=3)  # the digital twin, on its own finer mesh
presses = [emit.Press(18, 40, force_N=8), emit.Press(42, 22, force_N=14)]
reference = twin.frames([[] for _ in range(10)])  # untouched frames
frame = twin.frame(presses)  # (16, 16) volts

figure, axes = plt.subplots(1, 2, figsize=(11, 5), constrained_layout=True)
for axis, method in zip(axes, ["fit", "paper"]):
    reconstructor = emit.Reconstructor(sensor, method=method)
    reconstructor.set_reference(reference)
    contacts, pressure = reconstructor.reconstruct(frame, pressure=True)
    # Uncalibrated, forces come from the sensor file's nominal contact law, not from presses of
    # known force: their scale is off (emit.calibrate fits it; README "Calibration").
    state = "calibrated" if reconstructor.calibrated else "uncalibrated: forces from the nominal contact law"
    print(f"{method} ({state}):")
    for c in contacts:
        print(f"  contact at ({c.x_mm:5.1f}, {c.y_mm:5.1f}) mm, {c.force_N:5.2f} N, {c.area_mm2:5.1f} mm^2")

    mesh = reconstructor.mesh
    triangles = mesh.nodes_mm[:, :2][mesh.triangles]  # (F, 3, 2): each triangle's corners
    shown, label = (pressure, "pressure [N/mm²]") if method == "fit" else (reconstructor.image, "image δφ [V]")
    cells = PolyCollection(triangles, array=shown, cmap="magma", edgecolors="face")
    axis.add_collection(cells)
    figure.colorbar(cells, ax=axis, label=label)
    axis.scatter([p.x_mm for p in presses], [p.y_mm for p in presses], marker="+", s=200, c="cyan",
                 label="pressed (8 N, 14 N)")
    axis.scatter([c.x_mm for c in contacts], [c.y_mm for c in contacts], marker="x", s=120, c="lime",
                 label="found")
    title = {"fit": "contact fitting: pressure (uncalibrated)",
             "paper": "the paper's method (eq. 7): its image δφ,\none blur over both presses"}[method]
    axis.set(title=title, xlabel="x [mm]", ylabel="y [mm]", aspect="equal")
    axis.autoscale_view()
    axis.legend(loc="upper right")

figure.savefig(out, dpi=100)
print(f"wrote {out}")
