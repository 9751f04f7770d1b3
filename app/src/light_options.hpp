// Lights from the command line, for `hlr shadows` and `hlr draw --sun/--point-light`: "X,Y,Z"
// parsed into a directional or a point light (three finite numbers, taken as exact doubles), or a
// UsageError naming the option and the problem.
#pragma once

#include "errors.hpp"

#include <hlr/hidden_line/shadows.hpp>

#include <string>
#include <vector>

namespace hlr::app {

Vec3 parse_vector(const std::string& option, const std::string& text);
// Each "--sun DX,DY,DZ" a directional light; a zero or non-finite direction is a UsageError.
std::vector<hidden_line::Light> parse_suns(const std::vector<std::string>& suns);
// Each "--point-light X,Y,Z" a point light; a non-finite position is a UsageError.
std::vector<hidden_line::Light> parse_point_lights(const std::vector<std::string>& positions);
// Once the scene is read: a point light that one perspective view from it cannot serve
// (hidden_line::point_light_defect) is a UsageError naming it.
void check_point_lights(const std::vector<Mesh>& meshes, const std::vector<std::string>& positions);

}  // namespace hlr::app
