// Why hlr_scene does not read meshes through OpenMesh::IO: these tests pin down what OpenMesh's
// readers (Debian's OpenMesh 9.0) hand to a BaseImporter that records every call, on files that
// hlr reads exactly (scene_test.cpp). If one of them starts failing after an OpenMesh upgrade,
// the reader may have become usable: see kernel/src/scene_readers.hpp.
#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

using namespace OpenMesh;
using namespace OpenMesh::IO;

// Records raw vertices and faces; no half-edge structure, so nothing is refused for topology.
struct RecordingImporter : BaseImporter {
  std::vector<Vec3d> points;
  std::vector<std::vector<int>> faces;

  VertexHandle add_vertex(const Vec3f& p) override { return add_vertex(Vec3d(p)); }
  VertexHandle add_vertex(const Vec3d& p) override {
    points.push_back(p);
    return VertexHandle(static_cast<int>(points.size()) - 1);
  }
  VertexHandle add_vertex() override { return add_vertex(Vec3d(0, 0, 0)); }
  void set_point(VertexHandle v, const Vec3f& p) override { points.at(v.idx()) = Vec3d(p); }
  FaceHandle add_face(const VHandles& vs) override {
    std::vector<int> f;
    for (auto v : vs) f.push_back(v.idx());
    faces.push_back(f);
    return FaceHandle(static_cast<int>(faces.size()) - 1);
  }

  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const Vec3f&) override {}
  void set_normal(VertexHandle, const Vec3d&) override {}
  void set_color(VertexHandle, const Vec3uc&) override {}
  void set_color(VertexHandle, const Vec4uc&) override {}
  void set_color(VertexHandle, const Vec3f&) override {}
  void set_color(VertexHandle, const Vec4f&) override {}
  void set_texcoord(VertexHandle, const Vec2f&) override {}
  void set_status(VertexHandle, const Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
  void set_texcoord(VertexHandle, const Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
  void set_status(HalfedgeHandle, const Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const Vec3uc&) override {}
  void set_color(EdgeHandle, const Vec4uc&) override {}
  void set_color(EdgeHandle, const Vec3f&) override {}
  void set_color(EdgeHandle, const Vec4f&) override {}
  void set_status(EdgeHandle, const Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const Vec3f&) override {}
  void set_normal(FaceHandle, const Vec3d&) override {}
  void set_color(FaceHandle, const Vec3uc&) override {}
  void set_color(FaceHandle, const Vec4uc&) override {}
  void set_color(FaceHandle, const Vec3f&) override {}
  void set_color(FaceHandle, const Vec4f&) override {}
  void set_status(FaceHandle, const Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
  size_t n_vertices() const override { return points.size(); }
  size_t n_faces() const override { return faces.size(); }
  size_t n_edges() const override { return 0; }
};

std::string write(const std::string& name, const std::string& text) {
  auto p = std::filesystem::temp_directory_path() / ("hlr_openmesh_probe_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

bool read(const std::string& path, RecordingImporter& imp) {
  omerr().disable();  // OpenMesh's own diagnostics
  omlog().disable();
  omout().disable();
  Options opt;
  bool ok = IOManager().read(path, imp, opt);
  std::filesystem::remove(path);
  return ok;
}

const double kFloat01 = static_cast<double>(0.1f);

TEST(OpenMeshReaders, RoundTextCoordinatesToFloat) {
  const std::string tetra_off = "OFF\n4 4 0\n0.1 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string tetra_obj = "v 0.1 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string tetra_ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                "property double z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                "end_header\n0.1 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  for (auto [name, text] : {std::pair{"t.off", tetra_off}, std::pair{"t.obj", tetra_obj}, std::pair{"t.ply", tetra_ply}}) {
    RecordingImporter imp;
    ASSERT_TRUE(read(write(name, text), imp)) << name;
    ASSERT_EQ(imp.points.size(), 4u) << name;
    EXPECT_EQ(imp.points[0][0], kFloat01) << name << ": 0.1 arrives as a float (even PLY 'property double')";
    EXPECT_EQ(imp.faces.size(), 4u) << name;
  }
}

TEST(OpenMeshReaders, AcceptTruncatedOff) {
  RecordingImporter imp;
  // Promises 4 faces, has 2: OpenMesh reports success.
  EXPECT_TRUE(read(write("cut.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"), imp));
}

TEST(OpenMeshReaders, StlDropsDegenerateTrianglesSilently) {
  RecordingImporter imp;
  const std::string stl =
      "solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n"
      "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n";
  ASSERT_TRUE(read(write("d.stl", stl), imp));
  EXPECT_EQ(imp.faces.size(), 1u) << "the first triangle is dropped, and the second becomes face 0";
}

}  // namespace
