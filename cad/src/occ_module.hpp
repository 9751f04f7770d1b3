// The boundary between hlr_cad (linked into the program) and hlr_cad_occ, the module that holds
// every OpenCASCADE call and is loaded with dlopen on the first CAD file. OpenCASCADE's 29
// libraries cost about 20x a mesh run's start-up to load and relocate (docs/BENCHMARKS.md,
// "Start-up"), so a run on meshes does not load them at all.
#pragma once

#include <hlr/cad/cad.hpp>

#include <string>
#include <vector>

namespace hlr::cad::detail {

// The module's one exported symbol: reads and tessellates one model into parts, or throws
// ImportError. Both sides are built by this project with one compiler and one standard library,
// so C++ types and exceptions cross the boundary.
using ReadModelFunction = void(const std::string& path, const CadOptions& options, std::vector<CadPart>& parts);
inline constexpr const char* kReadModelSymbol = "hlr_cad_read_model";

}  // namespace hlr::cad::detail
