// The parts every JSON document of hlr writes alike: "input" and "view" (DESIGN.md, hlr-lines/1),
// defined in lines_json.cpp, and a light as hlr-shadows/1 writes it (shadows_writers.cpp).
#pragma once

#include <hlr/export/shadows.hpp>
#include <hlr/export/surfaces.hpp>

#include <nlohmann/json.hpp>

namespace hlr::exporter::detail {

nlohmann::json input_json(const InputInfo& input);
nlohmann::json view_json(const ViewInfo& view);
nlohmann::json light_json(const hidden_line::Light& light, const LightLabel& label = {});

}  // namespace hlr::exporter::detail
