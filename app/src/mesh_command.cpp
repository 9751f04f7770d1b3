// `hlr mesh MODEL... -o OUT.off|OUT.obj|OUT.stl|OUT.ply [--deflection D] [--angular-deflection DEG]`
//
// Writes the triangles hlr solves: a CAD model's tessellation (hlr/cad/cad.hpp) or a mesh as
// imported, so that other tools and checks run on the same faces. Every coordinate is written as
// the shortest text that reads back as the same double, so that hlr reads back the same mesh.
// Face groups (a CAD model's B-rep faces, a mesh file's groups) are kept where the format has
// them: OFF and PLY face colours (the group's number, as red/green/blue bytes), OBJ `g`. STL is
// ASCII (binary STL would round to float32). Several parts go into one file, one after the other.
#include "atomic_file.hpp"
#include "errors.hpp"
#include "run_scope.hpp"
#include "scene_options.hpp"
#include "subcommand.hpp"

#include <charconv>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hlr::app {
namespace {

struct MeshOptions {
  std::vector<std::string> inputs;
  std::string output;
  cad::CadOptions cad;
  RunLimits limits;
  int threads = 0;  // BRepMesh meshes faces in parallel
};

enum class Format { off, obj, stl, ply };

Format format_of(const std::string& path) {
  if (has_extension(path, ".off")) return Format::off;
  if (has_extension(path, ".obj")) return Format::obj;
  if (has_extension(path, ".stl")) return Format::stl;
  if (has_extension(path, ".ply")) return Format::ply;
  throw UserError(path, "unknown output format (the name must end in .off, .obj, .stl or .ply)");
}

void put(std::string& out, double v) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, v == 0 ? 0.0 : v).ptr);
}

void put_point(std::string& out, const std::array<double, 3>& p) {
  put(out, p[0]);
  out += ' ';
  put(out, p[1]);
  out += ' ';
  put(out, p[2]);
}

// The scene's faces in one numbering: part offsets, and a group number over all parts (-1: none).
struct Flat {
  std::vector<std::uint32_t> offset;  // per mesh: its first vertex
  std::vector<std::vector<std::int64_t>> group;  // per mesh, per face
  std::vector<std::string> group_name;
  std::size_t faces = 0, vertices = 0;
  bool grouped = false;
};

Flat flatten(const Scene& scene, const std::vector<std::string>& parts) {
  Flat flat;
  std::map<std::pair<std::size_t, std::int32_t>, std::int64_t> ids;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    flat.offset.push_back(static_cast<std::uint32_t>(flat.vertices));
    flat.vertices += mesh.vertices.size();
    flat.faces += mesh.faces.size();
    auto& group = flat.group.emplace_back(mesh.faces.size(), -1);
    if (mesh.face_group.empty()) continue;
    flat.grouped = true;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const std::int32_t g = mesh.face_group[f];
      auto [it, fresh] = ids.try_emplace({m, g}, std::int64_t(ids.size()));
      if (fresh) {
        std::string name = parts[m] + "_" + (std::size_t(g) < mesh.group_names.size() ? mesh.group_names[g] : std::to_string(g));
        for (char& c : name)
          if (c == ' ') c = '_';
        flat.group_name.push_back(name);
      }
      group[f] = it->second;
    }
  }
  return flat;
}

void put_color(std::string& out, std::int64_t id) {
  const std::int64_t c = id < 0 ? 0 : id;
  out += ' ' + std::to_string(c >> 16 & 255) + ' ' + std::to_string(c >> 8 & 255) + ' ' + std::to_string(c & 255);
}

std::string document(const Scene& scene, Format format, const std::vector<std::string>& parts) {
  const Flat flat = flatten(scene, parts);
  std::string out;
  // OFF and ASCII PLY share the body: one point per line, then "n v0 ... [r g b]" per face.
  auto points_and_counted_faces = [&] {
    for (const Mesh& mesh : scene.meshes)
      for (const auto& p : mesh.vertices) {
        put_point(out, p);
        out += '\n';
      }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
      for (std::size_t f = 0; f < scene.meshes[m].faces.size(); ++f) {
        const auto& face = scene.meshes[m].faces[f];
        out += std::to_string(face.size());
        for (std::uint32_t v : face) out += ' ' + std::to_string(flat.offset[m] + v);
        if (flat.grouped) put_color(out, flat.group[m][f]);
        out += '\n';
      }
  };
  switch (format) {
    case Format::off: {
      out += "OFF\n" + std::to_string(flat.vertices) + ' ' + std::to_string(flat.faces) + " 0\n";
      points_and_counted_faces();
      break;
    }
    case Format::obj: {
      out += "# hlr mesh\n";
      for (const Mesh& mesh : scene.meshes)
        for (const auto& p : mesh.vertices) {
          out += "v ";
          put_point(out, p);
          out += '\n';
        }
      for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        out += "o " + parts[m] + '\n';
        std::int64_t current = -2;
        for (std::size_t f = 0; f < scene.meshes[m].faces.size(); ++f) {
          const std::int64_t g = flat.group[m][f];
          if (g != current) out += "g " + (g < 0 ? parts[m] : flat.group_name[g]) + '\n';
          current = g;
          out += 'f';
          for (std::uint32_t v : scene.meshes[m].faces[f]) out += ' ' + std::to_string(flat.offset[m] + v + 1);
          out += '\n';
        }
      }
      break;
    }
    case Format::stl: {
      out += "solid hlr\n";
      for (const Mesh& mesh : scene.meshes)
        for (const auto& face : mesh.faces)
          for (std::size_t k = 2; k < face.size(); ++k) {  // a polygon as its fan
            const auto &a = mesh.vertices[face[0]], &b = mesh.vertices[face[k - 1]], &c = mesh.vertices[face[k]];
            // The normal is informative only (readers, hlr's among them, take the corners' order).
            const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
            const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (double& x : n) x = len > 0 ? x / len : 0;
            out += "  facet normal ";
            put_point(out, n);
            out += "\n    outer loop\n";
            for (const auto* p : {&a, &b, &c}) {
              out += "      vertex ";
              put_point(out, *p);
              out += '\n';
            }
            out += "    endloop\n  endfacet\n";
          }
      out += "endsolid hlr\n";
      break;
    }
    case Format::ply: {
      out += "ply\nformat ascii 1.0\ncomment hlr mesh\nelement vertex " + std::to_string(flat.vertices) +
             "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(flat.faces) +
             "\nproperty list uchar int vertex_indices\n";
      if (flat.grouped) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
      out += "end_header\n";
      points_and_counted_faces();
      break;
    }
  }
  return out;
}

int run(const MeshOptions& options) {
  const Format format = format_of(options.output);
  AtomicFile file(options.output);
  RunScope run(options.limits, options.threads);
  const Scene scene = run.read(options.inputs, options.cad, "model", "models");
  run.stage("writing " + options.output);
  // Part names as the drawings name them: the source's, else the file's stem.
  std::vector<std::string> parts;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    std::string name = scene.input.parts[m];
    if (name.empty()) {
      name = scene.input.files[m].substr(scene.input.files[m].find_last_of('/') + 1);
      if (const auto dot = name.find_last_of('.'); dot != std::string::npos && dot > 0) name.resize(dot);
    }
    for (char& c : name)
      if (c == ' ' || c == '\t') c = '_';
    parts.push_back(name.empty() ? "part" : name);
  }
  const Flat flat = flatten(scene, parts);
  // Colours are three bytes: more groups than that could not be told apart.
  if (flat.group_name.size() > (std::size_t(1) << 24) && format != Format::obj && format != Format::stl)
    throw UserError(options.output, "more than 2^24 face groups: OFF and PLY colours cannot tell them apart");
  file.write(document(scene, format, parts));
  file.commit();
  run.finish(scene);
  std::cout << "hlr mesh: " << scene.meshes.size() << (scene.meshes.size() == 1 ? " part, " : " parts, ") << flat.faces
            << " faces, " << flat.vertices << " vertices\n"
            << "wrote " << options.output << '\n';
  return kExitOk;
}

}  // namespace

Subcommand add_mesh_command(CLI::App& parent) {
  auto options = std::make_shared<MeshOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "mesh", "Write the triangles hlr solves: a CAD model's tessellation, or meshes as imported.");
  cmd->add_option("inputs", options->inputs, std::string(kInputKinds) + ", written together into one file")
      ->required()
      ->type_name("MODEL...");
  cmd->add_option("-o,--output", options->output,
                  "file to write, by extension: .off, .obj, .stl (ASCII) or .ply (ASCII); face groups (a CAD "
                  "model's B-rep faces) as OFF/PLY colours and OBJ groups")
      ->required()
      ->type_name("OUT");
  add_cad_options(*cmd, options->cad);
  add_limit_options(*cmd, options->limits);
  add_threads_option(*cmd, options->threads);
  cmd->footer(
      "Example:\n"
      "  hlr mesh part.step -o out/part.off\n"
      "\n"
      "Coordinates are written exactly (the shortest text of each double): hlr reads the same mesh back.");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
