#include "runtime/scene/mesh_generators.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

namespace lg {
namespace {

// A grid of (columns+1) x (rows+1) vertices from a parametrisation; u across, v down.
template <class F>
MeshData grid(const char* name, int columns, int rows, F position_normal) {
  MeshData m;
  m.name = name;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= columns; ++c) {
      glm::vec2 uv{float(c) / float(columns), float(r) / float(rows)};
      auto [p, n] = position_normal(uv);
      m.positions.push_back(p);
      m.normals.push_back(n);
      m.uvs.push_back(uv);
    }
  auto at = [&](int r, int c) { return static_cast<uint32_t>(r * (columns + 1) + c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      // Quads split along a diagonal; winding makes the parametrisation's normal the front.
      m.indices.insert(m.indices.end(), {at(r, c), at(r + 1, c), at(r + 1, c + 1)});
      m.indices.insert(m.indices.end(), {at(r, c), at(r + 1, c + 1), at(r, c + 1)});
    }
  return m;
}

// A unit direction from sphere uvs: u is the azimuth around +Y, v runs from the +Y pole down.
glm::vec3 sphere_direction(glm::vec2 uv) {
  float phi = uv.x * glm::two_pi<float>(), theta = uv.y * glm::pi<float>();
  return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

MeshData transformed(MeshData m, glm::vec3 offset, glm::quat rotation) {
  for (auto& p : m.positions) p = rotation * p + offset;
  for (auto& n : m.normals) n = rotation * n;
  return m;
}

}  // namespace

MeshData make_ellipsoid(glm::vec3 radii, int segments, int rings) {
  return grid("ellipsoid", segments, rings, [&](glm::vec2 uv) {
    glm::vec3 d = sphere_direction(uv);
    // The normal of a scaled sphere is the direction scaled by the inverse radii.
    return std::pair{d * radii, glm::normalize(d / radii)};
  });
}

MeshData make_sphere(float radius, int segments, int rings) {
  MeshData m = make_ellipsoid(glm::vec3(radius), segments, rings);
  m.name = "sphere";
  return m;
}

MeshData make_quad(float width, float depth) {
  return grid("quad", 1, 1, [&](glm::vec2 uv) {
    return std::pair{glm::vec3((uv.x - 0.5f) * width, 0.0f, (uv.y - 0.5f) * depth), glm::vec3(0.0f, 1.0f, 0.0f)};
  });
}

MeshData make_box(glm::vec3 size) {
  MeshData box;
  box.name = "box";
  glm::vec3 h = size * 0.5f;
  // Each face is a quad in XZ moved out along its normal by the half size on that axis.
  const std::pair<glm::vec3, glm::quat> faces[] = {
      {{0, 1, 0}, glm::quat(1, 0, 0, 0)},
      {{0, -1, 0}, glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0))},
      {{1, 0, 0}, glm::angleAxis(-glm::half_pi<float>(), glm::vec3(0, 0, 1))},
      {{-1, 0, 0}, glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1))},
      {{0, 0, 1}, glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0))},
      {{0, 0, -1}, glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0))},
  };
  for (const auto& [normal, rotation] : faces) {
    // The quad's extents in its own X and Z, taken from the box axes they map to.
    glm::vec3 ax = glm::abs(rotation * glm::vec3(1, 0, 0)), az = glm::abs(rotation * glm::vec3(0, 0, 1));
    MeshData face = make_quad(2.0f * glm::dot(ax, h), 2.0f * glm::dot(az, h));
    append_mesh(box, transformed(face, normal * h, rotation));
  }
  return box;
}

MeshData make_capsule(float length, float radius, int segments, int rings) {
  // A sphere split at its equator (around X) with the halves pushed apart by length / 2.
  rings += rings % 2;  // an even count puts a row on the equator, where the cylinder starts
  MeshData m = grid("capsule", segments, rings + 1, [&](glm::vec2 uv) {
    float v = std::round(uv.y * float(rings + 1));
    float half_rings = float(rings) * 0.5f;
    // Rows up to rings/2 are one cap, the row after the other; the middle band is the cylinder.
    float sphere_v = (v <= half_rings ? v : v - 1.0f) / float(rings);
    glm::vec3 d = sphere_direction({uv.x, sphere_v});
    glm::vec3 along_x{d.y, -d.x, d.z};  // the sphere's Y pole turned onto +X
    float side = v <= half_rings ? 1.0f : -1.0f;
    return std::pair{along_x * radius + glm::vec3(side * length * 0.5f, 0.0f, 0.0f), along_x};
  });
  return m;
}

MeshData make_bunny() {
  struct Part {
    glm::vec3 center, radii;
    glm::vec3 tilt_axis;
    float tilt;  // radians
  };
  const Part parts[] = {
      {{0.0f, 0.17f, -0.02f}, {0.15f, 0.15f, 0.19f}, {1, 0, 0}, 0.3f},      // body
      {{0.0f, 0.33f, 0.13f}, {0.09f, 0.085f, 0.10f}, {1, 0, 0}, 0.0f},      // head
      {{-0.035f, 0.47f, 0.10f}, {0.025f, 0.10f, 0.04f}, {0, 0, 1}, 0.25f},  // left ear
      {{0.035f, 0.47f, 0.10f}, {0.025f, 0.10f, 0.04f}, {0, 0, 1}, -0.25f},  // right ear
      {{0.0f, 0.16f, -0.21f}, {0.045f, 0.045f, 0.045f}, {1, 0, 0}, 0.0f},   // tail
      {{-0.07f, 0.03f, 0.09f}, {0.04f, 0.03f, 0.07f}, {1, 0, 0}, 0.0f},     // left front foot
      {{0.07f, 0.03f, 0.09f}, {0.04f, 0.03f, 0.07f}, {1, 0, 0}, 0.0f},      // right front foot
      {{-0.10f, 0.06f, -0.08f}, {0.05f, 0.06f, 0.10f}, {1, 0, 0}, 0.0f},    // left haunch
      {{0.10f, 0.06f, -0.08f}, {0.05f, 0.06f, 0.10f}, {1, 0, 0}, 0.0f},     // right haunch
  };
  MeshData bunny;
  bunny.name = "bunny";
  for (const auto& p : parts)
    append_mesh(bunny, transformed(make_ellipsoid(p.radii), p.center, glm::angleAxis(p.tilt, p.tilt_axis)));
  return bunny;
}

void append_mesh(MeshData& a, const MeshData& b) {
  auto base = static_cast<uint32_t>(a.positions.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  a.uvs.insert(a.uvs.end(), b.uvs.begin(), b.uvs.end());
  for (uint32_t i : b.indices) a.indices.push_back(base + i);
}

}  // namespace lg
