// fastshade.Renderer: every render option by its Python name; frames rendered with the GIL
// released, so several renderers in several Python threads run at once.
#include <memory>
#include <string>
#include <utility>

#include <nanobind/ndarray.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bindings.h"
#include "fastshade/render.h"
#include "scene_binding.h"

namespace nb = nanobind;

namespace fastshade::python {

namespace {

struct PyRenderer {
  Scene scene;  // the renderer's own copy: the Python scene may change afterwards
  std::unique_ptr<Renderer> renderer;
};

using ColorArray = nb::ndarray<nb::numpy, uint8_t, nb::shape<-1, -1, 3>>;

// One frame: colour (H, W, 3) uint8, owned by the array, and the stats as JSON text.
std::pair<ColorArray, std::string> render_frame(PyRenderer& r) {
  auto image = std::make_unique<Image>();
  RenderStats stats;
  {
    nb::gil_scoped_release unlocked;
    r.renderer->render_frame(*image);
    stats = r.renderer->last_stats();
    stats.frames = 1;
  }
  const std::size_t height = image->height, width = image->width;
  uint8_t* pixels = image->rgb.data();
  Image* owned = image.release();
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<Image*>(p); });
  return {ColorArray(pixels, {height, width, 3}, owner), stats.to_json()};
}

}  // namespace

void bind_render(nb::module_& m) {
  nb::class_<PyRenderer>(m, "_Renderer")
      .def(nb::new_([](const PyScene& scene, int threads, const std::string& method, double max_error, int tile,
                       const std::string& isa, bool srgb, const std::string& brdf, const std::string& normals,
                       const std::string& gouraud, const std::string& hidden_faces, double spec_threshold,
                       const std::string& spec_method, const std::string& classifier, double classify_min_px) {
             RenderOptions o;
             o.threads = threads, o.method = method, o.max_error = max_error, o.tile_px = tile, o.isa = isa;
             o.srgb = srgb, o.brdf = brdf, o.normals = normals, o.gouraud = gouraud, o.hidden_faces = hidden_faces;
             o.spec_threshold = spec_threshold, o.spec_method = spec_method, o.classifier = classifier;
             o.classify_min_px = classify_min_px;
             auto r = std::make_unique<PyRenderer>();
             r->scene = resolved_scene(scene);
             nb::gil_scoped_release unlocked;
             r->renderer = std::make_unique<Renderer>(r->scene, o);
             return r.release();
           }),
           nb::arg("scene"), nb::arg("threads"), nb::arg("method"), nb::arg("max_error"), nb::arg("tile"),
           nb::arg("isa"), nb::arg("srgb"), nb::arg("brdf"), nb::arg("normals"), nb::arg("gouraud"),
           nb::arg("hidden_faces"), nb::arg("spec_threshold"), nb::arg("spec_method"), nb::arg("classifier"),
           nb::arg("classify_min_px"))
      .def("render", &render_frame);
  m.def("_methods", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const MethodDescription& d : list_methods()) out.emplace_back(d.name, d.summary);
    return out;
  });
}

}  // namespace fastshade::python
