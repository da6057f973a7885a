#include "emit/acquire/frame_source.hpp"

#include "emit/acquire/sim_source.hpp"
#include "emit/errors.hpp"

namespace emit {

std::unique_ptr<FrameSource> open_source(const std::string& spec, const Sensor& sensor, const SourceOptions& options) {
  if (spec == "sim" || spec.rfind("sim:", 0) == 0)
    return std::make_unique<SimSource>(sensor, parse_sim_script(spec), options);
  // file:PATH and serial:PATH join here.
  throw InvalidInput("source \"" + spec + "\": unknown; expected sim, sim:random or sim:fixed:X,Y[,F]");
}

}  // namespace emit
