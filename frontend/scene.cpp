#include "frontend/scene.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "model/json_lines.h"
#include "frontend/obj_loader.h"
#include "frontend/surfaces.h"
#include "frontend/transform.h"
#include "model/input_error.h"
#include "model/text_file.h"

namespace rastersim::frontend {

Sphere scene_bounds(const Scene& scene) {
  std::vector<Vec3> points;
  for (const SceneObject& o : scene.objects)
    for (const Vec3& p : o.mesh.positions) points.push_back(transform_point(o.model, p));
  return bounding_sphere(points);
}

std::vector<ScreenTriangle> render_scene(const Scene& scene, const Camera& camera, const Profile& profile,
                                         RenderTrace* trace) {
  const Mat4 view_projection = camera.projection() * camera.view();
  const Vec3 view_direction = normalize(camera.target - camera.eye);
  const Clipper clipper(profile);
  const bool inverse_w = profile.depth_buffer == DepthBuffer::InverseW;
  if (inverse_w && camera.ortho)
    throw InputError("depth_buffer inverse_w needs a perspective camera: with an orthographic one every w is 1 "
                     "(docs/arithmetic.md section 6)");
  std::vector<ScreenTriangle> out;
  std::vector<CornerSources>* corners = trace ? &trace->corners : nullptr;
  for (size_t index = 0; index < scene.objects.size(); ++index) {
    const SceneObject& object = scene.objects[index];
    const Mesh& mesh = object.mesh;
    const Mat4 normals_to_world = normal_matrix(object.model);
    const bool mirrored = linear_determinant(object.model) < 0;
    const Material& material = object.material;
    auto to_eye = [&](const Vec3& world) { return camera.ortho ? -view_direction : normalize(camera.eye - world); };

    std::vector<Vec3> world(mesh.positions.size());
    std::vector<Vec4> clip(mesh.positions.size());
    std::vector<Vec3> color(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      world[v] = transform_point(object.model, mesh.positions[v]);
      clip[v] = view_projection * Vec4{world[v].x, world[v].y, world[v].z, 1.0};
      if (material.shading != SurfaceShading::Faceted) {
        const Vec3 normal = normalize(transform_direction(normals_to_world, mesh.normals[v]));
        color[v] = shade(material, scene.lighting, normal, to_eye(world[v]));
      }
    }
    for (size_t triangle_index = 0; triangle_index < mesh.triangles.size(); ++triangle_index) {
      const auto& triangle = mesh.triangles[triangle_index];
      const uint32_t corner[3] = {triangle[0], mirrored ? triangle[2] : triangle[1], mirrored ? triangle[1] : triangle[2]};
      ClipVertex vertices[3];
      for (int k = 0; k < 3; ++k) {
        vertices[k] = {clip[corner[k]], color[corner[k]], int64_t(corner[k])};
        if (mesh.textured()) vertices[k].u = mesh.texcoords[corner[k]][0], vertices[k].v = mesh.texcoords[corner[k]][1];
      }
      if (material.shading == SurfaceShading::Faceted) {
        const Vec3& a = world[corner[0]];
        const Vec3& b = world[corner[1]];
        const Vec3& c = world[corner[2]];
        const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
        const Vec3 face = shade(material, scene.lighting, normalize(cross(b - a, c - a)), to_eye(centroid));
        for (ClipVertex& v : vertices) v.color = face;
      }
      const size_t before = out.size();
      clipper.clip(vertices, out, corners);
      if (trace) {
        trace->object.resize(out.size(), int(index));
        trace->triangle.resize(out.size(), triangle_index);
      }
      for (size_t t = before; t < out.size(); ++t) {
        out[t].textured = mesh.textured();
        // The 1/w buffer's depth: near / w, 1 at the near plane (w within [near, far] after clipping,
        // up to rounding).
        if (inverse_w)
          for (ScreenVertex& v : out[t].v) v.z = std::clamp(camera.near / v.w, 0.0, 1.0);
        // Clipping keeps every w within [near, far]; a textured triangle may still span a wider w
        // ratio than the texture divide's bound allows (docs/arithmetic.md section 5).
        if (out[t].textured && profile.texture_unit) {
          const std::string ratio = check_texture_w_ratio(out[t]);
          if (!ratio.empty())
            throw InputError("object " + std::to_string(index + 1) + ", triangle " + std::to_string(triangle_index + 1) +
                             ": textured, and " + ratio + " (w, the eye distance, may vary by at most 16384 "
                             "across a textured triangle: move the near plane out, --near, or split the mesh)");
        }
        const std::string problem = check_screen_triangle(out[t], profile);
        if (!problem.empty()) throw std::logic_error("front end produced an unacceptable triangle: " + problem);
      }
    }
  }
  return out;
}

Scene obj_scene(Mesh mesh) {
  Scene scene;
  SceneObject object;
  object.mesh = std::move(mesh);
  object.material.color = {0.8, 0.8, 0.8};
  scene.objects.push_back(std::move(object));
  return scene;
}

// ---- Scene files ----------------------------------------------------------------------------------

namespace {

using nlohmann::json;

class SceneReader {
 public:
  SceneReader(const std::string& text, const std::string& file, const std::string& base)
      : file_(file), base_(base), lines_(text) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& problem) const {
    throw InputError(file_, lines_.line(pointer), problem);
  }

  // The member names of `object` must be among `allowed`.
  void only_keys(const json& object, const std::string& pointer, const std::vector<std::string>& allowed,
                 const std::string& what) const {
    for (auto it = object.begin(); it != object.end(); ++it)
      if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(JsonLines::child(pointer, it.key()), "unknown key '" + it.key() + "' in " + what + " (known: " + list + ")");
      }
  }

  const json& require_object(const json& v, const std::string& pointer, const std::string& what) const {
    if (!v.is_object()) fail(pointer, what + " must be a JSON object");
    return v;
  }

  double number(const json& v, const std::string& pointer, const std::string& what) const {
    if (!v.is_number()) fail(pointer, what + " must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(pointer, what + " must be a finite number");
    return d;
  }

  Vec3 vec3(const json& v, const std::string& pointer, const std::string& what) const {
    if (!v.is_array() || v.size() != 3) fail(pointer, what + " must be an array of 3 numbers");
    return {number(v[0], JsonLines::child(pointer, 0), what), number(v[1], JsonLines::child(pointer, 1), what),
            number(v[2], JsonLines::child(pointer, 2), what)};
  }

  // [r, g, b] in 0..255, returned as 0..1.
  Vec3 color(const json& v, const std::string& pointer, const std::string& what) const {
    const Vec3 c = vec3(v, pointer, what);
    for (double channel : {c.x, c.y, c.z})
      if (channel < 0 || channel > 255) fail(pointer, what + " channels must be in 0..255");
    return (1.0 / 255.0) * c;
  }

  Scene read(const json& doc) {
    Scene scene;
    require_object(doc, "", "a scene file");
    only_keys(doc, "", {"camera", "ambient", "lights", "objects"}, "the scene");
    if (doc.contains("camera")) read_camera(doc["camera"], "/camera", scene.camera);
    if (doc.contains("ambient")) scene.lighting.ambient = color(doc["ambient"], "/ambient", "ambient");
    if (doc.contains("lights")) {
      const json& lights = doc["lights"];
      if (!lights.is_array()) fail("/lights", "lights must be an array of light objects");
      if (lights.size() > kMaxSceneLights)
        fail("/lights", std::to_string(lights.size()) + " lights; a scene has at most " + std::to_string(kMaxSceneLights) +
                            " (each lights every vertex)");
      scene.lighting.lights.clear();
      for (size_t i = 0; i < lights.size(); ++i) scene.lighting.lights.push_back(read_light(lights[i], JsonLines::child("/lights", i)));
    }
    if (!doc.contains("objects")) fail("", "the scene has no 'objects' array");
    const json& objects = doc["objects"];
    if (!objects.is_array() || objects.empty()) fail("/objects", "objects must be a non-empty array of objects");
    size_t triangles = 0;
    for (size_t i = 0; i < objects.size(); ++i) {
      const std::string pointer = JsonLines::child("/objects", i);
      scene.objects.push_back(read_object(objects[i], pointer));
      // Bounded before the next object is made: 20 spheres of 1024 x 1024 once grew to 3.9 GB.
      triangles += scene.objects.back().mesh.triangles.size();
      if (triangles > kMaxSceneTriangles)
        fail(pointer, "the scene has " + std::to_string(triangles) + " triangles with this object, more than the " +
                          std::to_string(kMaxSceneTriangles) + " a scene may have: lower its surfaces' counts "
                          "(segments, rings, ...) or split the scene");
    }
    return scene;
  }

 private:
  void read_camera(const json& v, const std::string& pointer, CameraSettings& camera) const {
    require_object(v, pointer, "camera");
    only_keys(v, pointer, {"eye", "target", "up", "fov", "near", "far", "ortho"}, "camera");
    auto origin = [&](const char* key) { return Origin{file_, lines_.line(JsonLines::child(pointer, key))}; };
    auto vector_key = [&](const char* key, std::optional<Vec3>& value, Origin& where) {
      if (!v.contains(key)) return;
      value = vec3(v[key], JsonLines::child(pointer, key), std::string("camera ") + key);
      where = origin(key);
    };
    auto number_key = [&](const char* key, std::optional<double>& value, Origin& where) {
      if (!v.contains(key)) return;
      value = number(v[key], JsonLines::child(pointer, key), std::string("camera ") + key);
      where = origin(key);
    };
    vector_key("eye", camera.values.eye, camera.eye);
    vector_key("target", camera.values.target, camera.target);
    vector_key("up", camera.values.up, camera.up);
    number_key("fov", camera.values.fov, camera.fov);
    number_key("near", camera.values.near, camera.near);
    number_key("far", camera.values.far, camera.far);
    if (v.contains("ortho")) {
      if (!v["ortho"].is_boolean()) fail(JsonLines::child(pointer, "ortho"), "camera ortho must be true or false");
      camera.values.ortho = v["ortho"].get<bool>();
    }
  }

  DirectionalLight read_light(const json& v, const std::string& pointer) const {
    require_object(v, pointer, "a light");
    only_keys(v, pointer, {"direction", "color"}, "a light");
    if (!v.contains("direction")) fail(pointer, "a light needs a 'direction' (the way its light travels)");
    DirectionalLight light;
    light.direction = vec3(v["direction"], pointer + "/direction", "light direction");
    if (!(length(light.direction) > 0)) fail(pointer + "/direction", "light direction must not be the zero vector");
    if (v.contains("color")) light.color = color(v["color"], pointer + "/color", "light color");
    return light;
  }

  SceneObject read_object(const json& v, const std::string& pointer) const {
    require_object(v, pointer, "an object");
    only_keys(v, pointer,
              {"mesh", "surface", "params", "translate", "rotate", "scale", "color", "specular", "shininess", "shading"},
              "an object");
    SceneObject object;
    if (v.contains("mesh") == v.contains("surface")) fail(pointer, "an object needs exactly one of 'mesh' and 'surface'");
    if (v.contains("mesh")) {
      const std::string key = pointer + "/mesh";
      if (!v["mesh"].is_string()) fail(key, "mesh must be a file name (a string)");
      // A NUL (\u0000) would end the name where the file system reads it: another file would load.
      if (v["mesh"].get<std::string>().find('\0') != std::string::npos)
        fail(key, "mesh file name '" + v["mesh"].get<std::string>() + "' holds a NUL character");
      const std::filesystem::path relative = v["mesh"].get<std::string>();
      const std::filesystem::path path = relative.is_absolute() ? relative : std::filesystem::path(base_) / relative;
      std::error_code ec;
      if (!std::filesystem::exists(path, ec)) fail(key, "mesh file '" + path.string() + "' not found");
      if (!std::filesystem::is_regular_file(path, ec))
        fail(key, "mesh file '" + path.string() + "' is not a regular file (a folder or a device)");
      if (v.contains("params")) fail(pointer + "/params", "params belong to a 'surface', not to a mesh");
      try {
        object.mesh = load_obj_mesh(path.string());
      } catch (const InputError& e) {  // the mesh's own file and line first, then where it was named
        throw InputError(std::string(e.what()) + " (the mesh of " + file_ + ":" + std::to_string(lines_.line(key)) + ")");
      }
    } else {
      object.mesh = read_surface(v, pointer);
    }
    Vec3 translate{}, rotate{}, scale{1, 1, 1};
    if (v.contains("translate")) translate = vec3(v["translate"], pointer + "/translate", "translate");
    if (v.contains("rotate")) rotate = vec3(v["rotate"], pointer + "/rotate", "rotate (degrees about x, y, z)");
    if (v.contains("scale")) {
      const std::string key = pointer + "/scale";
      if (v["scale"].is_number()) {
        const double s = number(v["scale"], key, "scale");
        scale = {s, s, s};
      } else {
        scale = vec3(v["scale"], key, "scale (a number or 3 numbers)");
      }
      if (scale.x == 0 || scale.y == 0 || scale.z == 0) fail(key, "scale must not be zero");
    }
    object.model = model_matrix(translate, rotate, scale);
    Material& m = object.material;
    if (v.contains("color")) m.color = color(v["color"], pointer + "/color", "color");
    if (v.contains("specular")) m.specular = color(v["specular"], pointer + "/specular", "specular");
    if (v.contains("shininess")) {
      m.shininess = number(v["shininess"], pointer + "/shininess", "shininess");
      if (m.shininess < 1 || m.shininess > 10000) fail(pointer + "/shininess", "shininess must be in 1..10000");
    }
    if (v.contains("shading")) {
      const json& s = v["shading"];
      const std::string name = s.is_string() ? s.get<std::string>() : "";
      if (name == "smooth") m.shading = SurfaceShading::Smooth;
      else if (name == "faceted") m.shading = SurfaceShading::Faceted;
      else if (name == "unlit") m.shading = SurfaceShading::Unlit;
      else fail(pointer + "/shading", "shading must be \"smooth\", \"faceted\" or \"unlit\"");
    }
    return object;
  }

  Mesh read_surface(const json& v, const std::string& pointer) const {
    const std::string key = pointer + "/surface";
    const std::string name = v["surface"].is_string() ? v["surface"].get<std::string>() : "";
    const SurfaceKind* kind = find_surface_kind(name);
    if (!kind) {
      std::string list;
      for (const SurfaceKind& k : surface_kinds()) list += (list.empty() ? "" : ", ") + k.name;
      fail(key, "surface must be one of " + list);
    }
    std::vector<double> values;
    std::vector<std::string> names;
    for (const SurfaceParameter& p : kind->parameters) {
      values.push_back(p.default_value);
      names.push_back(p.name);
    }
    const std::string params_key = pointer + "/params";
    if (v.contains("params")) {
      const json& params = v["params"];
      require_object(params, params_key, "params");
      only_keys(params, params_key, names, "the params of a " + name);
      for (size_t i = 0; i < kind->parameters.size(); ++i) {
        const SurfaceParameter& p = kind->parameters[i];
        if (!params.contains(p.name)) continue;
        const std::string at = JsonLines::child(params_key, p.name);
        const double d = number(params[p.name], at, p.name);
        char range[96];
        std::snprintf(range, sizeof range, p.integer ? "%.0f..%.0f" : "%g..%g", p.min, p.max);
        if (p.integer && d != std::floor(d)) fail(at, p.name + " must be an integer in " + range);
        if (d < p.min || d > p.max) fail(at, p.name + " must be in " + range);
        values[i] = d;
      }
    }
    const std::string relation = kind->check(values);
    if (!relation.empty()) fail(v.contains("params") ? params_key : key, relation);
    return kind->build(values);
  }

  std::string file_;
  std::string base_;
  JsonLines lines_;
};

std::string read_text(const std::string& path, const char* what) {
  return read_text_file(path, what, kMaxSceneBytes);
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file_name, const std::string& base_folder) {
  const json doc = parse_json_document(text, file_name);
  return SceneReader(text, file_name, base_folder).read(doc);
}

Scene load_scene(const std::string& path) {
  const std::string text = read_text(path, "a scene file");
  return parse_scene(text, path, std::filesystem::path(path).parent_path().string());
}

std::vector<std::string> scene_mesh_files(const std::string& path) {
  std::vector<std::string> meshes;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) > kMaxSceneBytes) return meshes;
  std::string text;
  try {
    text = read_text(path, "a scene file");
  } catch (const InputError&) {
    return meshes;  // the load reports it
  }
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (!doc.is_object() || !doc.contains("objects") || !doc["objects"].is_array()) return meshes;
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  for (const nlohmann::json& object : doc["objects"]) {
    if (!object.is_object() || !object.contains("mesh") || !object["mesh"].is_string()) continue;
    const std::filesystem::path relative = object["mesh"].get<std::string>();
    meshes.push_back((relative.is_absolute() ? relative : base / relative).string());
  }
  return meshes;
}

}  // namespace rastersim::frontend
