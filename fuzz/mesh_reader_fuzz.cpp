// The mesh readers (OFF, OBJ, STL ASCII and binary, PLY ASCII and binary) and the face
// preparation behind them: the first byte picks the format, the rest is the file.
#include "harness.hpp"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const formats[] = {".off", ".obj", ".stl", ".ply"};
  const std::string extension = formats[data[0] % 4];
  std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  return hlr::fuzz::refused_or_done([&] {
    hlr::ImportReport report;
    (void)hlr::parse_mesh("fuzz" + extension, extension, std::move(bytes), report);
  });
}
