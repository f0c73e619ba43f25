// Stiff scenes for every method of the table (stability_methods.h): each case is rendered
// with `reference` and every configuration, and each image must be free of garbage, keep the
// reference's visibility and stay within the configuration's bound (docs/STABILITY.md).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "fastshade/primitives.h"
#include "fastshade/scene.h"
#include "front/projection.h"
#include "front/vertex_stage.h"
#include "stability/stability_harness.h"

namespace fastshade::stability {
namespace {

const ::testing::Environment* const kTable = ::testing::AddGlobalTestEnvironment(new TableWriter);

// The light most cases use: off the view axis, so H is neither V nor L.
const glm::vec3 kLight(0.3f, 0.2f, 1.0f);

// Ground planes: the grid (in XY, normals around +z) laid into XZ (+z turns to +y), lit from
// above and in front; kFacingHighlight is the model-space normal that the camera, looking
// down -z, sees as H = normalize(L + V) for that light.
const glm::vec3 kLightFromAbove(0.0f, 1.0f, 0.3f);
const glm::mat4 kLayFlat = glm::rotate(glm::mat4(1.0f), float(-M_PI / 2), glm::vec3(1, 0, 0));
const glm::dvec3 kFacingHighlight = glm::dvec3(glm::inverse(kLayFlat) *
                                               glm::vec4(glm::normalize(glm::vec3(0, 1, 1.3f)), 0.0f));

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A scene through parse_scene, with the suite's colours and one view-space light.
Scene json_scene(int size, double shininess, glm::vec3 light, const std::string& camera,
                 const std::string& objects) {
  const std::string json =
      R"({"image": {"width": )" + std::to_string(size) + R"(, "height": )" + std::to_string(size) +
      R"(, "background": [)" + number(kBackground) + "," + number(kBackground) + "," + number(kBackground) +
      R"(]}, "camera": )" + camera + R"(, "ambient": [)" + number(kAmbient) + "," + number(kAmbient) + "," +
      number(kAmbient) + R"(], "lights": [{"direction": [)" + number(light.x) + "," + number(light.y) + "," +
      number(light.z) + R"(], "space": "view"}], "materials": {"m": {"diffuse": )" + number(kDiffuse) +
      R"(, "specular": )" + number(kSpecular) + R"(, "shininess": )" + number(shininess) +
      R"(}}, "objects": [)" + objects + "]}";
  return parse_scene(json, "stability", ".");
}

const char* const kFit = R"({"fit": true, "distance": 2.7, "fovy_deg": 45})";

// A 128 x 128 pixel-camera grid whose normals turn around H by up to half_angle.
Case dome_case(const std::string& name, double shininess, double half_angle, int quads = 16) {
  Case c{name, base_scene(128, 128, shininess, kLight)};
  pixel_camera(c.scene);
  add_object(c.scene, grid_mesh(quads, quads, {-64, -64}, {64, 64}, dome(half_vector(c.scene), half_angle)));
  return c;
}

// ---- specular exponents ------------------------------------------------------------------

// The highlight fills the image at every exponent: normals turn by 3 / sqrt(n) (cos^n falls
// to 1 %) towards the edges.
TEST(StabilityScenes, SpecularExponents) {
  for (double n : {1.0, 2.0, 37.5, 1000.0, 1e4, 1e6})
    run_case(dome_case("exponent " + number(n) + ", highlight over the image", n, std::min(0.8, 3 / std::sqrt(n))));
}

// A whole sphere: per-pixel normals turn by ~0.02 rad, the lobe at n = 1e4 is 0.01 rad wide
// and at 1e6 0.001 rad: highlights narrower than a pixel.
TEST(StabilityScenes, HighlightsNarrowerThanAPixel) {
  for (double n : {1e4, 1e6}) {
    Case c{"highlight < 1 px (sphere, n " + number(n) + ")",
           json_scene(128, n, kLight, kFit, R"({"primitive": "icosphere", "subdivisions": 4})")};
    run_case(c);
  }
}

// ---- light directions -----------------------------------------------------------------

TEST(StabilityScenes, GrazingLightAndLightAlongTheView) {
  const std::string sphere = R"({"primitive": "uvsphere", "segments": 48, "rings": 24})";
  struct Setup {
    const char* name;
    glm::vec3 light;
    double n;
  };
  for (const Setup& s : {Setup{"grazing light, N.L = 0 across the sphere", {1, 0, 1e-3f}, 37.5},
                         Setup{"light in the image plane (L perpendicular to V)", {1, 0.2f, 0}, 37.5},
                         Setup{"light along the view (H = L = V)", {0, 0, 1}, 1000},
                         Setup{"light behind the viewer (no half vector)", {0, 0, -1}, 37.5}})
    run_case(Case{s.name, json_scene(128, s.n, s.light, kFit, sphere)});
}

// A bright light on a shiny material: the colour clips at 1 over the highlight's core, a kink
// the hybrid's segments interpolate across (the clip comes after the lerp, so it is harmless).
TEST(StabilityScenes, SaturatedHighlight) {
  Case c = dome_case("saturated highlight (colour clipped at 1)", 37.5, 0.5);
  c.scene.lights[0].color = glm::vec3(1.8f);
  run_case(c);
}

// ---- vertex normals -------------------------------------------------------------------

// The exact colour of a flat grid whose normals are all n (infinite viewer): every pixel.
std::function<bool(int, int, uint8_t*)> flat_colour(const Scene& s, glm::dvec3 n) {
  n = glm::normalize(n);
  const glm::dvec3 l = glm::normalize(glm::dvec3(s.lights[0].direction));
  const glm::dvec3 h = glm::normalize(l + glm::dvec3(0, 0, 1));
  const Material& m = s.materials[0];
  uint8_t rgb[3];
  for (int ch = 0; ch < 3; ++ch)
    rgb[ch] = quantize(s.ambient[ch] + m.diffuse[ch] * std::max(glm::dot(n, l), 0.0) +
                           m.specular[ch] * cos_power(glm::dot(n, h), m.shininess),
                       false);
  return [=](int, int, uint8_t* out) {
    for (int ch = 0; ch < 3; ++ch) out[ch] = rgb[ch];
    return true;
  };
}

TEST(StabilityScenes, VertexNormalsEqualNearlyEqualAntiparallel) {
  {
    Case c = dome_case("vertex normals equal", 1000, 0.0, 8);
    c.analytic = flat_colour(c.scene, half_vector(c.scene));
    run_case(c);
  }
  {
    // Normals 1e-6 rad apart: the colour is the flat one within far less than a step.
    Case c = dome_case("vertex normals 1e-6 rad apart", 1000, 0.5e-6 / std::sqrt(2.0), 8);
    c.analytic = flat_colour(c.scene, half_vector(c.scene));
    run_case(c);
  }
  {
    // Columns of vertices alternate N, -N, N: the exact normal flips across two lines.
    Case c{"antiparallel vertex normals (fold lines)", base_scene(128, 128, 37.5, kLight)};
    pixel_camera(c.scene);
    const glm::vec3 n = glm::normalize(glm::vec3(half_vector(c.scene)) + glm::vec3(0.2f, 0, 0));
    add_object(c.scene, grid_mesh(2, 4, {-64, -64}, {64, 64}, [&](double u, double) { return u == 0.5 ? -n : n; }));
    c.fold = true;
    run_case(c);
  }
  {
    // Not coplanar: the interpolated normal passes through zero at one point on an edge and
    // sweeps every direction around it.
    Case c{"antiparallel vertex normals (point)", base_scene(128, 128, 37.5, kLight)};
    pixel_camera(c.scene);
    const glm::dvec3 h = half_vector(c.scene);
    Mesh m;
    m.source = "antiparallel";
    m.positions = {{-70, -60, 0}, {70, -60, 0}, {0, 70, 0}};
    m.normals = {glm::vec3(h), glm::vec3(-h), glm::normalize(glm::vec3(h) + glm::vec3(0, 0.7f, 0))};
    m.triangles = {{0, 1, 2}};
    add_object(c.scene, std::move(m));
    c.fold = true;
    run_case(c);
  }
}

// Per-pixel normal angles of 2e-4 rad, below where float rounds 2 cos(phi) to 2 (docs/PAPER.md,
// "Rotation by the difference form"): the equal-angle recurrence's stiff case.
TEST(StabilityScenes, PerPixelNormalAnglesBelowTwoPointFourEMinusFour) {
  run_case(dome_case("per-pixel normal angle 2e-4 rad", 2000, 64 * 2e-4));
  run_case(dome_case("per-pixel normal angle 1e-6 rad", 2000, 64 * 1e-6));
}

// ---- geometry -------------------------------------------------------------------------

// 64 slivers, each 2000 px long and exactly 0.2 px^2 after snapping (doubled area 26214 in
// 1/256-px units: long edge (512000, 7), third vertex at (69398, 1)), one per pixel row, laid
// so that the row's centres fall in the thin band near the third vertex.
TEST(StabilityScenes, Slivers2000PxLongAndPointTwoPxSquared) {
  Case c{"slivers 2000 px x 0.2 px^2", base_scene(256, 64, 37.5, kLight)};
  pixel_camera(c.scene);
  Mesh m;
  m.source = "slivers";
  const glm::dvec3 h = half_vector(c.scene);
  auto world = [&](double px, double py) { return glm::vec3(float(px - 128.0), float(32.0 - py), 0.0f); };
  for (int row = 0; row < 64; ++row) {
    // A at the row's centre line plus j/256 px, for j cycling through small offsets.
    const double ax = -200.0 + (row % 8) * 16.0, ay = row + 0.5 + ((row / 8) % 4 - 2) / 256.0;
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.push_back(world(ax, ay));
    m.positions.push_back(world(ax + 512000 / 256.0, ay + 7 / 256.0));
    m.positions.push_back(world(ax + 69398 / 256.0, ay + 1 / 256.0));
    m.normals.push_back(glm::vec3(h));
    m.normals.push_back(glm::normalize(glm::vec3(h) + glm::vec3(0.6f, 0, 0)));
    m.normals.push_back(glm::normalize(glm::vec3(h) + glm::vec3(0, 0.6f, 0)));
    m.triangles.push_back({base, base + 1, base + 2});
  }
  // The pipeline snaps each to the intended fixed-point corners: its area is 0.2 px^2.
  const ViewTransform xf = view_transform(c.scene);
  const Viewport vp = make_viewport(c.scene.width, c.scene.height);
  for (const auto& t : m.triangles) {
    ScreenVertex s[3];
    for (int i = 0; i < 3; ++i) s[i] = project(xf.proj * xf.view * glm::vec4(m.positions[t[i]], 1.0f), vp);
    const int64_t det = (int64_t(s[1].x_fx) - s[0].x_fx) * (int64_t(s[2].y_fx) - s[0].y_fx) -
                        (int64_t(s[2].x_fx) - s[0].x_fx) * (int64_t(s[1].y_fx) - s[0].y_fx);
    ASSERT_EQ(std::llabs(det), 26214) << "the sliver must snap to 0.2 px^2";
  }
  add_object(c.scene, std::move(m));
  RenderOptions o;
  o.method = ShadingMethod::Reference;
  RenderStats stats;
  render(c.scene, o, 1, &stats);
  EXPECT_GT(stats.covered_pixels, 100) << "the slivers must cover pixel centres to test anything";
  run_case(c);
}

// One triangle reaching 30000 px from the image centre (inside the guard band, no clipping)
// and one reaching 1e5 px (clipped to the band: new vertices with interpolated normals).
// Its centroid is the image centre, where its normals (72 degrees off H, symmetric) average
// to H: the highlight of a narrow lobe (n 5000) sits in the middle.
TEST(StabilityScenes, TrianglesSpanningTheGuardBand) {
  for (double reach : {30000.0, 1e5}) {
    Case c{"triangle reaching " + number(reach) + " px", base_scene(128, 128, 5000, kLight)};
    pixel_camera(c.scene);
    const glm::dvec3 h = half_vector(c.scene);
    const glm::dvec3 e1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), h)), e2 = glm::cross(h, e1);
    Mesh m;
    m.source = "guard band";
    for (double angle : {90.0, 210.0, 330.0}) {
      const double a = angle * M_PI / 180;
      m.positions.push_back({float(reach * std::cos(a)), float(reach * std::sin(a)), 0.0f});
      m.normals.push_back(glm::vec3(glm::normalize(h + 3.0 * (std::cos(a) * e1 + std::sin(a) * e2))));
    }
    m.triangles = {{0, 1, 2}};
    add_object(c.scene, std::move(m));
    run_case(c);
  }
}

TEST(StabilityScenes, VerticesAMillionUnitsFromTheOrigin) {
  {
    // A sphere at (1e6, 1e6, 1e6) seen from 3 units away.
    const std::string camera = R"({"eye": [1000000, 1000000, 1000003], "target": [1000000, 1000000, 1000000],
                                   "fovy_deg": 45, "near": 1, "far": 10})";
    const std::string sphere = R"({"primitive": "icosphere", "subdivisions": 3,
                                   "transform": {"translate": [1000000, 1000000, 1000000]}})";
    run_case(Case{"sphere at (1e6, 1e6, 1e6)", json_scene(128, 37.5, kLight, camera, sphere)});
  }
  {
    // A ground plane reaching 1e6 in every direction seen from 1 unit above: crosses the near
    // plane, reaches the horizon, spans the guard band.
    Case c{"ground plane to 1e6, eye 1 unit above", base_scene(128, 128, 37.5, kLightFromAbove)};
    c.scene.camera = Camera{{0, 1, 0}, {0, 0.5f, -10}, {0, 1, 0}, 60.0f, 0.01f, 1e7f};
    add_object(c.scene, grid_mesh(8, 8, {-1e6f, -1e6f}, {1e6f, 1e6f}, dome(kFacingHighlight, 1.2)), kLayFlat);
    run_case(c);
  }
}

// The eye 0.05 above a plane that passes under and behind it, near plane 1e-3: triangles are
// clipped where w = 1e-3 and reach w = 10 (1/w from 0.1 to 1000 in one triangle).
TEST(StabilityScenes, TrianglesCrossingTheNearPlane) {
  for (double n : {37.5, 1000.0})
    for (Viewer viewer : {Viewer::Infinite, Viewer::Local}) {
      Case c{"near plane crossed, w from 1e-3 (n " + number(n) + (viewer == Viewer::Local ? ", local viewer)" : ")"),
             base_scene(128, 128, n, kLightFromAbove)};
      c.scene.viewer = viewer;
      c.scene.camera = Camera{{0, 0.05f, 0}, {0, 0, -1}, {0, 1, 0}, 90.0f, 1e-3f, 100.0f};
      const NormalField normals = dome(kFacingHighlight, std::min(0.8, 3 / std::sqrt(n)));
      add_object(c.scene, grid_mesh(4, 4, {-10, -10}, {10, 10}, normals), kLayFlat);
      run_case(c);
    }
}

// 20,480 triangles on a sphere 30 px across (0.07 px^2 each on average): most cover no
// pixel centre, some one.
TEST(StabilityScenes, SubPixelTriangles) {
  const std::string camera = R"({"eye": [0, 0, 6.5], "target": [0, 0, 0], "fovy_deg": 45, "near": 1, "far": 20})";
  for (double n : {37.5, 1000.0})
    run_case(Case{"sub-pixel triangles (n " + number(n) + ")",
                  json_scene(64, n, kLight, camera, R"({"primitive": "icosphere", "subdivisions": 5})")});
}

}  // namespace
}  // namespace fastshade::stability
