#pragma once
/// \file quote_input.hpp
/// A piece of the user's input inside a one-line error message: quoted, at most `max_chars`
/// characters (then "..."), control characters and bytes that are not UTF-8 written as \xNN, so a
/// binary file, a 4 KB line or a byte-order mark never reach the terminal raw.
#include <cstddef>
#include <string>
#include <string_view>

namespace emit {

/// `"text"`, shortened and escaped as above. Example: quote_input("a\tb") is `"a\x09b"`.
std::string quote_input(std::string_view text, std::size_t max_chars = 40);

}  // namespace emit
