#include "emit/model/reading_screen.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "emit/core/errors.hpp"

namespace emit {

void ReadingSurveyOptions::validate() const {
  if (!std::isnan(rail) && !(rail > 0))
    throw InvalidInput("rail: must be a positive reading (or not given, to find it), got " + std::to_string(rail));
  if (!(rail_frames > 0 && rail_frames <= 1))
    throw InvalidInput("rail frames: must be in (0, 1], got " + std::to_string(rail_frames));
  if (!(drop_above >= 0 && drop_above < 1))
    throw InvalidInput("drop above: must be in [0, 1), got " + std::to_string(drop_above));
}

std::vector<Index> ReadingSurvey::dropped() const {
  std::vector<Index> out;
  for (Index m = 0; m < static_cast<Index>(screen.dropped.size()); ++m)
    if (screen.is_dropped(m)) out.push_back(m);
  return out;
}

std::vector<Index> ReadingSurvey::worst(std::size_t count) const {
  std::vector<Index> order(bad_frames.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    return bad_frames[static_cast<std::size_t>(a)] > bad_frames[static_cast<std::size_t>(b)];
  });
  std::vector<Index> out;
  for (const Index m : order)
    if (out.size() < count && bad_frames[static_cast<std::size_t>(m)] > 0) out.push_back(m);
  return out;
}

ReadingSurvey survey_readings(const Matrix& frames, const Matrix& references, const ReadingSurveyOptions& options) {
  options.validate();
  if (frames.rows() != references.rows() || frames.cols() != references.cols())
    throw InvalidInput("reading survey: " + std::to_string(frames.rows()) + " × " + std::to_string(frames.cols()) +
                       " frames against " + std::to_string(references.rows()) + " × " +
                       std::to_string(references.cols()) + " references");
  const Index n = frames.rows(), M = frames.cols();
  ReadingSurvey s;
  s.screen.rail = options.rail;
  if (std::isnan(options.rail)) {
    // The largest finite value; a rail when it recurs in enough frames.
    double top = -std::numeric_limits<double>::infinity();
    for (const Matrix* a : {&frames, &references})
      for (Index i = 0; i < n; ++i)
        for (Index m = 0; m < M; ++m)
          if (const double v = (*a)(i, m); std::isfinite(v)) top = std::max(top, v);
    Index at_top = 0;
    for (Index i = 0; i < n; ++i)
      if ((frames.row(i).array() == top).any() || (references.row(i).array() == top).any()) ++at_top;
    s.rail_found = n > 0 && at_top >= 2 && static_cast<double>(at_top) >= options.rail_frames * static_cast<double>(n);
    s.screen.rail = s.rail_found ? top : std::numeric_limits<double>::infinity();
  }
  s.bad_frames.assign(static_cast<std::size_t>(M), 0);
  s.screen.dropped.assign(static_cast<std::size_t>(M), 0);
  for (Index m = 0; m < M; ++m) {
    bool one_value = n > 0;
    for (Index i = 0; i < n; ++i) {
      if (!s.screen.usable(frames(i, m), references(i, m))) ++s.bad_frames[static_cast<std::size_t>(m)];
      one_value = one_value && frames(i, m) == frames(0, m) && references(i, m) == frames(0, m);
    }
    if (one_value) s.stuck.push_back(m);
    if (one_value ||
        static_cast<double>(s.bad_frames[static_cast<std::size_t>(m)]) > options.drop_above * static_cast<double>(n))
      s.screen.dropped[static_cast<std::size_t>(m)] = 1;
  }
  for (Index i = 0; i < n; ++i) {
    Index bad = 0;
    for (Index m = 0; m < M; ++m)
      if (!s.screen.is_dropped(m) && !s.screen.usable(frames(i, m), references(i, m))) ++bad;
    s.masked_readings += bad;
    if (bad > 0) ++s.frames_with_bad;
  }
  return s;
}

}  // namespace emit
