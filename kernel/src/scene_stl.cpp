// STL, binary and ASCII.
//
// Binary: an 80-byte header, a little-endian uint32 triangle count N, then N records of 50 bytes
// (normal, three corners as float32 x y z, a 2-byte attribute). The file must be 84 + 50 N bytes
// long: shorter is truncated; longer is read with a warning. Normals and attributes are ignored.
// ASCII: "solid NAME", then "facet normal nx ny nz / outer loop / vertex x y z ... / endloop /
// endfacet" blocks, then "endsolid NAME"; several solids may follow each other. Keywords in any
// letter case; coordinates are parsed as doubles (the text is the input). A file without its
// "endsolid" is truncated.
// A file is ASCII when it starts with "solid", holds no NUL byte in its first 512 bytes and is
// not exactly the size a binary STL with its count would have (binary writers may begin their
// header with "solid" too).
//
// STL stores every triangle's corners on their own. Corners are merged into one vertex when their
// coordinates are equal as doubles (after the float -> double conversion for binary files, which
// is exact), with -0 and +0 equal; vertices are numbered in order of first appearance. Nothing
// else is merged: corners that differ in the last bit stay apart, and so do their edges.
#include "scene_readers.hpp"

#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace hlr::scene_detail {

namespace {

// Numbers corners by first appearance; equal coordinates (== on double, so -0 == +0) share one.
class CornerMerger {
 public:
  explicit CornerMerger(RawMesh& mesh) : mesh_(mesh) {}
  std::uint32_t index(const std::array<double, 3>& p) {
    auto [it, inserted] = ids_.try_emplace(coordinate_key(p), static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }
 private:
  RawMesh& mesh_;
  std::unordered_map<std::array<double, 3>, std::uint32_t, CoordinateHash> ids_;
};

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

std::uint32_t le_u32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

RawMesh read_binary(const std::string& bytes, std::uint32_t n) {
  RawMesh mesh;
  CornerMerger corners(mesh);
  mesh.faces.reserve(n);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::uint32_t t = 0; t < n; ++t) {
    const unsigned char* rec = data + 84 + std::size_t(50) * t + 12;  // past the normal
    std::vector<std::uint32_t> f(3);
    for (int c = 0; c < 3; ++c) {
      std::array<double, 3> p;
      for (int a = 0; a < 3; ++a) {
        float x = std::bit_cast<float>(le_u32(rec + 12 * c + 4 * a));
        p[a] = x;
        check_coordinate(p[a], a, "", [&] { return "triangle " + std::to_string(t); });
      }
      f[c] = corners.index(p);
    }
    mesh.faces.push_back(std::move(f));
  }
  return mesh;
}

RawMesh read_ascii(const std::string& bytes) {
  RawMesh mesh;
  CornerMerger corners(mesh);
  TokenReader in(bytes);
  std::string_view t;
  auto at = [&] { return "line " + std::to_string(in.line_number()) + ": "; };
  auto is = [&](std::string_view word) { return equals_ignoring_case(t, word); };
  std::size_t facet = 0;
  auto need = [&](std::string_view word) {
    if (!in.next(t)) fail("truncated: the file ends inside facet " + std::to_string(facet));
    if (!is(word)) fail(at() + "expected '" + std::string(word) + "', found " + quoted(t));
  };

  in.next(t);  // "solid", checked by the caller
  in.skip_line();
  for (;;) {
    if (!in.next(t)) fail("truncated: the file ends before 'endsolid'");
    if (is("endsolid")) {
      in.skip_line();
      if (!in.next(t)) break;
      if (!is("solid")) fail(at() + "expected 'solid' after 'endsolid', found " + quoted(t));
      in.skip_line();
      continue;
    }
    if (!is("facet")) fail(at() + "expected 'facet' or 'endsolid', found " + quoted(t));
    if (!in.next(t)) fail("truncated: the file ends inside facet " + std::to_string(facet));
    if (is("normal")) {
      for (int i = 0; i < 3; ++i)
        if (!in.next(t)) fail("truncated: the file ends inside facet " + std::to_string(facet));
      need("outer");
    } else if (!is("outer")) {
      fail(at() + "expected 'normal' or 'outer', found " + quoted(t));
    }
    need("loop");
    std::vector<std::uint32_t> f;
    for (;;) {
      if (!in.next(t)) fail("truncated: the file ends inside facet " + std::to_string(facet));
      if (is("endloop")) break;
      if (!is("vertex")) fail(at() + "expected 'vertex' or 'endloop', found " + quoted(t));
      std::array<double, 3> p;
      for (int a = 0; a < 3; ++a) {
        if (!in.next(t)) fail("truncated: the file ends inside facet " + std::to_string(facet));
        if (!parse_double(t, p[a])) fail(at() + "facet " + std::to_string(facet) + ": expected a number, found " + quoted(t));
        check_coordinate(p[a], a, t, [&] { return at() + "facet " + std::to_string(facet); });
      }
      f.push_back(corners.index(p));
    }
    need("endfacet");
    mesh.faces.push_back(std::move(f));
    ++facet;
  }
  return mesh;
}

}  // namespace

RawMesh read_stl(const std::string& bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
  bool ascii = bytes.size() - i >= 5 && equals_ignoring_case(std::string_view(bytes).substr(i, 5), "solid") &&
               std::memchr(bytes.data(), '\0', std::min<std::size_t>(bytes.size(), 512)) == nullptr;
  if (bytes.size() < 84) {
    if (ascii) return read_ascii(bytes);
    fail("not an STL file: no 'solid' at the start, and shorter (" + std::to_string(bytes.size()) +
         " bytes) than a binary STL's 84-byte header");
  }
  const std::uint32_t n = le_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  const std::uint64_t expected = 84 + std::uint64_t(50) * n;
  if (bytes.size() == expected) return read_binary(bytes, n);
  if (ascii) return read_ascii(bytes);
  if (bytes.size() < expected)
    fail("truncated binary STL: the header promises " + std::to_string(n) + " triangles (" +
         std::to_string(expected) + " bytes), the file has " + std::to_string(bytes.size()) + " bytes");
  RawMesh mesh = read_binary(bytes, n);
  std::size_t extra = bytes.size() - expected;
  mesh.warnings.push_back(std::to_string(extra) + (extra == 1 ? " byte" : " bytes") +
                          " after the last triangle ignored");
  return mesh;
}

}  // namespace hlr::scene_detail
