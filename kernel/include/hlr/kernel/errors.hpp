// Errors the library's jobs throw to their caller (the hlr program prints them as one line).
#pragma once

#include <stdexcept>
#include <string>

namespace hlr {

// A problem with a file the user named, or with input standing for one (an input that is not
// valid, an output that cannot be written). what() is "FILE: problem", one line.
struct UserError : std::runtime_error {
  UserError(const std::string& file, const std::string& problem) : std::runtime_error(file + ": " + problem) {}
};

// A job stopped because its caller asked it to (Progress::cancelled, hidden_line/jobs.hpp).
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace hlr
