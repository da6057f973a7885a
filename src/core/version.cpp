#include "emit/core/version.hpp"

namespace emit {

const char* version() { return EMIT_VERSION_STRING; }

}  // namespace emit
