#pragma once
/// \file errors.hpp
/// Typed exceptions at the library boundary. Each message is one line that says what is wrong
/// and where (a key, a file and line, a frame); the CLI prints it as `emit: <message>`.
#include <stdexcept>
#include <string>

namespace emit {

/// Base of every error emit throws on purpose.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The user's input is wrong: a sensor file key, a press, a frame, a mesh file's content.
struct InvalidInput : Error {
  using Error::Error;
};

/// A file could not be read or written.
struct IoError : Error {
  using Error::Error;
};

/// A numerical method failed (e.g. a matrix that should be positive definite is not).
struct SolverError : Error {
  using Error::Error;
};

}  // namespace emit
