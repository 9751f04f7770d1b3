// Lights from the command line (light_options.hpp).
#include "light_options.hpp"

#include <cstdlib>

namespace hlr::app {

Vec3 parse_vector(const std::string& option, const std::string& text) {
  Vec3 v{};
  std::size_t at = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', at);
    const std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    char* end = nullptr;
    v[i] = std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || (i < 2) != (comma != std::string::npos))
      throw UsageError(option + " " + text + ": expected three numbers X,Y,Z");
    at = comma + 1;
  }
  return v;
}

namespace {

std::vector<hidden_line::Light> parse_lights(const char* option, hidden_line::Light::Kind kind,
                                             const std::vector<std::string>& texts) {
  std::vector<hidden_line::Light> out;
  for (const auto& s : texts) {
    hidden_line::Light light{kind, parse_vector(option, s)};
    if (auto defect = hidden_line::light_defect(light)) throw UsageError(std::string(option) + " " + s + ": " + *defect);
    out.push_back(light);
  }
  return out;
}

}  // namespace

std::vector<hidden_line::Light> parse_suns(const std::vector<std::string>& suns) {
  return parse_lights("--sun", hidden_line::Light::directional, suns);
}

std::vector<hidden_line::Light> parse_point_lights(const std::vector<std::string>& positions) {
  return parse_lights("--point-light", hidden_line::Light::point, positions);
}

void check_point_lights(const std::vector<Mesh>& meshes, const std::vector<std::string>& positions) {
  const auto lights = parse_point_lights(positions);
  for (std::size_t i = 0; i < lights.size(); ++i)
    if (auto defect = hidden_line::point_light_defect(meshes, lights[i]))
      throw UsageError("--point-light " + positions[i] + ": " + *defect);
}

}  // namespace hlr::app
