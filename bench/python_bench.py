#!/usr/bin/env python3
"""What Python costs over C++ (the targets below), each against its baseline in the same process,
on the same frames and the same Reconstructor (Reconstructor.cpp_seconds_per_frame times the C++
loop alone):

- a contact-fitting frame: reconstruct(frame) from Python, against Reconstructor::process in a C++
  loop (target: at most 10 % more);
- 10,000 paper-method frames as one array: reconstruct(frames) into one structured array, against
  reconstruct_batch on a std::vector<Frame> as `emit reconstruct` runs it (target: at least 90 %
  of the C++ rate).

    PYTHONPATH=build/python python3 bench/python_bench.py [--rounds 5]

Rounds alternate Python and C++ so that both see the same machine; the median of each is reported.
"""

import argparse
import statistics
import time

import numpy as np

import emit


def median_ratio(python, cpp, rounds):
    python_s, cpp_s = [], []
    for _ in range(rounds):
        python_s.append(python())
        cpp_s.append(cpp())
    return statistics.median(python_s), statistics.median(cpp_s)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--fit-frames", type=int, default=200)
    parser.add_argument("--paper-frames", type=int, default=10_000)
    args = parser.parse_args()

    sensor = emit.Sensor.default()
    twin = emit.Twin(sensor, mesh_seed=3)
    rng = np.random.default_rng(1)
    reference = twin.frames([[] for _ in range(10)])
    distinct = twin.frames([[emit.Press(x, y, force_N=f)] for x, y, f in
                            zip(rng.uniform(10, 50, 200), rng.uniform(10, 50, 200), rng.uniform(4, 16, 200))])

    fit = emit.Reconstructor(sensor, method="fit")
    fit.set_reference(reference)
    frames = distinct[: args.fit_frames]

    def python_fit():
        start = time.perf_counter()
        for frame in frames:
            fit.reconstruct(frame)
        return (time.perf_counter() - start) / len(frames)

    p, c = median_ratio(python_fit, lambda: fit.cpp_seconds_per_frame(frames), args.rounds)
    print(f"fit, a frame at a time ({len(frames)} frames): Python {1e3 * p:.3f} ms, C++ {1e3 * c:.3f} ms "
          f"a frame: Python costs {100 * (p / c - 1):+.1f} % (target <= +10 %)")

    paper = emit.Reconstructor(sensor, method="paper")
    paper.set_reference(reference)
    stack = distinct[np.arange(args.paper_frames) % len(distinct)]

    def python_batch():
        start = time.perf_counter()
        paper.reconstruct(stack)
        return (time.perf_counter() - start) / len(stack)

    p, c = median_ratio(python_batch, lambda: paper.cpp_seconds_per_frame(stack, batch=True), args.rounds)
    print(f"paper, {len(stack)} frames as one array: Python {1 / p:,.0f} frames/s, C++ batch {1 / c:,.0f} "
          f"frames/s: {100 * c / p:.1f} % of the C++ rate (target >= 90 %)")


if __name__ == "__main__":
    main()
