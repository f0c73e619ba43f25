// fastshade.Renderer: every render option by its Python name; frames rendered with the GIL
// released, so several renderers in several Python threads run at once.
#include <memory>
#include <mutex>
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

// A frame's buffers, owned by one capsule that every array it returns holds: no copies.
struct FrameBuffers {
  Image color;
  AovImages aovs;
};

// Buffers whose arrays Python has let go, kept for the renderer's next frame: a fresh 1080p
// frame's buffers are 6 MB of zero-fill and page faults for colour alone (and 50 MB with every
// AOV), which the command line's timed frames never pay (Renderer::render_frame reuses them).
// Shared with the capsules, so a frame may outlive its renderer.
struct BufferPool {
  std::mutex mutex;
  std::unique_ptr<FrameBuffers> spare;
};

// What a frame's capsule owns: its buffers, handed back to the pool when the last array goes.
struct PooledFrame {
  std::unique_ptr<FrameBuffers> buffers;
  std::shared_ptr<BufferPool> pool;
  ~PooledFrame() {
    const std::lock_guard<std::mutex> lock(pool->mutex);
    pool->spare = std::move(buffers);
  }
};

struct PyRenderer {
  Scene scene;  // the renderer's own copy: the Python scene may change afterwards
  std::unique_ptr<Renderer> renderer;
  std::shared_ptr<BufferPool> pool = std::make_shared<BufferPool>();
};

using ColorArray = nb::ndarray<nb::numpy, uint8_t, nb::shape<-1, -1, 3>>;

template <typename T, typename... Shape>
nb::object array_of(std::vector<T>& v, const nb::capsule& owner, Shape... shape) {
  if (v.empty()) return nb::none();
  return nb::cast(nb::ndarray<nb::numpy, T>(v.data(), {std::size_t(shape)...}, owner));
}

// One frame: colour (H, W, 3) uint8, the stats as JSON text, and the AOVs asked for (None for
// the others): depth (H, W) float32, normal (H, W, 3) float32, ids (H, W) int32.
nb::tuple render_frame(PyRenderer& r, bool depth, bool normal, bool triangle_id, bool object_id) {
  auto frame = std::make_unique<PooledFrame>();
  frame->pool = r.pool;
  RenderStats stats;
  {
    nb::gil_scoped_release unlocked;
    {
      const std::lock_guard<std::mutex> lock(r.pool->mutex);
      frame->buffers = std::move(r.pool->spare);
    }
    if (!frame->buffers) frame->buffers = std::make_unique<FrameBuffers>();
    r.renderer->render_frame(frame->buffers->color, AovSet{depth, normal, triangle_id, object_id}, frame->buffers->aovs);
    stats = r.renderer->last_stats();
    stats.frames = 1;
  }
  FrameBuffers* b = frame->buffers.get();
  nb::capsule owner(frame.release(), [](void* p) noexcept { delete static_cast<PooledFrame*>(p); });
  const std::size_t height = b->color.height, width = b->color.width;
  return nb::make_tuple(ColorArray(b->color.rgb.data(), {height, width, 3}, owner), stats.to_json(),
                        array_of(b->aovs.depth, owner, height, width), array_of(b->aovs.normal, owner, height, width, 3),
                        array_of(b->aovs.triangle_id, owner, height, width),
                        array_of(b->aovs.object_id, owner, height, width));
}

}  // namespace

namespace {

// A keyword's text as its typed option; a bad spelling names the keyword.
template <OptionValue T>
T option_from(const nb::dict& d, const char* key) {
  return parse_option<T>(nb::cast<std::string>(d[key]), key);
}

}  // namespace

RenderOptions render_options(const nb::dict& d) {
  RenderOptions o;
  o.threads = nb::cast<int>(d["threads"]);
  o.method = option_from<ShadingMethod>(d, "method");
  o.max_error = nb::cast<double>(d["max_error"]);
  o.tile_px = nb::cast<int>(d["tile"]);
  o.isa = option_from<Isa>(d, "isa");
  o.srgb = nb::cast<bool>(d["srgb"]);
  o.brdf = option_from<BrdfChoice>(d, "brdf");
  o.normals = option_from<PhongNormals>(d, "normals");
  o.gouraud = option_from<GouraudMode>(d, "gouraud");
  o.hidden_faces = option_from<HiddenFaces>(d, "hidden_faces");
  o.spec_threshold = nb::cast<double>(d["spec_threshold"]);
  o.spec_method = option_from<SpecMethod>(d, "spec_method");
  o.classifier = option_from<ClassifierRule>(d, "classifier");
  o.classify_min_px = nb::cast<double>(d["classify_min_px"]);
  return o;
}

void bind_render(nb::module_& m) {
  nb::class_<PyRenderer>(m, "_Renderer")
      .def(nb::new_([](const PyScene& scene, const nb::dict& options) {
             const RenderOptions o = render_options(options);
             auto r = std::make_unique<PyRenderer>();
             r->scene = resolved_scene(scene);
             nb::gil_scoped_release unlocked;
             r->renderer = std::make_unique<Renderer>(r->scene, o);
             return r.release();
           }),
           nb::arg("scene"), nb::arg("options"))
      .def("render", &render_frame, nb::arg("depth"), nb::arg("normal"), nb::arg("triangle_id"), nb::arg("object_id"));
  m.def("_methods", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const MethodDescription& d : list_methods()) out.emplace_back(d.name, d.summary);
    return out;
  });
}

}  // namespace fastshade::python
