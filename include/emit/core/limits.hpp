#pragma once
/// \file limits.hpp
/// The largest sizes a user can ask emit for, in one place: the thread count (the CLI's
/// --threads, Python's threads=) and the frames a run holds in memory (`emit simulate`'s
/// --frames and its grid's --spacing-mm, Python's simulate()). Each is checked before any work,
/// by the CLI and the Python module alike, and refused in one line naming the option and the
/// limit. They are there to refuse a typo (--threads 1000000000 asked for 4 GB; --spacing-mm 0.01
/// a grid of 36 million presses), not to tune: each lies far beyond what a run needs.
/// (Meshes have their own limit, the sensor's mesh.max_triangles: mesh/generate_mesh.hpp.)
#include <cstddef>
#include <string>

namespace emit::limits {

/// The most threads emit runs a computation on. Threads beyond the cores buy no speed (the work
/// is arithmetic), and each costs memory: a batch worker its own reconstructor's scratch (up to a
/// few MB on a 100k-triangle mesh), the BLAS its buffers. 256 is twice the cores of the largest
/// two-socket servers of today (2 × 64): room for any machine emit runs on, while 256 workers
/// reconstructing a frame of the default sensor cost 0.3–0.5 s and 10–30 MB more than one.
inline constexpr int max_threads = 256;

/// What a thread count must be, as messages say it: "a whole number from 1 to 256 (…)".
std::string thread_count_rule();

/// \throw InvalidInput "<name> must be <thread_count_rule()>, got <count>" unless
/// 1 ≤ count ≤ max_threads.
void check_thread_count(const std::string& name, long long count);

/// The memory a run may hold its frames in: 256 MiB of readings, 131,072 frames of 16
/// electrodes (32,768 of 32). A twin frame takes 10–40 ms, so that many already take one to two
/// hours; the frames, their presses and the CSV text stay within 1 GB.
inline constexpr std::size_t max_frames_bytes = std::size_t{256} << 20;

/// The frames of `electrodes` × `electrodes` readings that fit in max_frames_bytes.
long long max_frames_held(int electrodes);

/// \throw InvalidInput "<what>: <frames> frames of <N> electrodes, beyond the <max> a run holds
/// in memory (256 MiB of readings); <advice>" unless frames ≤ max_frames_held(electrodes).
/// `what` names the option and its value ("--frames 1000000000").
void check_frames_held(const std::string& what, double frames, int electrodes, const std::string& advice);

}  // namespace emit::limits
