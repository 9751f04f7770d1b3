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

std::vector<hidden_line::Light> parse_suns(const std::vector<std::string>& suns) {
  std::vector<hidden_line::Light> out;
  for (const auto& s : suns) {
    hidden_line::Light light{hidden_line::Light::directional, parse_vector("--sun", s)};
    if (auto defect = hidden_line::light_defect(light)) throw UsageError("--sun " + s + ": " + *defect);
    out.push_back(light);
  }
  return out;
}

}  // namespace hlr::app
