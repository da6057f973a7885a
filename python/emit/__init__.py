"""emit: tomographic tactile sensors, from Python.

Where a sheet is pressed, and how hard, from its electrodes' voltages: the sensor, its mesh, the
digital twin, every reconstruction method with its calibration, and live sources. The numbers are
emit's own (the C++ library, through pybind11); arrays are numpy's.

    import emit
    sensor = emit.Sensor.load("examples/sensors/default60.json")
    reconstructor = emit.Reconstructor(sensor, method="paper")
    reconstructor.set_reference(untouched_frames)       # (N, N) or (K, N, N)
    for contact in reconstructor.reconstruct(frame):    # (N, N): a list of Contact
        print(contact.x_mm, contact.y_mm, contact.force_N)

Errors are emit.InvalidInput (a ValueError), emit.IoError (an OSError) and emit.SolverError (a
RuntimeError), all emit.Error, each carrying emit's one-line message.
"""

from ._emit import (  # noqa: F401  (the package's names; `from emit import *` takes them all)
    CONTACT_DTYPE,
    Calibration,
    Contact,
    Error,
    InvalidInput,
    IoError,
    LiveStream,
    Mesh,
    Press,
    Reconstructor,
    Sensor,
    SolverError,
    Tracker,
    Twin,
    __version__,
    calibrate,
    load_frames,
    methods,
    simulate,
)

