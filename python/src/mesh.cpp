// fastshade.Mesh: a triangle mesh from numpy arrays or a file, its arrays back as numpy.
#include <algorithm>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <nanobind/ndarray.h>
#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bindings.h"
#include "fastshade/error.h"
#include "fastshade/mesh.h"

namespace nb = nanobind;
using namespace nb::literals;

namespace fastshade::python {

namespace {


// A numpy copy of n rows of 3 (the mesh stays the owner of its own arrays).
template <typename T>
nb::ndarray<nb::numpy, T, nb::shape<-1, 3>> rows_copy(const T* data, std::size_t rows) {
  T* copy = new T[rows * 3];
  std::copy(data, data + rows * 3, copy);
  nb::capsule owner(copy, [](void* p) noexcept { delete[] static_cast<T*>(p); });
  return nb::ndarray<nb::numpy, T, nb::shape<-1, 3>>(copy, {rows, 3}, owner);
}

// `value` as a C-contiguous (N, 3) array of T: anything numpy.asarray takes, of a numeric kind
// in `kinds` ("f", "iu"), or InputError naming `what`.
template <typename T>
nb::ndarray<const T, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu> rows3(nb::handle value, const char* what,
                                                                              const std::string& kinds) {
  const nb::module_ np = nb::module_::import_("numpy");
  nb::object array;
  try {
    array = np.attr("asarray")(value);
  } catch (const nb::python_error& e) {
    throw InputError(what, std::string("not an array (") + e.what() + ")");
  }
  const auto shape = nb::cast<std::vector<std::size_t>>(array.attr("shape"));
  if (shape.size() != 2 || shape[1] != 3) {
    std::string got = "(";
    for (std::size_t i = 0; i < shape.size(); ++i) got += (i ? ", " : "") + std::to_string(shape[i]);
    throw InputError(what, "expected shape (N, 3), got " + got + (shape.size() == 1 ? ",)" : ")"));
  }
  const std::string kind = nb::cast<std::string>(array.attr("dtype").attr("kind"));
  if (kinds.find(kind) == std::string::npos)
    throw InputError(what, "expected a " + std::string(std::is_same_v<T, float> ? "numeric" : "integer") + " array, got dtype " +
                               nb::cast<std::string>(array.attr("dtype").attr("name")));
  if (std::is_same_v<T, uint32_t> && shape[0] > 0) {  // indices: checked before the cast can wrap them
    const long long lo = nb::cast<long long>(nb::int_(array.attr("min")()));
    const long long hi = nb::cast<long long>(nb::int_(array.attr("max")()));
    if (lo < 0 || hi > 0xFFFFFFFELL)
      throw InputError(what, "index " + std::to_string(lo < 0 ? lo : hi) + " out of range");
  }
  nb::object contiguous = np.attr("ascontiguousarray")(array, "dtype"_a = std::is_same_v<T, float> ? "float32" : "uint32");
  return nb::cast<nb::ndarray<const T, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>>(contiguous);
}

Mesh mesh_from_arrays(nb::handle vertices_in, nb::handle faces_in, nb::handle normals_in) {
  const auto vertices = rows3<float>(vertices_in, "vertices", "fiu");
  const auto faces = rows3<uint32_t>(faces_in, "faces", "iu");
  Mesh mesh;
  mesh.source = "array";
  const float* v = vertices.data();
  for (std::size_t i = 0; i < vertices.shape(0); ++i) mesh.positions.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
  const uint32_t* f = faces.data();
  for (std::size_t i = 0; i < faces.shape(0); ++i) mesh.triangles.push_back({f[3 * i], f[3 * i + 1], f[3 * i + 2]});
  if (!normals_in.is_none()) {
    const auto normals = rows3<float>(normals_in, "normals", "fiu");
    const float* n = normals.data();
    for (std::size_t i = 0; i < normals.shape(0); ++i) mesh.normals.push_back({n[3 * i], n[3 * i + 1], n[3 * i + 2]});
  }
  check_mesh(mesh);  // before recomputing: normals need indices in range
  if (mesh.normals.empty()) recompute_normals(mesh);
  return mesh;
}

}  // namespace

void bind_mesh(nb::module_& m) {
  nb::class_<Mesh>(m, "Mesh", "A triangle mesh: vertices (N, 3) float32, faces (M, 3) uint32, normals (N, 3).")
      .def(nb::new_([](nb::handle vertices, nb::handle faces, nb::handle normals) {
             return std::make_shared<Mesh>(mesh_from_arrays(vertices, faces, normals));
           }),
           nb::arg("vertices"), nb::arg("faces"), nb::arg("normals").none() = nb::none(),
           "From (N, 3) float vertices, (M, 3) integer faces (0-based, counter-clockwise seen from the front) "
           "and optional (N, 3) vertex normals (area-weighted ones are computed if None).")
      .def_prop_ro(
          "vertices", [](const Mesh& mesh) { return rows_copy(reinterpret_cast<const float*>(mesh.positions.data()), mesh.positions.size()); },
          nb::rv_policy::move, "Object-space vertex positions, (N, 3) float32 (a copy).")
      .def_prop_ro(
          "faces", [](const Mesh& mesh) { return rows_copy(reinterpret_cast<const uint32_t*>(mesh.triangles.data()), mesh.triangles.size()); },
          nb::rv_policy::move, "Triangles as vertex indices, (M, 3) uint32 (a copy).")
      .def_prop_ro(
          "normals", [](const Mesh& mesh) { return rows_copy(reinterpret_cast<const float*>(mesh.normals.data()), mesh.normals.size()); },
          nb::rv_policy::move, "Unit vertex normals, (N, 3) float32 (a copy).")
      .def_prop_ro("source", [](const Mesh& mesh) { return mesh.source; }, "The file or 'array' it came from.")
      .def("__repr__", [](const Mesh& mesh) {
        return "<fastshade.Mesh " + mesh.source + ": " + std::to_string(mesh.positions.size()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " triangles>";
      });
  m.def(
      "load_mesh",
      [](const std::filesystem::path& path, const std::string& normals, bool weld) {
        MeshLoadOptions options;
        if (normals == "file") options.normals = NormalsMode::File;
        else if (normals == "recompute") options.normals = NormalsMode::Recompute;
        else if (normals != "auto") throw InputError("normals", "expected 'auto', 'file' or 'recompute', got '" + normals + "'");
        options.weld = weld;
        std::shared_ptr<Mesh> mesh;
        {
          nb::gil_scoped_release unlocked;
          mesh = std::make_shared<Mesh>(load_mesh(path, options));
        }
        return mesh;
      },
      nb::arg("path"), nb::arg("normals") = "auto", nb::arg("weld") = false,
      "Reads OBJ, OFF, PLY or STL as the command line does (normals: 'auto', 'file' or 'recompute').");
}

}  // namespace fastshade::python
