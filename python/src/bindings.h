// The Python module's pieces (python/src/*.cpp), each binding one part of the public API.
#pragma once
#include <nanobind/nanobind.h>

namespace fastshade::python {

void bind_errors(nanobind::module_& m);
void bind_mesh(nanobind::module_& m);
void bind_scene(nanobind::module_& m);
void bind_render(nanobind::module_& m);

}  // namespace fastshade::python
