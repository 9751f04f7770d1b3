// The raster shadow map (raster_shadows.hpp). Plain double and float on purpose; nothing here is
// exact, and nothing of the exact path is used but the choice of the light's view.
#include <hlr/hidden_line/raster_shadows.hpp>

#include "depth_buffer.hpp"

#include <hlr/kernel/mesh_edges.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hlr::hidden_line {
namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 unit(const Vec3& a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

// At most this many samples per face and map pixel squared: a face far larger than the map's
// picture of the scene (a scene seen nearly edge-on from the light) gets a coarser grid.
constexpr double kMaxSamplesPerPixelSquared = 4;

struct FaceSamples {
  double fraction = 0;
  std::uint32_t samples = 0;
};

class ShadowSampler {
 public:
  ShadowSampler(const std::vector<Mesh>& meshes, const Light& light, const detail::DepthBuffer& map, int resolution)
      : meshes_(meshes), light_(light), map_(map), resolution_(resolution) {
    for (const Mesh& mesh : meshes) sides_.push_back(component_sides(mesh, edge_uses(mesh)));
  }

  FaceSamples face(std::uint32_t m, std::uint32_t f) const {
    const Mesh& mesh = meshes_[m];
    const auto& corners = mesh.faces[f];
    Vec3 n{0, 0, 0}, mean{0, 0, 0};
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const Vec3& p = mesh.vertices[corners[k]];
      const Vec3& q = mesh.vertices[corners[(k + 1) % corners.size()]];
      n[0] += (p[1] - q[1]) * (p[2] + q[2]);
      n[1] += (p[2] - q[2]) * (p[0] + q[0]);
      n[2] += (p[0] - q[0]) * (p[1] + q[1]);
      for (int i = 0; i < 3; ++i) mean[i] += p[i] / double(corners.size());
    }
    if (!(dot(n, n) > 0)) return {};  // degenerate: no area to light
    if (sides_[m].outward[f] < 0) n = {-n[0], -n[1], -n[2]};  // a closed component wound inward
    const Vec3& lv = light_.vector;
    const double facing = light_.kind == Light::directional
                              ? -dot(n, lv)
                              : dot(n, Vec3{lv[0] - mean[0], lv[1] - mean[1], lv[2] - mean[2]});
    if (!(facing > 0)) return {};  // attached shadow: facing away or edge-on

    // The spacing: one map pixel, at the face's nearest distance from a point light.
    double spacing = map_.grid.pixel;
    if (light_.kind == Light::point) {
      double z_max = 0;  // the orthonormal perspective frame's z is 1 / distance along its axis
      for (std::uint32_t v : corners) z_max = std::max(z_max, map_.points[m][v][2]);
      if (z_max > 0) spacing /= z_max;
    }
    // The face's own orthonormal frame (u, v, normal).
    const Vec3 normal = unit(n);
    int least = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(normal[k]) < std::abs(normal[least])) least = k;
    Vec3 axis{0, 0, 0};
    axis[least] = 1;
    const Vec3 u = unit(cross(normal, axis)), v = cross(normal, u);
    const double offset = dot(normal, mesh.vertices[corners[0]]);
    std::vector<std::array<double, 2>> ring;
    double u0 = HUGE_VAL, u1 = -HUGE_VAL, v0 = HUGE_VAL, v1 = -HUGE_VAL;
    for (std::uint32_t c : corners) {
      const Vec3& p = mesh.vertices[c];
      ring.push_back({dot(u, p), dot(v, p)});
      u0 = std::min(u0, ring.back()[0]), u1 = std::max(u1, ring.back()[0]);
      v0 = std::min(v0, ring.back()[1]), v1 = std::max(v1, ring.back()[1]);
    }
    const double box = (u1 - u0) * (v1 - v0);
    const double cap = kMaxSamplesPerPixelSquared * double(resolution_) * double(resolution_);
    if (box / (spacing * spacing) > cap) spacing = std::sqrt(box / cap);
    // A grid centred on the face's box.
    const long columns = std::max(1L, static_cast<long>(std::ceil((u1 - u0) / spacing)));
    const long rows = std::max(1L, static_cast<long>(std::ceil((v1 - v0) / spacing)));
    const double left = (u0 + u1) / 2 - double(columns) * spacing / 2;
    const double bottom = (v0 + v1) / 2 - double(rows) * spacing / 2;

    // The receiver's own slope-scaled bias, as the map's faces have theirs (the map's offset of
    // this face): a sample by an edge falls in a pixel whose centre lies on the neighbouring face,
    // whose offset is for its own slope, not this one's.
    const detail::RasterFace& own = map_.faces[map_.first_face[m] + f];
    const double receiver_bias = own.fills ? own.offset : 0;
    std::uint32_t samples = 0, lit = 0;
    auto sample = [&](double su, double sv) {
      const Vec3 p{su * u[0] + sv * v[0] + offset * normal[0], su * u[1] + sv * v[1] + offset * normal[1],
                   su * u[2] + sv * v[2] + offset * normal[2]};
      ++samples;
      if (sees_light(p, receiver_bias)) ++lit;
    };
    std::vector<double> crossings;
    for (long row = 0; row < rows; ++row) {
      const double y = bottom + (double(row) + 0.5) * spacing;
      crossings.clear();
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const auto& p = ring[k];
        const auto& q = ring[(k + 1) % ring.size()];
        if ((p[1] <= y) == (q[1] <= y)) continue;
        crossings.push_back(p[0] + (y - p[1]) / (q[1] - p[1]) * (q[0] - p[0]));
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const long c0 = std::max(0L, static_cast<long>(std::ceil((crossings[k] - left) / spacing - 0.5)));
        const long c1 = std::min(columns, static_cast<long>(std::ceil((crossings[k + 1] - left) / spacing - 0.5)));
        for (long column = c0; column < c1; ++column) sample(left + (double(column) + 0.5) * spacing, y);
      }
    }
    if (samples == 0) sample(dot(u, mean), dot(v, mean));  // smaller than the grid: one sample
    return {double(lit) / double(samples), samples};
  }

 private:
  // Whether nothing in the map lies nearer to the light than p (with the map's depth bias).
  bool sees_light(const Vec3& p, double receiver_bias) const {
    const Vec3 q = map_.orthonormal(map_.frame.to_view(p));
    const double column = map_.grid.column(q[0]), row = map_.grid.row(q[1]);
    if (!(column >= 0 && row >= 0 && column < map_.grid.width && row < map_.grid.height)) return true;
    const std::size_t pixel = std::size_t(row) * map_.grid.width + std::size_t(column);
    return map_.normalized(q[2]) + receiver_bias >= map_.depth[pixel];
  }

  const std::vector<Mesh>& meshes_;
  const Light& light_;
  const detail::DepthBuffer& map_;
  int resolution_;
  // The front side as the exact path takes it (shadows.hpp): a closed component wound inward
  // faces outward.
  std::vector<ComponentSides> sides_;
};

}  // namespace

RasterShadows raster_shadows(const std::vector<Mesh>& meshes, const Light& light, int resolution) {
  if (auto defect = light_defect(light)) throw std::invalid_argument(*defect);
  const std::optional<View> view = light_view(meshes, light);
  if (!view)
    throw std::invalid_argument(point_light_defect(meshes, light).value_or(
        "the raster shadow map takes a point light with the scene on one side of a plane through it (one "
        "perspective view); a light among the geometry is solved exactly in a cube of views, the map has none"));
  const detail::DepthBuffer map(meshes, *view, resolution);
  const ShadowSampler sampler(meshes, light, map, resolution);
  RasterShadows out;
  out.grid = map.grid;
  for (std::uint32_t m = 0; m < meshes.size(); ++m) {
    const std::size_t nf = meshes[m].faces.size();
    auto& fraction = out.sunlit_fraction.emplace_back(nf, 0.0);
    auto& samples = out.samples.emplace_back(nf, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nf, 64), [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t f = range.begin(); f != range.end(); ++f) {
        const FaceSamples s = sampler.face(m, static_cast<std::uint32_t>(f));
        fraction[f] = s.fraction;
        samples[f] = s.samples;
      }
    });
    for (std::uint32_t s : samples) out.total_samples += s;
  }
  return out;
}

}  // namespace hlr::hidden_line
