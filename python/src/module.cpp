// fastshade._fastshade: the C++ library's public API for Python (python/fastshade re-exports it).
#include "bindings.h"

NB_MODULE(_fastshade, m) {
  m.doc() = "fastshade: a multicore tiled CPU renderer (Gouraud, Phong and the paper's fast methods)";
  fastshade::python::bind_errors(m);
  fastshade::python::bind_mesh(m);
  fastshade::python::bind_scene(m);
  fastshade::python::bind_render(m);
  fastshade::python::bind_batch(m);
}
