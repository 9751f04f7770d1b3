// The parts every JSON document of hlr writes alike: "input" and "view" (DESIGN.md, hlr-lines/1),
// defined in lines_json.cpp, a light as hlr-shadows/1 writes it (shadows_writers.cpp), and a
// top-level member written in its place as dump(1) writes it (lines_json.cpp).
#pragma once

#include <hlr/export/shadows.hpp>
#include <hlr/export/surfaces.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace hlr::exporter::detail {

nlohmann::json input_json(const InputInfo& input);
nlohmann::json view_json(const ViewInfo& view);
nlohmann::json light_json(const hidden_line::Light& light, const LightLabel& label = {});
// Appends `"key": value` as dump(1) writes a member of the top-level object (one level in), after
// a newline; the caller writes the commas and braces between members.
void append_member(std::string& out, std::string_view key, const nlohmann::json& value);

}  // namespace hlr::exporter::detail
