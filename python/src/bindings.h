// The Python module's pieces (python/src/*.cpp), each binding one part of the public API.
#pragma once
#include <nanobind/nanobind.h>

#include "fastshade/render.h"

namespace fastshade::python {

void bind_errors(nanobind::module_& m);
void bind_mesh(nanobind::module_& m);
void bind_scene(nanobind::module_& m);
void bind_render(nanobind::module_& m);
void bind_batch(nanobind::module_& m);

// Render options from the dict python/fastshade/__init__.py checks (every option by its Python
// name, with its type).
RenderOptions render_options(const nanobind::dict& options);

}  // namespace fastshade::python
