// Lights from the command line, for `hlr shadows` and `hlr draw --sun`: "DX,DY,DZ" parsed into a
// directional light (three finite numbers, taken as exact doubles), or a UsageError naming the
// option and the problem.
#pragma once

#include "errors.hpp"

#include <hlr/hidden_line/shadows.hpp>

#include <string>
#include <vector>

namespace hlr::app {

Vec3 parse_vector(const std::string& option, const std::string& text);
// Each "--sun DX,DY,DZ" a directional light; a zero or non-finite direction is a UsageError.
std::vector<hidden_line::Light> parse_suns(const std::vector<std::string>& suns);

}  // namespace hlr::app
