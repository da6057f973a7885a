#include "emit/acquire/frame_source.hpp"

#include "emit/core/option_check.hpp"

namespace emit {

void SourceOptions::validate() const {
  option_check::non_negative("SourceOptions", "frames_per_s", frames_per_s);
  option_check::at_least("SourceOptions", "untouched_frames", untouched_frames, 0);
  option_check::positive("SourceOptions", "reconnect_s", reconnect_s);
}

}  // namespace emit
