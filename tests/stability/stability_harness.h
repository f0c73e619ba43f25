// Scene-level stability checks: build a stiff scene through the public API (in-memory or
// procedural meshes), render it with `reference` and every configuration of the method table,
// and require of each image: no garbage (every covered pixel within the colour range the scene
// can produce, so a NaN turned to 0 shows), the reference's visibility, and an error within
// the configuration's derived bound (stability_bounds.h). Each result becomes a row of the
// table in docs/STABILITY.md (written when FASTSHADE_STABILITY_TABLE names a file).
#pragma once
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "fastshade/image.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "light/lighting.h"
#include "stability/stability_bounds.h"
#include "stability/stability_methods.h"

namespace fastshade::stability {

// ---- scenes ---------------------------------------------------------------------------------

// Colours chosen so that garbage shows: every lit pixel is at least the ambient 0.15 (38 LSB),
// the background is 0.1 (26 LSB), a NaN quantises to 0, and kd + ks + ambient = 1 keeps
// highlights below saturation, where clamping would hide errors.
inline constexpr float kAmbient = 0.15f, kBackground = 0.1f, kDiffuse = 0.35f, kSpecular = 0.5f;

inline Scene base_scene(int width, int height, double shininess, glm::vec3 light_view) {
  Scene s;
  s.width = width;
  s.height = height;
  s.background = glm::vec3(kBackground);
  s.ambient = glm::vec3(kAmbient);
  s.lights.push_back({glm::normalize(light_view), glm::vec3(1.0f), LightSpace::View});
  s.materials.push_back({"m", glm::vec3(kDiffuse), glm::vec3(kSpecular), shininess});
  s.source = "stability";
  return s;
}

// A camera on +z looking down -z at the z = 0 plane, where one world unit is one pixel:
// world (x, y, 0) lands on pixel centre (W/2 + x, H/2 - y) up to float rounding.
inline constexpr float kPixelCameraDistance = 1000.0f;
inline void pixel_camera(Scene& s, float near = 1.0f, float far = 1e4f) {
  const double half_fov = std::atan(0.5 * s.height / kPixelCameraDistance);
  s.camera = Camera{{0, 0, kPixelCameraDistance}, {0, 0, 0}, {0, 1, 0}, float(2 * half_fov * 180 / M_PI), near, far};
}

using NormalField = std::function<glm::vec3(double u, double v)>;  // u, v in [0, 1]

// An nx x ny grid of quads over [x0, x1] x [y0, y1] at z = 0, counter-clockwise seen from +z.
inline Mesh grid_mesh(int nx, int ny, glm::vec2 lo, glm::vec2 hi, const NormalField& normal) {
  Mesh m;
  m.source = "grid";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double u = double(i) / nx, v = double(j) / ny;
      m.positions.push_back({float(lo.x + (hi.x - lo.x) * u), float(lo.y + (hi.y - lo.y) * v), 0.0f});
      m.normals.push_back(normal(u, v));
    }
  auto at = [&](int i, int j) { return uint32_t(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// Normals around `centre`, turned by up to `half_angle` radians towards the grid's edges: a
// highlight centred in the image when `centre` is the half vector.
inline NormalField dome(glm::dvec3 centre, double half_angle) {
  centre = glm::normalize(centre);
  const glm::dvec3 e1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), centre));
  const glm::dvec3 e2 = glm::cross(centre, e1);
  return [=](double u, double v) {
    const double a = (2 * u - 1) * half_angle, b = (2 * v - 1) * half_angle, angle = std::hypot(a, b);
    const double sinc = angle > 0 ? std::sin(angle) / angle : 1.0;  // turn by `angle` towards (a, b)
    return glm::vec3(glm::normalize(centre * std::cos(angle) + (e1 * a + e2 * b) * sinc));
  };
}

inline void add_object(Scene& s, Mesh mesh, const glm::mat4& model = glm::mat4(1.0f)) {
  s.objects.push_back({std::make_shared<const Mesh>(std::move(mesh)), 0, model});
}

// The half vector of the scene's first light for the infinite viewer.
inline glm::dvec3 half_vector(const Scene& s) {
  return glm::normalize(glm::dvec3(s.lights[0].direction) + glm::dvec3(0, 0, 1));
}

// Largest angle between two vertex normals of one triangle, over every mesh.
inline double normal_spread(const Scene& s) {
  double spread = 0;
  for (const Object& o : s.objects) {
    const Mesh& m = *o.mesh;
    if (m.normals.size() != m.positions.size()) return M_PI;  // recomputed: anything
    for (const auto& t : m.triangles)
      for (int a = 0; a < 3; ++a) {
        const glm::dvec3 na = glm::normalize(glm::dvec3(m.normals[t[a]]));
        const glm::dvec3 nb = glm::normalize(glm::dvec3(m.normals[t[(a + 1) % 3]]));
        spread = std::max(spread, std::atan2(glm::length(glm::cross(na, nb)), glm::dot(na, nb)));
      }
  }
  return spread;
}

// ---- one case -------------------------------------------------------------------------------

struct Case {
  Case(std::string case_name, Scene case_scene) : name(std::move(case_name)), scene(std::move(case_scene)) {}
  std::string name;
  Scene scene;
  // The exact normal flips across a curve (antiparallel vertex normals): the colour jumps
  // there, and a pixel centre within rounding of the curve may land on either side. Pixels
  // with a neighbour more than kFoldJumpLsb away in the reference are left out and counted.
  bool fold = false;
  // Optional closed form of the reference at a pixel (8-bit, per channel), or none.
  std::function<bool(int x, int y, uint8_t out[3])> analytic;
};

inline constexpr int kFoldJumpLsb = 24;

struct Row {
  std::string case_name, config;
  Bound bound;
  double measured = 0;
  long long excluded = 0;
};

inline std::vector<Row>& table_rows() {
  static std::vector<Row> rows;
  return rows;
}

// One result for the table; thread-safe (tests may run cases concurrently).
inline void record(Row row) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  table_rows().push_back(std::move(row));
}

// Writes the tables of docs/STABILITY.md when FASTSHADE_STABILITY_TABLE names a file: scene
// cases against every configuration ("bound / measured", two tables: the methods, then the
// BRDFs), then the kernel-level rows.
class TableWriter : public ::testing::Environment {
 public:
  void TearDown() override {
    const char* path = std::getenv("FASTSHADE_STABILITY_TABLE");
    if (!path || table_rows().empty()) return;
    std::map<std::string, const MethodConfig*> configs;
    for (const MethodConfig& c : method_configs()) configs[c.label] = &c;
    std::vector<std::string> cases;
    std::map<std::string, std::map<std::string, const Row*>> cell;
    std::vector<const Row*> kernel_rows;
    for (const Row& r : table_rows()) {
      if (!configs.count(r.config)) {
        kernel_rows.push_back(&r);
        continue;
      }
      if (!cell.count(r.case_name)) cases.push_back(r.case_name);
      cell[r.case_name][r.config] = &r;
    }
    std::ofstream out(path);
    auto write = [&](bool brdfs) {
      std::vector<const MethodConfig*> cols;
      for (const MethodConfig& c : method_configs())
        if ((c.options.brdf.kind != BrdfKind::Exact) == brdfs) cols.push_back(&c);
      out << "| case |";
      for (const MethodConfig* c : cols) out << " " << c->label << " |";
      out << "\n|---|";
      for (std::size_t i = 0; i < cols.size(); ++i) out << "---|";
      out << "\n";
      for (const std::string& name : cases) {
        const Row& first = *cell[name].begin()->second;
        out << "| " << name;
        if (first.excluded) out << " (" << first.excluded << " px at the fold left out)";
        out << " |";
        for (const MethodConfig* c : cols) {
          const auto it = cell[name].find(c->label);
          if (it == cell[name].end()) {
            out << " |";
            continue;
          }
          const Row& r = *it->second;
          out << " " << (r.bound.status == Status::NoBound ? std::string("—") : cell_number(r.bound.lsb)) << " / "
              << cell_number(r.measured) << (r.bound.status == Status::Fallback ? " ⇄" : "") << " |";
        }
        out << "\n";
      }
      out << "\n";
    };
    write(false);
    write(true);
    out << "| kernel-level case | kernel | bound | measured |\n|---|---|---:|---:|\n";
    for (const Row* r : kernel_rows)
      out << "| " << r->case_name << " | " << r->config << " | " << cell_number(r->bound.lsb) << " | "
          << cell_number(r->measured) << " |\n";
  }

 private:
  static std::string cell_number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
};

struct Images {
  Image image;
  RenderStats stats;
};

inline Images render_case(const Scene& scene, const RenderOptions& options) {
  Images r;
  r.image = render(scene, options, 1, &r.stats);
  return r;
}

// With FASTSHADE_STABILITY_IMAGES naming a directory, every image is written there as
// "<case> -- <configuration>.png", to look at what a case renders.
inline void dump_image(const Case& c, const MethodConfig& config, const Image& image) {
  const char* dir = std::getenv("FASTSHADE_STABILITY_IMAGES");
  if (!dir) return;
  std::string name = c.name + " -- " + config.label;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '.') ch = '_';
  write_image(image, std::filesystem::path(dir) / (name + ".png"));
}

// Every pixel is the background or a colour the scene's lighting can produce.
inline void expect_plausible(const Case& c, const Image& img, const std::string& label) {
  const Scene& s = c.scene;
  double top[3] = {s.ambient.r, s.ambient.g, s.ambient.b};
  double lo = 1;
  for (int ch = 0; ch < 3; ++ch) lo = std::min(lo, double(s.ambient[ch]));
  for (const Material& m : s.materials)
    for (int ch = 0; ch < 3; ++ch) {
      double add = 0;
      for (const Light& l : s.lights) add += l.color[ch] * (m.diffuse[ch] + m.specular[ch]);
      top[ch] = std::max(top[ch], s.ambient[ch] + add);
    }
  uint8_t bg[3];
  for (int ch = 0; ch < 3; ++ch) bg[ch] = quantize(s.background[ch], false);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const uint8_t* p = &img.rgb[(std::size_t(y) * img.width + x) * 3];
      if (p[0] == bg[0] && p[1] == bg[1] && p[2] == bg[2]) continue;
      for (int ch = 0; ch < 3; ++ch) {
        const double hi = std::min(255.0, std::ceil(255.0 * std::min(1.0, top[ch])) + 1);
        const double low = std::floor(255.0 * lo) - 1;
        ASSERT_TRUE(p[ch] >= low && p[ch] <= hi)
            << c.name << ", " << label << ": pixel (" << x << ", " << y << ") channel " << ch << " = "
            << int(p[ch]) << " outside [" << low << ", " << hi << "]: garbage (a NaN quantises to 0)";
      }
    }
}

// Largest channel difference between two images of one size, in LSB.
inline int max_difference(const Image& a, const Image& b) {
  int worst = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) worst = std::max(worst, std::abs(int(a.rgb[i]) - int(b.rgb[i])));
  return worst;
}

// Renders the case with every configuration and checks each against its bound.
inline void run_case(const Case& c) {
  const std::vector<MethodConfig>& configs = method_configs();
  const CaseGeometry geo{normal_spread(c.scene)};
  const Images ref = render_case(c.scene, configs.front().options);
  expect_plausible(c, ref.image, "reference");
  const int w = ref.image.width, h = ref.image.height;
  auto at = [&](const Image& img, int x, int y, int ch) { return int(img.rgb[(std::size_t(y) * w + x) * 3 + ch]); };
  if (c.analytic) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        uint8_t want[3];
        if (!c.analytic(x, y, want)) continue;
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_LE(std::abs(at(ref.image, x, y, ch) - int(want[ch])), 1)
              << c.name << ": reference against the closed form at (" << x << ", " << y << ")";
      }
  }
  // Pixels next to a fold of the exact normal (see Case::fold).
  std::vector<char> skip(std::size_t(w) * h, 0);
  long long excluded = 0;
  if (c.fold)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= w || v >= h || skip[std::size_t(y) * w + x]) continue;
            for (int ch = 0; ch < 3; ++ch)
              if (std::abs(at(ref.image, x, y, ch) - at(ref.image, u, v, ch)) > kFoldJumpLsb) {
                skip[std::size_t(y) * w + x] = 1;
                ++excluded;
                break;
              }
          }
  for (const MethodConfig& config : configs) {
    const Bound bound = derive_bound(config, c.scene, geo);
    const Images got = config.rule == BoundRule::Yardstick ? ref : render_case(c.scene, config.options);
    expect_plausible(c, got.image, config.label);
    dump_image(c, config, got.image);
    EXPECT_EQ(got.stats.covered_pixels, ref.stats.covered_pixels)
        << c.name << ", " << config.label << ": visibility must not depend on the method";
    double worst = 0;
    int wx = 0, wy = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (skip[std::size_t(y) * w + x]) continue;
        for (int ch = 0; ch < 3; ++ch) {
          const double e = std::abs(at(got.image, x, y, ch) - at(ref.image, x, y, ch));
          if (e > worst) worst = e, wx = x, wy = y;
        }
      }
    EXPECT_LE(worst, bound.lsb) << c.name << ", " << config.label << ": " << worst
                                << " LSB at pixel (" << wx << ", " << wy << "), bound " << bound.lsb;
    record({c.name, config.label, bound, worst, excluded});
  }
}

}  // namespace fastshade::stability
