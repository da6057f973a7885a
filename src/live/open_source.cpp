#include "emit/live/open_source.hpp"

#include "emit/acquire/device_source.hpp"
#include "emit/core/errors.hpp"
#include "emit/twin/sim_source.hpp"

namespace emit {

std::unique_ptr<FrameSource> open_source(const std::string& spec, const Sensor& sensor, const SourceOptions& options) {
  options.validate();
  if (spec == "sim" || spec.rfind("sim:", 0) == 0) {
    if (options.loop)
      throw InvalidInput("source \"" + spec + "\": only a recording (file:PATH) can be replayed in a loop");
    return std::make_unique<SimSource>(sensor, parse_sim_script(spec), options);
  }
  if (auto device = open_device_source(spec, sensor, options)) return device;
  throw InvalidInput("source \"" + spec +
                     "\": unknown; expected sim, sim:random, sim:fixed[:X,Y[,F]], file:PATH or serial:PATH[@BAUD]");
}

}  // namespace emit
