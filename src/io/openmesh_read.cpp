// The OpenMesh side of loading: a checking importer, silenced reads that may run in parallel
// (one reader object each), and the checks on what OpenMesh built.
#include "io/openmesh_read.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/reader/OBJReader.hh>
#include <OpenMesh/Core/IO/reader/OFFReader.hh>
#include <OpenMesh/Core/IO/reader/PLYReader.hh>
#include <OpenMesh/Core/IO/reader/STLReader.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <new>
#include <optional>
#include <string>

#include "io/mesh_checks.h"

namespace fastshade::io {

namespace {

using OpenMesh::FaceHandle;
using OpenMesh::VertexHandle;

// Sees every face a reader hands over. OpenMesh's own ImporterT drops a face with an invalid or
// repeated index without a word; here bad indices and short faces are recorded as errors.
//
// Polygons: OpenMesh's TriMesh adds a polygon as a fan and reports only the last triangle's
// success; when that fails, ImporterT re-adds the whole polygon on fresh copies of its vertices
// (so triangles that did go in are added twice), and a failed middle triangle is lost. Here
// the fan triangles are added one by one: if all fail, the polygon is re-added on copies as
// OpenMesh does (so the counts match OpenMesh's on suzanne.obj), otherwise only the failed
// triangles are re-added on copies of their 3 vertices. Triangles go through ImporterT as is.
class CheckingImporter final : public OpenMesh::IO::ImporterT<OmMesh> {
 public:
  CheckingImporter(OmMesh& mesh, bool check_range, std::vector<uint8_t>* file_normal)
      : ImporterT(mesh), mesh_(mesh), check_range_(check_range), file_normal_(file_normal) {}

  using ImporterT::add_face;
  using ImporterT::add_vertex;
  using ImporterT::set_normal;

  VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    ++vertices_read;
    return ImporterT::add_vertex(p);
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    ++vertices_read;
    return ImporterT::add_vertex(p);
  }
  VertexHandle add_vertex() override {
    ++vertices_read;
    return ImporterT::add_vertex();
  }

  // The OFF and PLY readers reserve 3 * nV edges. A closed triangle mesh has about 1.5 * nF
  // = 3 * nV edges, so this is usually a few edges short and the edge array (tens of MB) is
  // reallocated and copied at the very end: 0.55 s instead of 0.27 s for the 871k dragon.
  // 3 * nF bounds the edges of any triangle mesh; unused reserved memory is never touched.
  void reserve(unsigned int nV, unsigned int nE, unsigned int nF) override {
    mesh_.reserve(nV, std::max<std::size_t>(nE, 3 * std::size_t{nF}), nF);
  }

  void set_normal(VertexHandle vh, const OpenMesh::Vec3f& n) override {
    if (!vh.is_valid() || static_cast<std::size_t>(vh.idx()) >= mesh_.n_vertices()) return;
    mark_normal(vh);
    ImporterT::set_normal(vh, n);
  }
  void set_normal(VertexHandle vh, const OpenMesh::Vec3d& n) override {
    if (!vh.is_valid() || static_cast<std::size_t>(vh.idx()) >= mesh_.n_vertices()) return;
    mark_normal(vh);
    ImporterT::set_normal(vh, n);
  }

  FaceHandle add_face(const VHandles& idx) override {
    const std::size_t ordinal = faces_read++;
    if (error) return FaceHandle();
    if (idx.size() < 3) {
      error = "face " + std::to_string(ordinal) + " (counting from 0) has " +
              std::to_string(idx.size()) + " vertices; a face needs at least 3";
      return FaceHandle();
    }
    // OFF, PLY and OBJ list every vertex before the faces, so a file index is valid if below
    // the number read; vertices OpenMesh appended as copies are not addressable by the file.
    // The STL reader makes its indices itself, interleaved with such copies.
    const std::size_t limit = check_range_ ? vertices_read : mesh_.n_vertices();
    for (const VertexHandle vh : idx) {
      if (vh.idx() < 0 || static_cast<std::size_t>(vh.idx()) >= limit) {
        error = "face " + std::to_string(ordinal) + " (counting from 0) references vertex " +
                std::to_string(vh.idx()) + " but the file has " + std::to_string(limit) +
                " vertices";
        return FaceHandle();
      }
    }
    for (std::size_t i = 0; i < idx.size(); ++i) {
      for (std::size_t j = i + 1; j < idx.size(); ++j) {
        if (idx[i] == idx[j]) {
          ++dropped_degenerate;  // zero area; a halfedge mesh cannot hold it
          return FaceHandle();
        }
      }
    }
    expected_triangles += idx.size() - 2;
    if (idx.size() == 3) {
      const std::size_t before = mesh_.n_vertices();
      const FaceHandle fh = ImporterT::add_face(idx);
      if (!fh.is_valid()) {
        error = "OpenMesh could not add face " + std::to_string(ordinal);
      } else if (mesh_.n_vertices() > before) {
        copied_vertices(idx, before);  // ImporterT's non-manifold fallback
      }
      return fh;
    }

    FaceHandle last;
    std::vector<std::size_t> failed;
    VHandles tri(3);
    for (std::size_t i = 1; i + 1 < idx.size(); ++i) {
      tri = {idx[0], idx[i], idx[i + 1]};
      const FaceHandle fh = mesh_.add_face(tri);
      if (fh.is_valid()) {
        last = fh;
      } else {
        failed.push_back(i);
      }
    }
    if (failed.empty()) return last;
    if (failed.size() == idx.size() - 2) {
      const VHandles copy = copy_vertices(idx);
      for (std::size_t i = 1; i + 1 < copy.size(); ++i) {
        last = add_on_copies({copy[0], copy[i], copy[i + 1]}, ordinal);
      }
      return last;
    }
    for (const std::size_t i : failed) {
      last = add_on_copies(copy_vertices({idx[0], idx[i], idx[i + 1]}), ordinal);
    }
    return last;
  }

  std::size_t vertices_read = 0;
  std::size_t faces_read = 0;  // add_face calls: one per face record in OFF and PLY
  std::size_t expected_triangles = 0;
  std::size_t dropped_degenerate = 0;
  std::size_t duplicated = 0;
  std::optional<std::string> error;

 private:
  void mark_normal(VertexHandle vh) {
    if (!file_normal_) return;
    if (file_normal_->size() < mesh_.n_vertices()) file_normal_->resize(mesh_.n_vertices(), 0);
    (*file_normal_)[static_cast<std::size_t>(vh.idx())] = 1;
  }

  bool has_file_normal(VertexHandle vh) const {
    return file_normal_ && static_cast<std::size_t>(vh.idx()) < file_normal_->size() &&
           (*file_normal_)[static_cast<std::size_t>(vh.idx())];
  }

  // The vertices ImporterT appended from index `first` on are copies of `originals`, in order.
  void copied_vertices(const VHandles& originals, std::size_t first) {
    const std::size_t added = mesh_.n_vertices() - first;
    duplicated += added;
    for (std::size_t j = 0; j < added && j < originals.size(); ++j) {
      const VertexHandle copy(static_cast<int>(first + j));
      if (has_file_normal(originals[j])) {
        mark_normal(copy);
        mesh_.set_normal(copy, mesh_.normal(originals[j]));
      }
    }
  }

  VHandles copy_vertices(const VHandles& originals) {
    VHandles copy;
    const std::size_t first = mesh_.n_vertices();
    for (const VertexHandle vh : originals) {
      const OmMesh::Point p = mesh_.point(vh);  // by value: add_vertex may reallocate
      copy.push_back(mesh_.add_vertex(p));
    }
    copied_vertices(originals, first);
    return copy;
  }

  FaceHandle add_on_copies(const VHandles& tri, std::size_t ordinal) {
    const FaceHandle fh = mesh_.add_face(tri);
    if (!fh.is_valid()) error = "OpenMesh could not add face " + std::to_string(ordinal);
    return fh;
  }

  OmMesh& mesh_;
  bool check_range_;
  std::vector<uint8_t>* file_normal_;
};

// OpenMesh has one reader object per format (a global that IOManager().read picks by
// extension), and a reader keeps the state of the read in progress in its members. Concurrent
// reads therefore each get a reader object of their own: a pool per format, grown on demand
// (so it holds at most as many readers as reads ever ran at once) and never freed, because a
// reader's constructor registers it with OpenMesh's IOManager, which keeps the pointer. Reads
// never go through IOManager().read, so no one iterates its reader list while it grows.
//
// OpenMesh's log streams are globals too: they are silenced while any read runs and restored
// when the last one ends; readers only query them while silenced, so no one toggles them
// during a read.
class ReaderPool {
 public:
  // A reader for `format`, for one read; gives it back on destruction.
  class Lease {
   public:
    Lease(ReaderPool& pool, MeshFormat format) : pool_(pool), format_(format) {
      reader_ = pool_.acquire(format);
    }
    ~Lease() { pool_.release(format_, reader_); }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    OpenMesh::IO::BaseReader& reader() const { return *reader_; }

   private:
    ReaderPool& pool_;
    MeshFormat format_;
    OpenMesh::IO::BaseReader* reader_;
  };

  // Never destroyed either: a static destructor would drop the pool's pointers at exit (so leak
  // checkers report every reader) while a detached thread might still be reading.
  static ReaderPool& instance() {
    static ReaderPool& pool = *new ReaderPool;
    return pool;
  }

 private:
  static constexpr std::size_t kFormats = 4;  // MeshFormat's values

  OpenMesh::IO::BaseReader* acquire(MeshFormat format) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (active_reads_++ == 0) quiet_streams();
    std::vector<OpenMesh::IO::BaseReader*>& idle = idle_[static_cast<std::size_t>(format)];
    if (!idle.empty()) {
      OpenMesh::IO::BaseReader* reader = idle.back();
      idle.pop_back();
      return reader;
    }
    switch (format) {  // leaked on purpose, see above
      case MeshFormat::Obj: return new OpenMesh::IO::_OBJReader_();
      case MeshFormat::Off: return new OpenMesh::IO::_OFFReader_();
      case MeshFormat::Ply: return new OpenMesh::IO::_PLYReader_();
      case MeshFormat::Stl: return new OpenMesh::IO::_STLReader_();
    }
    return nullptr;  // unreachable: every MeshFormat is handled
  }

  void release(MeshFormat format, OpenMesh::IO::BaseReader* reader) {
    const std::lock_guard<std::mutex> lock(mutex_);
    idle_[static_cast<std::size_t>(format)].push_back(reader);
    if (--active_reads_ == 0) restore_streams();
  }

  void quiet_streams() {
    err_ = omerr().is_enabled();
    log_ = omlog().is_enabled();
    out_ = omout().is_enabled();
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  void restore_streams() const {
    if (err_) omerr().enable();
    if (log_) omlog().enable();
    if (out_) omout().enable();
  }

  std::mutex mutex_;
  std::array<std::vector<OpenMesh::IO::BaseReader*>, kFormats> idle_;
  int active_reads_ = 0;
  bool err_ = false, log_ = false, out_ = false;  // the streams' state before the reads
};

std::string count_mismatch(const char* what, uint64_t declared, std::size_t read) {
  return std::string("the header declares ") + std::to_string(declared) + " " + what +
         " but OpenMesh read " + std::to_string(read) + " (truncated or malformed file?)";
}

}  // namespace

void read_checked(const std::filesystem::path& path, bool want_normals, OmRead& out) {
  const Precheck pre = precheck_mesh_file(path);

  OmMesh& mesh = out.mesh;
  mesh.clear();
  out.file_normal.clear();
  if (want_normals) mesh.request_vertex_normals();
  CheckingImporter importer(mesh, pre.format != MeshFormat::Stl,
                            want_normals ? &out.file_normal : nullptr);
  OpenMesh::IO::Options options;
  if (want_normals) options += OpenMesh::IO::Options::VertexNormal;

  bool ok = false;
  {
    const ReaderPool::Lease lease(ReaderPool::instance(), pre.format);
    OpenMesh::IO::BaseReader& reader = lease.reader();
    try {
      // What IOManager().read does once it has found the reader for the extension.
      if (reader.can_u_read(path.string())) {
        importer.prepare();
        ok = reader.read(path.string(), importer, options);
        importer.finish();
      }
    } catch (const std::bad_alloc&) {
      fail(path, "OpenMesh ran out of memory reading it (does a count in it lie?)");
    } catch (const std::exception& e) {
      fail(path, std::string("OpenMesh failed: ") + e.what());
    } catch (...) {
      fail(path, "OpenMesh failed with an unknown exception");
    }
  }
  if (!ok) fail(path, std::string("OpenMesh could not read it as ") + format_name(pre.format));
  if (importer.error) fail(path, *importer.error);

  if (pre.declared_vertices && importer.vertices_read != *pre.declared_vertices) {
    fail(path, count_mismatch("vertices", *pre.declared_vertices, importer.vertices_read));
  }
  if (pre.declared_faces && importer.faces_read != *pre.declared_faces &&
      importer.faces_read != 0) {
    fail(path, count_mismatch("faces", *pre.declared_faces, importer.faces_read));
  }
  if (pre.obj) {
    if (importer.vertices_read != pre.obj->positions) {
      fail(path, "the file has " + std::to_string(pre.obj->positions) +
                     " vertices but OpenMesh read " + std::to_string(importer.vertices_read));
    }
    if (mesh.n_faces() != pre.obj->triangles) {
      fail(path, "the file's faces make " + std::to_string(pre.obj->triangles) +
                     " triangles but OpenMesh built " + std::to_string(mesh.n_faces()));
    }
  }
  if (mesh.n_faces() != importer.expected_triangles) {
    fail(path, "OpenMesh built " + std::to_string(mesh.n_faces()) + " triangles of the " +
                   std::to_string(importer.expected_triangles) + " the faces make");
  }
  if (mesh.n_faces() == 0) {
    fail(path, "no faces (" + std::to_string(mesh.n_vertices()) + " vertices" +
                   (mesh.n_vertices() > 0 ? ": a point cloud?)" : ")"));
  }

  const std::size_t nv = mesh.n_vertices();
  const OmMesh::Point* points = mesh.points();
  for (std::size_t i = 0; i < nv; ++i) {
    const auto& p = points[i];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
      fail(path, "vertex " + std::to_string(i) + " (counting from 0) has a non-finite coordinate (" +
                     std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                     std::to_string(p[2]) + ")");
    }
  }

  out.duplicated_vertices = importer.duplicated;
  out.dropped_degenerate_faces = importer.dropped_degenerate;
  out.has_file_normals = false;
  if (want_normals && !out.file_normal.empty()) {
    out.file_normal.resize(nv, 0);
    bool all = true;
    for (const auto fh : mesh.faces()) {
      for (const auto vh : mesh.fv_range(fh)) {
        all = all && out.file_normal[static_cast<std::size_t>(vh.idx())];
      }
      if (!all) break;
    }
    out.has_file_normals = all;
  }
}

}  // namespace fastshade::io
