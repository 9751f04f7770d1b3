// Errors the hlr program reports to its user: one line on stderr, "hlr: FILE: problem", exit 1.
#pragma once

#include <hlr/kernel/errors.hpp>

#include <stdexcept>
#include <string>

namespace hlr::app {

// A problem with a file the user named; main prints what() behind "hlr: ".
using hlr::UserError;

// A command line that cannot be carried out, found only once the work has begun (a --scale at
// which the drawing does not fit its sheet). what() is "OPTION VALUE: problem"; exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Exit codes of the hlr program.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInputError = 1;  // bad input or unwritable output: a UserError
inline constexpr int kExitUsage = 2;       // bad command line
inline constexpr int kExitContract = 3;    // a result breaks a promise of the exact path (a bug)
inline constexpr int kExitTimeout = 124;   // --timeout reached (as timeout(1) exits); signals: 128 + N

}  // namespace hlr::app
