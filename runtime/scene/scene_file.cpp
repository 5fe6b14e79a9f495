#include "runtime/scene/scene_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vector_relational.hpp>
#include <map>
#include <optional>
#include <set>

#include "graph/json_reader.h"
#include "graph/spelling.h"
#include "runtime/scene/json_fields.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/mesh_import.h"
#include "runtime/scene/mesh_plane.h"
#include "runtime/scene/scene_error.h"

namespace lg {
namespace {

constexpr double max_length = 1e6, max_power = 1e9;

const std::vector<std::string> entity_keys = {"name",
                                              "parent",
                                              "transform",
                                              "model",
                                              "shape",
                                              "material",
                                              "occlusion",
                                              "camera",
                                              "directional_light",
                                              "point_light",
                                              "spot_light",
                                              "sphere_light",
                                              "tube_light",
                                              "rect_light",
                                              "irradiance_volume",
                                              "reflection_probe",
                                              "captured_by_probes",
                                              "planar_reflector"};

class SceneFileReader {
 public:
  SceneFileReader(World& world, const std::string& path, const AssetRoots& roots,
                  const OcclusionBakeReader& read_occlusion, Diagnostics& d)
      : world_(world), path_(path), roots_(roots), read_occlusion_(read_occlusion), d_(d) {}

  void read(const JsonValue& root) {
    JsonFields top(root, "", "a scene file",
                   {"format", "name", "materials", "environment", "post", "entities", "occlusion"}, d_);
    if (!top.is_object()) return;
    if (const JsonValue* f = top.get("format"); !f || !f->is_string() || f->as_string() != world_format)
      top.error_at("format", std::string("expected \"format\": \"") + world_format + "\"");
    top.string("name", world_.name);
    if (const JsonValue* m = top.get("materials")) materials(*m, top.pointer("materials"));
    if (const JsonValue* env = top.get("environment")) environment(*env, top.pointer("environment"));
    if (const JsonValue* post = top.get("post")) post_settings(*post, top.pointer("post"));
    top.require("entities");
    if (const JsonValue* list = top.get("entities")) {
      if (!list->is_array()) return top.error_at("entities", "'entities' must be an array of objects");
      for (size_t i = 0; i < list->items().size(); ++i) entity(list->items()[i], json_pointer_append("/entities", i));
    }
    if (const JsonValue* bake = top.get("occlusion")) attach_scene_occlusion(top, *bake);
  }

 private:
  World& world_;
  const std::string& path_;
  const AssetRoots& roots_;
  const OcclusionBakeReader& read_occlusion_;
  Diagnostics& d_;
  std::map<std::string, int> materials_;    // name -> world material
  std::map<std::string, Entity> entities_;  // name -> entity, for "parent"

  void materials(const JsonValue& v, const std::string& p) {
    if (!v.is_object()) return d_.error(v.pos(), p, "'materials' must be an object of named materials");
    for (const auto& [name, m] : v.members()) {
      JsonFields f(m, json_pointer_append(p, name), "material '" + name + "'",
                   {"base_color", "alpha", "roughness", "metalness", "emissive"}, d_);
      PbrMaterial out;
      out.name = name;
      glm::vec3 base(out.base_color);
      f.vec3("base_color", base, 0, 1);
      f.number("alpha", out.base_color.a, 0, 1);
      out.base_color = glm::vec4(base, out.base_color.a);
      f.number("roughness", out.roughness, 0, 1);
      f.number("metalness", out.metalness, 0, 1);
      f.vec3("emissive", out.emissive, 0, max_power);
      materials_[name] = world_.add_material(std::move(out));
    }
  }

  void environment(const JsonValue& v, const std::string& p) {
    JsonFields f(v, p, "the environment", {"path", "intensity"}, d_);
    if (!f.is_object()) return;
    EnvironmentLight env;
    if (const JsonValue* path = f.get("path")) env.path = asset(f, "path", *path, {".hdr", ".exr"});
    f.number("intensity", env.intensity, 0, max_power);
    world_.add<EnvironmentLight>(world_.create("environment"), env);
  }

  void post_settings(const JsonValue& v, const std::string& p) {
    JsonFields f(v, p, "post", {"exposure"}, d_);
    PostProcessSettings post;
    f.number("exposure", post.exposure, -20, 20, "EV");
    world_.add<PostProcessSettings>(world_.create("post"), post);
  }

  // The canonical path of a file the scene refers to, or empty after reporting.
  std::string asset(const JsonFields& f, std::string_view key, const JsonValue& v,
                    const std::vector<std::string>& extensions) {
    if (!v.is_string()) {
      f.error_at(key, "'" + std::string(key) + "' must be a path relative to the scene file");
      return {};
    }
    std::string error;
    auto resolved = resolve_asset_path(path_, v.as_string(), roots_, extensions, &error);
    if (!resolved) f.error_at(key, error);
    return resolved.value_or("");
  }

  // A probe's shape: a box of half sizes `extent` or a sphere of `radius` (one of them; neither
  // keeps the sphere of the default radius).
  ProbeShape probe_shape(const JsonFields& f, glm::vec3& extent, float& radius) {
    if (f.get("extent") && f.get("radius")) f.error_at("radius", "give either 'extent' (a box) or 'radius' (a sphere)");
    if (f.get("extent")) {
      f.vec3("extent", extent, 1e-3, max_length);
      return ProbeShape::box;
    }
    f.number("radius", radius, 1e-3, max_length, "metres");
    return ProbeShape::sphere;
  }

  void entity(const JsonValue& v, const std::string& p) {
    JsonFields f(v, p, "an entity", entity_keys, d_);
    if (!f.is_object()) return;
    std::string name;
    f.string("name", name);
    Entity e = world_.create(name.empty() ? "entity " + p.substr(p.rfind('/') + 1) : name);
    if (!name.empty() && !entities_.emplace(name, e).second)
      f.error_at("name", "another entity is already named '" + name + "'");
    Transform t;
    if (const JsonValue* parent = f.get("parent")) t.parent = parent_entity(f, *parent);
    if (const JsonValue* tv = f.get("transform")) transform(*tv, f.pointer("transform"), t);
    world_.add<Transform>(e, t);

    int material = -1;
    if (const JsonValue* m = f.get("material")) material = material_index(f, *m);
    if (f.get("model") && f.get("shape"))
      f.error_at("shape", "an entity has a 'model' or a 'shape', not both");
    else if (const JsonValue* model = f.get("model"))
      import_model(f, *model, e, material);
    else if (const JsonValue* shape = f.get("shape"))
      world_.add<MeshRenderer>(e, {make_shape(*shape, f.pointer("shape")), material});
    else if (f.get("material"))
      f.error_at("material", "a material needs a 'model' or a 'shape' to apply to");
    if (const JsonValue* bake = f.get("occlusion")) attach_occlusion(f, *bake, e);
    bool captured = true;
    f.boolean("captured_by_probes", captured);
    if (!captured) each_drawn_part(e, [](MeshRenderer& r) { r.captured_by_probes = false; });
    bool reflector = false;
    f.boolean("planar_reflector", reflector);
    if (reflector) planar_reflector(f, e);
    components(f, e);
  }

  // Every mesh the entity draws must be flat: its plane is what the reflection mirrors in.
  void planar_reflector(const JsonFields& f, Entity e) {
    bool drawn = false;
    each_drawn_part(e, [&](MeshRenderer& r) {
      drawn = true;
      if (r.mesh < 0) return;  // its shape or model was already reported
      const MeshData& mesh = *world_.meshes().at(size_t(r.mesh));
      const std::optional<MeshPlane> plane = mesh_plane(mesh);
      if (!plane)
        return f.error_at("planar_reflector", "a planar reflector's mesh must be flat and face one way; '" +
                                                  mesh.name + "' has no side to reflect from");
      if (!plane->flat())
        return f.error_at("planar_reflector",
                          "a planar reflector's mesh must be flat; '" + mesh.name + "' has vertices " +
                              format_number(plane->max_distance) + " m off its plane (at most " +
                              format_number(plane->allowed_distance) + " m): use a 'quad' shape or a flat model");
      r.reflector_plane = plane->plane;
    });
    if (!drawn) f.error_at("planar_reflector", "'planar_reflector' needs a 'model' or a 'shape' to reflect with");
  }

  Entity parent_entity(const JsonFields& f, const JsonValue& v) {
    if (!v.is_string()) {
      f.error_at("parent", "'parent' must be the name of an entity listed before this one");
      return {};
    }
    if (auto found = entities_.find(v.as_string()); found != entities_.end()) return found->second;
    std::vector<std::string> names;
    for (const auto& [n, _] : entities_) names.push_back(n);
    std::string guess = closest_name(v.as_string(), names);
    f.error_at("parent", "no entity named '" + v.as_string() + "' is listed before this one" +
                             (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
    return {};
  }

  int material_index(const JsonFields& f, const JsonValue& v) {
    if (!v.is_string()) {
      f.error_at("material", "'material' must be the name of a material in 'materials'");
      return -1;
    }
    if (auto found = materials_.find(v.as_string()); found != materials_.end()) return found->second;
    std::vector<std::string> names;
    for (const auto& [n, _] : materials_) names.push_back(n);
    std::string guess = closest_name(v.as_string(), names);
    f.error_at("material", "no material named '" + v.as_string() + "' in 'materials'" +
                               (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
    return -1;
  }

  void transform(const JsonValue& v, const std::string& p, Transform& t) {
    JsonFields f(v, p, "a transform", {"position", "rotation", "look_at", "scale"}, d_);
    if (!f.is_object()) return;
    f.vec3("position", t.position, -max_length, max_length);
    std::vector<double> r;
    if (f.get("rotation") && f.get("look_at")) {
      f.error_at("look_at", "a transform has a 'rotation' or a 'look_at', not both");
    } else if (f.numbers("rotation", r, 3, 4, -1e4, 1e4)) {
      t.rotation = rotation(f, r);
    } else if (f.numbers("look_at", r, 3, 3, -max_length, max_length)) {
      glm::vec3 target(r[0], r[1], r[2]);
      if (target == t.position)
        f.error_at("look_at", "'look_at' must differ from the position");
      else
        t.rotation = look_rotation(target - t.position);
    }
    if (const JsonValue* s = f.get("scale"); s && s->is_number()) {
      float uniform = 1.0f;
      f.number("scale", uniform, 1e-6, max_length);
      t.scale = glm::vec3(uniform);
    } else {
      f.vec3("scale", t.scale, 1e-6, max_length);
    }
  }

  // Three numbers are Euler angles in degrees (yaw about Y, then pitch about X, then roll
  // about Z: R = Ry Rx Rz); four are a quaternion x, y, z, w as glTF writes them.
  glm::quat rotation(const JsonFields& f, const std::vector<double>& r) {
    if (r.size() == 3) {
      auto axis = [](double degrees, glm::vec3 a) {
        return glm::angleAxis(glm::radians(static_cast<float>(degrees)), a);
      };
      return axis(r[1], {0, 1, 0}) * axis(r[0], {1, 0, 0}) * axis(r[2], {0, 0, 1});
    }
    glm::quat q{float(r[3]), float(r[0]), float(r[1]), float(r[2])};
    if (!(glm::length(q) > 1e-6f)) {
      f.error_at("rotation", "a rotation quaternion must not be zero");
      return glm::quat(1, 0, 0, 0);
    }
    return glm::normalize(q);
  }

  void import_model(const JsonFields& f, const JsonValue& v, Entity e, int material) {
    std::string resolved = asset(f, "model", v, {".gltf", ".glb", ".obj"});
    if (resolved.empty()) return;
    try {
      bool obj = resolved.size() >= 4 &&
                 (resolved.substr(resolved.size() - 4) == ".obj" || resolved.substr(resolved.size() - 4) == ".OBJ");
      if (obj)
        import_obj(world_, resolved, e);
      else
        import_gltf(world_, resolved, e);
    } catch (const SceneError& error) {
      for (const auto& item : error.diagnostics().items()) {
        std::string place = item.pos.line > 0
                                ? ":" + std::to_string(item.pos.line) + ":" + std::to_string(item.pos.column)
                                : std::string();  // the model's own line and column, as in `file:line:col`
        f.error_at("model", "'" + v.as_string() + "'" + place + ": " + item.message);
      }
      return;
    }
    if (material < 0) return;
    // The override applies to everything the model placed: the entity's descendants.
    each_drawn_part(e, [&](MeshRenderer& r) { r.material = material; });
  }

  // Calls f on the meshes of entity e and of its descendants (what its model placed).
  template <class F>
  void each_drawn_part(Entity e, F&& f) {
    world_.each<MeshRenderer>([&](Entity drawn, MeshRenderer& r) {
      for (Entity a = drawn; !a.is_null();
           a = world_.try_get<Transform>(a) ? world_.get<Transform>(a).parent : Entity{})
        if (a == e) {
          f(r);
          return;
        }
    });
  }

  // An entity's "occlusion": a bake of its model (or shape) alone, for the meshes it draws (its
  // own and its model's) in their own space.
  void attach_occlusion(const JsonFields& f, const JsonValue& v, Entity e) {
    const JsonValue* source = f.get("model") ? f.get("model") : f.get("shape");
    if (!source) return f.error_at("occlusion", "'occlusion' needs a 'model' or a 'shape' to apply to");
    std::vector<Drawn> drawn = drawn_by([&](Entity d) {
      for (Entity a = d; !a.is_null(); a = world_.try_get<Transform>(a) ? world_.get<Transform>(a).parent : Entity{})
        if (a == e) return true;
      return false;
    });
    for (Drawn& d : drawn) d.world = glm::mat4(1.0f);
    read_bake(f, v, drawn, source->is_string() ? "model '" + source->as_string() + "'" : "this entity's shape");
  }

  // The file's own "occlusion": a bake of this scene file, every draw where it stands.
  void attach_scene_occlusion(const JsonFields& f, const JsonValue& v) {
    if (d_.has_errors()) return;  // the geometry it is checked against must be whole
    std::vector<Drawn> drawn = drawn_by([](Entity) { return true; });
    for (const Drawn& d : drawn)
      if (world_.meshes()[size_t(d.mesh)]->occlusion)
        return f.error_at("occlusion",
                          "an entity has an 'occlusion' of its own, and the scene file's bake covers "
                          "every draw: give one or the other");
    read_bake(f, v, drawn, "this scene file");
  }

  struct Drawn {
    uint32_t entity_index;
    int mesh;
    glm::mat4 world;
  };

  // The draws whose entity passes `wanted`, in draw order (entity order, as make_scene_view()
  // sorts them), with their world matrices.
  template <class Wanted>
  std::vector<Drawn> drawn_by(Wanted wanted) {
    std::vector<Drawn> drawn;
    world_.each<MeshRenderer>([&](Entity d, const MeshRenderer& r) {
      if (wanted(d)) drawn.push_back({d.index, r.mesh, world_.world_matrix(d)});
    });
    std::sort(drawn.begin(), drawn.end(),
              [](const Drawn& a, const Drawn& b) { return a.entity_index < b.entity_index; });
    return drawn;
  }

  // Reads the bake `v` names for the draws `drawn` (their meshes with these transforms) and
  // attaches it to their meshes; `what` names them in errors.
  void read_bake(const JsonFields& f, const JsonValue& v, const std::vector<Drawn>& drawn, const std::string& what) {
    const std::string bake = asset(f, "occlusion", v, {".lgbake"});
    if (bake.empty()) return;
    if (!read_occlusion_)
      return f.error_at("occlusion", "'" + v.as_string() +
                                         "' cannot be read here: this program loads worlds "
                                         "without an occlusion bake reader (WorldLoadOptions::read_occlusion)");
    if (drawn.empty()) {  // a model that failed to load has said so already
      if (!d_.has_errors()) f.error_at("occlusion", "'occlusion' needs meshes to apply to; " + what + " draws none");
      return;
    }
    std::vector<const MeshData*> meshes;
    std::vector<glm::mat4> transforms;
    std::set<int> seen;
    for (const Drawn& d : drawn) {
      if (d.mesh < 0) return;  // the shape or model already reported its error
      if (!seen.insert(d.mesh).second)
        return f.error_at("occlusion", "a mesh of " + what + " is drawn twice; a bake belongs to one draw of it");
      meshes.push_back(world_.meshes()[size_t(d.mesh)].get());
      transforms.push_back(d.world);
    }
    std::vector<std::shared_ptr<const MeshOcclusion>> baked;
    try {
      baked = read_occlusion_(bake, meshes, transforms);
    } catch (const std::exception& error) {
      return f.error_at("occlusion", "'" + v.as_string() + "' for " + what + ": " + error.what());
    }
    for (size_t m = 0; m < drawn.size() && m < baked.size(); ++m) world_.edit_mesh(drawn[m].mesh).occlusion = baked[m];
  }

  int make_shape(const JsonValue& v, const std::string& p) {
    JsonFields f(v, p, "a shape", {"type", "radius", "size", "length"}, d_);
    if (!f.is_object()) return -1;
    f.require("type");
    std::string type;
    f.string("type", type);
    const std::vector<std::string> types = {"sphere", "box", "quad", "capsule", "bunny"};
    auto needs = [&](std::initializer_list<const char*> used) {
      for (const char* key : {"radius", "size", "length"}) {
        bool wanted = std::find_if(used.begin(), used.end(),
                                   [&](const char* u) { return std::string_view(u) == key; }) != used.end();
        if (wanted)
          f.require(key);
        else if (f.get(key))
          f.error_at(key, "a " + type + " has no '" + key + "'");
      }
    };
    float radius = 0.5f, length = 1.0f;
    glm::vec3 size{1.0f};
    std::vector<double> extent;
    f.number("radius", radius, 1e-4, max_length);
    f.number("length", length, 0, max_length);
    if (type == "sphere") {
      needs({"radius"});
      return world_.add_mesh(make_sphere(radius));
    }
    if (type == "box") {
      needs({"size"});
      f.vec3("size", size, 1e-4, max_length);
      return world_.add_mesh(make_box(size));
    }
    if (type == "quad") {
      needs({"size"});
      if (f.numbers("size", extent, 2, 2, 1e-4, max_length)) size = glm::vec3(extent[0], 0.0f, extent[1]);
      return world_.add_mesh(make_quad(size.x, size.z));
    }
    if (type == "capsule") {
      needs({"length", "radius"});
      return world_.add_mesh(make_capsule(length, radius));
    }
    if (type == "bunny") {
      needs({});
      return world_.add_mesh(make_bunny());
    }
    if (f.get("type") && f.get("type")->is_string()) {
      std::string guess = closest_name(type, types);
      f.error_at("type", "unknown shape '" + type + "'; " +
                             (guess.empty() ? "expected sphere, box, quad, capsule or bunny"
                                            : "did you mean '" + guess + "'?"));
    }
    return -1;
  }

  void components(const JsonFields& entity, Entity e) {
    auto with = [&](const char* key, std::vector<std::string> keys,
                    const std::function<void(const JsonFields&)>& read) {
      if (const JsonValue* v = entity.get(key)) {
        JsonFields f(*v, entity.pointer(key), key, std::move(keys), d_);
        if (f.is_object()) read(f);
      }
    };
    with("camera", {"vertical_fov", "near", "aperture", "focus_distance"}, [&](const JsonFields& f) {
      Camera c;
      float fov = glm::degrees(c.vertical_fov);
      f.number("vertical_fov", fov, 1, 179, "degrees");
      c.vertical_fov = glm::radians(fov);
      f.number("near", c.near_plane, 1e-4, 1e3, "metres");
      f.number("aperture", c.aperture, 0, 10, "metres");
      f.number("focus_distance", c.focus_distance, 1e-3, max_length, "metres");
      world_.add<Camera>(e, c);
      if (world_.active_camera.is_null()) world_.active_camera = e;  // the file's, not an imported one
    });
    with("directional_light", {"color", "irradiance", "angular_radius", "shadows"}, [&](const JsonFields& f) {
      DirectionalLight l;
      float angle = glm::degrees(l.angular_radius);
      f.vec3("color", l.color, 0, max_power);
      f.number("irradiance", l.intensity, 0, max_power, "W/m^2");
      f.number("angular_radius", angle, 0, 10, "degrees");
      l.angular_radius = glm::radians(angle);
      f.boolean("shadows", l.casts_shadows);
      world_.add<DirectionalLight>(e, l);
    });
    with("point_light", {"color", "intensity", "range", "shadows"}, [&](const JsonFields& f) {
      PointLight l;
      f.vec3("color", l.color, 0, max_power);
      f.number("intensity", l.intensity, 0, max_power, "W/sr");
      f.number("range", l.range, 0, max_length, "metres");
      f.boolean("shadows", l.casts_shadows);
      world_.add<PointLight>(e, l);
    });
    with("spot_light", {"color", "intensity", "range", "inner_angle", "outer_angle", "shadows"},
         [&](const JsonFields& f) {
           SpotLight l;
           f.vec3("color", l.color, 0, max_power);
           f.number("intensity", l.intensity, 0, max_power, "W/sr");
           f.number("range", l.range, 0, max_length, "metres");
           float inner = glm::degrees(l.inner_cone_angle), outer = glm::degrees(l.outer_cone_angle);
           const size_t errors_before = d_.error_count();
           f.number("inner_angle", inner, 0, 90, "degrees");
           f.number("outer_angle", outer, 0, 90, "degrees");
           // Compared only when both were read: a rejected value left at its default would
           // give a second, misleading error.
           if (d_.error_count() == errors_before && inner > outer)
             f.error_at(f.get("inner_angle") ? "inner_angle" : "outer_angle",
                        "'inner_angle' (" + format_number(inner) + " degrees) must not exceed 'outer_angle' (" +
                            format_number(outer) + " degrees)");
           l.inner_cone_angle = glm::radians(inner);
           l.outer_cone_angle = glm::radians(outer);
           f.boolean("shadows", l.casts_shadows);
           world_.add<SpotLight>(e, l);
         });
    with("sphere_light", {"color", "radiance", "radius", "shadows"}, [&](const JsonFields& f) {
      SphereLight l;
      f.vec3("color", l.color, 0, max_power);
      f.number("radiance", l.intensity, 0, max_power, "W/(m^2 sr)");
      f.number("radius", l.radius, 1e-4, 1e3, "metres");
      f.boolean("shadows", l.casts_shadows);
      world_.add<SphereLight>(e, l);
    });
    with("tube_light", {"color", "radiance", "length", "radius", "shadows"}, [&](const JsonFields& f) {
      TubeLight l;
      f.vec3("color", l.color, 0, max_power);
      f.number("radiance", l.intensity, 0, max_power, "W/(m^2 sr)");
      f.number("length", l.length, 0, 1e3, "metres");
      f.number("radius", l.radius, 1e-4, 1e3, "metres");
      f.boolean("shadows", l.casts_shadows);
      world_.add<TubeLight>(e, l);
    });
    with("rect_light", {"color", "radiance", "width", "height", "two_sided", "shadows"}, [&](const JsonFields& f) {
      RectLight l;
      f.vec3("color", l.color, 0, max_power);
      f.number("radiance", l.intensity, 0, max_power, "W/(m^2 sr)");
      f.number("width", l.width, 1e-4, 1e3, "metres");
      f.number("height", l.height, 1e-4, 1e3, "metres");
      f.boolean("two_sided", l.two_sided);
      f.boolean("shadows", l.casts_shadows);
      world_.add<RectLight>(e, l);
    });
    with("irradiance_volume", {"size", "probes"}, [&](const JsonFields& f) {
      IrradianceVolume vol;
      f.vec3("size", vol.size, 1e-3, max_length);
      std::vector<double> counts;
      if (f.numbers("probes", counts, 3, 3, 1, 256)) {
        if (counts[0] != std::floor(counts[0]) || counts[1] != std::floor(counts[1]) ||
            counts[2] != std::floor(counts[2]))
          f.error_at("probes", "'probes' must be three whole numbers");
        else
          vol.probe_counts = glm::ivec3(counts[0], counts[1], counts[2]);
      }
      world_.add<IrradianceVolume>(e, vol);
    });
    with("reflection_probe", {"extent", "radius", "blend", "proxy"}, [&](const JsonFields& f) {
      ReflectionProbe probe;
      const size_t errors_before = d_.error_count();
      probe.influence = probe_shape(f, probe.extent, probe.radius);
      f.number("blend", probe.blend, 0, max_length, "metres");
      // The weight must reach 1 somewhere: a blend deeper than the volume's half size never does.
      const float half = probe.influence == ProbeShape::box ? std::min({probe.extent.x, probe.extent.y, probe.extent.z})
                                                            : probe.radius;
      if (d_.error_count() == errors_before && probe.blend > half)
        f.error_at("blend", "'blend' (" + format_number(probe.blend) + " m) must not exceed the influence volume's " +
                                (probe.influence == ProbeShape::box ? "smallest extent (" : "radius (") +
                                format_number(half) + " m)");
      probe.proxy = probe.influence, probe.proxy_extent = probe.extent, probe.proxy_radius = probe.radius;
      if (const JsonValue* proxy = f.get("proxy")) {
        JsonFields p(*proxy, f.pointer("proxy"), "the reflection probe's proxy", {"extent", "radius", "offset"}, d_);
        if (p.is_object()) {
          const size_t proxy_errors = d_.error_count();
          probe.proxy = probe_shape(p, probe.proxy_extent, probe.proxy_radius);
          p.vec3("offset", probe.proxy_offset, -max_length, max_length);
          const glm::vec3 o = glm::abs(probe.proxy_offset);
          const bool inside = probe.proxy == ProbeShape::box ? glm::all(glm::lessThan(o, probe.proxy_extent))
                                                             : glm::length(probe.proxy_offset) < probe.proxy_radius;
          // The cube is taken at the entity's origin: a proxy around somewhere else is not what it saw.
          if (d_.error_count() == proxy_errors && !inside)
            f.error_at("proxy", "the proxy must contain the probe (the entity's origin)");
        }
      }
      world_.add<ReflectionProbe>(e, probe);
    });
  }
};

World read_world(const std::optional<JsonValue>& root, const std::string& path, const AssetRoots& roots,
                 const OcclusionBakeReader& read_occlusion, Diagnostics& d) {
  World world;
  world.name = std::filesystem::path(path).stem().string();
  if (root) SceneFileReader(world, path, roots, read_occlusion, d).read(*root);
  if (d.has_errors()) {
    d.sort_by_position();
    throw SceneError(std::move(d));
  }
  return world;
}

}  // namespace

World load_scene_file(const std::string& path, const AssetRoots& roots, const OcclusionBakeReader& read_occlusion) {
  Diagnostics d(path);
  auto root = read_json_file(path, d);
  return read_world(root, path, roots, read_occlusion, d);
}

World parse_scene_file(std::string_view text, const std::string& path, const AssetRoots& roots,
                       const OcclusionBakeReader& read_occlusion) {
  Diagnostics d(path);
  auto root = read_json(text, d);
  return read_world(root, path, roots, read_occlusion, d);
}

}  // namespace lg
