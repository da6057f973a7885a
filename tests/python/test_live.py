"""emit.LiveStream: live sources as Python iterators of (frame, contacts)."""

import os
import subprocess
import threading
import time
import tty

import numpy as np
import pytest

import emit
from conftest import distance_mm


def test_a_held_press_from_the_twin(sensor):
    stream = emit.LiveStream("sim:fixed:20,40,10", sensor, method="paper", frames_per_s=0, max_frames=10)
    frames = list(stream)
    # max_frames reconstructed frames after the baseline's capture of 10; the twin's first 15
    # frames are untouched, so 5 untouched frames come first, then 5 of the press.
    assert len(frames) == 10
    for frame, contacts in frames[:5]:
        assert frame.shape == (16, 16)
        assert contacts == []  # a frame without a press reports nothing (README, 1 % false alarms)
    for frame, contacts in frames[5:]:
        assert len(contacts) >= 1
        # The README's p95 of the paper method's position error on this sheet is 8.05 mm.
        assert distance_mm(contacts[0], 20, 40) < 8.05
    assert stream.sequence == 19
    assert stream.pressure.shape == (stream.mesh.triangle_count,)
    assert stream.frames_missed == 0


def test_each_frame_has_its_board_and_host_times(sensor):
    # A paced twin takes frame k at k / 5 s on its clock (a pace any build keeps: a slower twin
    # would run at the rate it can, twin/sim_source.hpp); each frame reaches the host at a time of
    # the host's system clock (time.time()'s), in order, during this test.
    stream = emit.LiveStream("sim:fixed:20,40,10", sensor, method="paper", frames_per_s=5, max_frames=5,
                             capture_frames=2)
    started = time.time()
    times = [(stream.sequence, stream.board_time_s, stream.host_time_s) for _ in stream]
    assert len(times) == 5
    for sequence, board_s, host_s in times:
        assert board_s == pytest.approx(sequence / 5, abs=1e-9)
        assert started - 1 <= host_s <= time.time()
    assert all(b[2] >= a[2] for a, b in zip(times, times[1:]))


def test_a_recording_ends_the_iteration(cli, sensor, tmp_path):
    subprocess.run([cli, "live", "--source", "sim:fixed:30,30,10", "--fps", "0", "--frames", "20",
                    "--record", tmp_path / "rec.emitrec", "--method", "paper", "--cache", tmp_path / "cache"],
                   check=True, capture_output=True)
    stream = emit.LiveStream(f"file:{tmp_path / 'rec.emitrec'}", sensor, method="paper", frames_per_s=0)
    frames = list(stream)
    # The recording holds all 30 frames the CLI handled (its baseline's 10 included): the stream
    # captures its own 10 and reconstructs the other 20, and ends there. The twin's first 15 are
    # untouched; the last 15 show the press near (30, 30).
    assert len(frames) == 20
    assert all(contacts == [] for _, contacts in frames[:5])
    assert all(contacts and distance_mm(contacts[0], 30, 30) < 8.05 for _, contacts in frames[5:])


def test_a_board_on_a_serial_port(cli, sensor, tmp_path):
    # A real serial port's other end: a pseudo-terminal, into which the test writes the packets a
    # board sent (a recording's bytes after its 32-byte header: docs/recording.md), as a board would.
    subprocess.run([cli, "live", "--source", "sim:fixed:20,40,10", "--fps", "0", "--frames", "15",
                    "--record", tmp_path / "board.emitrec", "--method", "paper", "--cache", tmp_path / "cache"],
                   check=True, capture_output=True)
    packets = (tmp_path / "board.emitrec").read_bytes()[32:]
    board, port = os.openpty()
    tty.setraw(board)
    writer = threading.Thread(target=lambda: os.write(board, packets))
    writer.start()
    stream = emit.LiveStream(f"serial:{os.ttyname(port)}", sensor, method="paper", max_frames=15)
    frames = list(stream)
    writer.join()
    os.close(board)
    os.close(port)
    # The 25 frames the board sent: 10 for the baseline, 5 untouched, 10 pressed at (20, 40).
    assert len(frames) == 15
    assert all(contacts == [] for _, contacts in frames[:5])
    assert all(contacts and distance_mm(contacts[0], 20, 40) < 8.05 for _, contacts in frames[5:])
    assert [stream.sequence, stream.frames_missed] == [24, 0]


def test_waiting_for_frames_releases_the_gil(sensor):
    # A paced source (10 frames/s) keeps the iterator waiting; a Python thread must run meanwhile.
    stream = emit.LiveStream("sim:fixed:30,30,10", sensor, method="paper", frames_per_s=10, max_frames=3,
                             capture_frames=2)
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    thread = threading.Thread(target=count)
    thread.start()
    start = time.monotonic()
    frames = list(stream)
    elapsed = time.monotonic() - start
    stop.set()
    thread.join()
    assert len(frames) == 3
    # 5 frames at 10 frames/s: about half a second of waiting, during which a Python loop counts
    # to many thousands; were the GIL held it would barely start (the interpreter hands the GIL
    # over every 5 ms only between Python bytecodes).
    assert elapsed > 0.3
    assert counter[0] > 10000


def test_a_failing_source_raises_its_message(cli, sensor, tmp_path):
    # A recording cut 100 bytes into its last packet (a crashed run's): its 29 whole frames come
    # (10 for the baseline, 19 reconstructed), then emit.IoError naming the file, the frame and
    # the byte (32 + 29 * 532 = 15460); never a quiet end of the iteration.
    subprocess.run([cli, "live", "--source", "sim:fixed:30,30,10", "--fps", "0", "--frames", "20",
                    "--record", tmp_path / "rec.emitrec", "--method", "paper", "--cache", tmp_path / "cache"],
                   check=True, capture_output=True)
    cut = tmp_path / "cut.emitrec"
    cut.write_bytes((tmp_path / "rec.emitrec").read_bytes()[:-100])
    stream = emit.LiveStream(f"file:{cut}", sensor, method="paper", frames_per_s=0)
    frames = []
    with pytest.raises(emit.IoError) as failure:
        for frame in stream:
            frames.append(frame)
    assert str(failure.value) == f"{cut}: truncated: frame 29 (byte 15460) has 432 of its 532 bytes"
    assert len(frames) == 19


def test_a_serial_port_removed_for_good_raises_its_message(sensor):
    # The board's port closed for good: retried for reconnect_s (here 1 s), then emit.IoError.
    board, port = os.openpty()
    tty.setraw(board)
    path = os.ttyname(port)
    stream = emit.LiveStream(f"serial:{path}", sensor, method="paper", reconnect_s=1.0)
    os.close(board)
    os.close(port)
    start = time.monotonic()
    with pytest.raises(emit.IoError) as failure:
        next(stream)
    assert time.monotonic() - start >= 1.0
    assert str(failure.value).startswith(f"serial:{path} at 921600 baud: disconnected for 1 s and not back (")
