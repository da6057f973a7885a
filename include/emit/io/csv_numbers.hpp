#pragma once
/// \file csv_numbers.hpp
/// One line of comma-separated numbers, as the frames files and a real skin's folder hold them
/// (io/frames_csv.hpp, io/real_dataset.hpp): blanks around a value allowed, every value finite.
#include <string>
#include <vector>

#include "emit/io/line_reader.hpp"

namespace emit {

/// The numbers of `line` into `values` (cleared first; a caller that keeps it allocates nothing
/// once it has grown). `nan`, `inf` are taken only with allow_not_finite (a real board's readings,
/// to be masked). \throw InvalidInput "<path>:<line>: value k \"text\" is not a number" or
/// "… value k is inf", `lines` naming the place.
void parse_csv_numbers(const std::string& line, const LineReader& lines, std::vector<double>& values,
                       bool allow_not_finite = false);

}  // namespace emit
