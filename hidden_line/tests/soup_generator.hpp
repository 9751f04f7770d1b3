// Random triangle soups for the property tests (hidden_line_property_test.cpp,
// lines_property_test.cpp): 3 to 12 triangles on a small integer grid ([0, 4]^3, so that shared
// vertices, vertices on edges, coplanar and coincident triangles, penetrations and cyclic overlaps
// are common), some flattened onto z = 0 or 2, up to 2 repeated (as given or reversed), vertices
// shared or not, seen in a random named view or along a random small-integer direction.
//
// random_soup() draws with `*gen`, so it must be called inside a RapidCheck property.
#pragma once

#include "surface_runs.hpp"

#include <rapidcheck.h>

#include <array>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hlr::hltest {

using Corner = std::array<int, 3>;
using Triangle = std::array<Corner, 3>;

inline bool degenerate(const Triangle& t) {
  const long ux = t[1][0] - t[0][0], uy = t[1][1] - t[0][1], uz = t[1][2] - t[0][2];
  const long wx = t[2][0] - t[0][0], wy = t[2][1] - t[0][1], wz = t[2][2] - t[0][2];
  return uy * wz - uz * wy == 0 && uz * wx - ux * wz == 0 && ux * wy - uy * wx == 0;
}

struct Soup {
  std::vector<Triangle> triangles;
  bool share_vertices = false;  // identical corners become one vertex (edges shared, coplanar merges)
  View view;
};

inline Mesh to_mesh(const Soup& soup) {
  Mesh mesh;
  mesh.file = "soup";
  std::map<Corner, std::uint32_t> index;
  for (const auto& t : soup.triangles) {
    std::vector<std::uint32_t> face;
    for (const auto& c : t) {
      auto it = soup.share_vertices ? index.find(c) : index.end();
      if (it == index.end()) {
        mesh.vertices.push_back({double(c[0]), double(c[1]), double(c[2])});
        const auto v = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
        if (soup.share_vertices) index[c] = v;
        face.push_back(v);
      } else {
        face.push_back(it->second);
      }
    }
    mesh.face_index.push_back(static_cast<std::uint32_t>(mesh.faces.size()));
    mesh.faces.push_back(face);
  }
  return mesh;
}

// The mesh as an OFF file (with face colours when it has face groups: one grey level per group).
inline std::string off_text(const Mesh& mesh) {
  std::ostringstream out;
  out << "OFF\n" << mesh.vertices.size() << " " << mesh.faces.size() << " 0\n";
  for (const auto& v : mesh.vertices) out << v[0] << " " << v[1] << " " << v[2] << "\n";
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    out << mesh.faces[f].size();
    for (std::uint32_t v : mesh.faces[f]) out << " " << v;
    if (!mesh.face_group.empty()) out << " " << mesh.face_group[f] << " " << mesh.face_group[f] << " " << mesh.face_group[f];
    out << "\n";
  }
  return out.str();
}

inline std::string view_text(const View& v) {
  std::ostringstream out;
  out << v.name << " direction (" << v.direction[0] << ", " << v.direction[1] << ", " << v.direction[2] << ") up ("
      << v.up[0] << ", " << v.up[1] << ", " << v.up[2] << ")";
  if (v.eye) out << " eye (" << (*v.eye)[0] << ", " << (*v.eye)[1] << ", " << (*v.eye)[2] << ")";
  return out.str();
}

inline rc::Gen<Triangle> gen_triangle() {
  auto coordinate = rc::gen::inRange(0, 5);
  auto corner = rc::gen::map(rc::gen::tuple(coordinate, coordinate, coordinate), [](const auto& t) {
    return Corner{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
  });
  return rc::gen::suchThat(rc::gen::map(rc::gen::tuple(corner, corner, corner),
                                        [](const auto& t) {
                                          return Triangle{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
                                        }),
                           [](const Triangle& t) { return !degenerate(t); });
}

inline rc::Gen<View> gen_view() {
  auto named = rc::gen::map(rc::gen::inRange(0, 7), [](int i) { return named_views()[static_cast<std::size_t>(i)]; });
  auto d = rc::gen::inRange(-3, 4);
  auto direction = rc::gen::map(
      rc::gen::suchThat(rc::gen::tuple(d, d, d),
                        [](const auto& t) { return std::get<0>(t) != 0 || std::get<1>(t) != 0 || std::get<2>(t) != 0; }),
      [](const auto& t) {
        View v = direction_view({double(std::get<0>(t)), double(std::get<1>(t)), double(std::get<2>(t))});
        if (view_defect(v)) v.up = {0, 1, 0};  // direction along z
        return v;
      });
  return rc::gen::oneOf(named, direction);
}

// A perspective view: an eye on a grid of eighths around and inside the soups' box [0, 4]^3 (so
// that faces are seen edge-on, from close by, and cut by the near plane), looking at a point
// inside it. The eye may lie on a face: check perspective_defect.
inline rc::Gen<View> gen_perspective_view() {
  auto e = rc::gen::inRange(-3, 8);
  auto t = rc::gen::inRange(0, 4);
  return rc::gen::map(rc::gen::tuple(e, e, e, t, t, t), [](const auto& g) {
    const Vec3 eye{std::get<0>(g) + 0.375, std::get<1>(g) + 0.625, std::get<2>(g) + 0.125};
    const Vec3 target{std::get<3>(g) + 0.5, std::get<4>(g) + 0.25, std::get<5>(g) + 0.75};
    View v = direction_view({target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]});
    if (view_defect(v)) v.up = {0, 1, 0};  // direction along z
    v.name = "perspective";
    v.eye = eye;
    return v;
  });
}

// A random soup and view (see the top of this file). Only inside a RapidCheck property.
inline Soup random_soup() {
  Soup soup;
  const int n = *rc::gen::inRange(3, 13);
  soup.triangles = *rc::gen::container<std::vector<Triangle>>(static_cast<std::size_t>(n), gen_triangle());
  // Make coplanar and coincident triangles common: flatten some onto z = 0 or z = 2, and repeat
  // some (as given, or reversed).
  if (*rc::gen::inRange(0, 3) == 0) {
    for (auto& t : soup.triangles) {
      if (*rc::gen::arbitrary<bool>()) {
        const int z = *rc::gen::element(0, 2);
        Triangle flat = t;
        for (auto& c : flat) c[2] = z;
        if (!degenerate(flat)) t = flat;
      }
    }
  }
  const int copies = *rc::gen::inRange(0, 3);
  for (int k = 0; k < copies; ++k) {
    Triangle t = soup.triangles[static_cast<std::size_t>(*rc::gen::inRange(0, n))];
    if (*rc::gen::arbitrary<bool>()) std::swap(t[1], t[2]);
    soup.triangles.push_back(t);
  }
  soup.share_vertices = *rc::gen::arbitrary<bool>();
  soup.view = *gen_view();
  return soup;
}

}  // namespace hlr::hltest
