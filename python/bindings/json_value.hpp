#pragma once
/// \file json_value.hpp
/// Python values as the JSON the library reads (a sensor dict for sensor/sensor_json.hpp),
/// converted directly, not through json.dumps's text: a value JSON text cannot hold is then
/// either kept for the library to judge by its own rule, or refused here naming its key, never
/// a JSON parser's message. NaN and ±infinity stay numbers (the sensor's reader refuses them
/// as it refuses any number out of range: "shape.width_mm: must be a finite number, got nan"); an
/// int beyond 64 bits becomes ±infinity (10**400, as 1e400 would); text that is not Unicode (a
/// lone surrogate), a key that is not a string, a value of no JSON kind, or nesting deeper than
/// a sensor's are refused.
#include <string>

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace emit::python {

/// `value` (dict, list, tuple, str, int, float, bool, None; numpy scalars by their int or float)
/// as JSON. \throw InvalidInput "<key path>: <what is wrong>" ("electrodes[2].x_mm: …"), the key
/// path as the sensor's reader names keys.
nlohmann::json json_of(const pybind11::handle& value);

}  // namespace emit::python
