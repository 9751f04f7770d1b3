// The parts every JSON document of hlr writes alike: "input" and "view" (DESIGN.md, hlr-lines/1).
// Defined in lines_json.cpp.
#pragma once

#include <hlr/export/surfaces.hpp>

#include <nlohmann/json.hpp>

namespace hlr::exporter::detail {

nlohmann::json input_json(const InputInfo& input);
nlohmann::json view_json(const ViewInfo& view);

}  // namespace hlr::exporter::detail
