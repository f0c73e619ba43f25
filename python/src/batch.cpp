// fastshade.batch's engine-neutral steps (python/fastshade/_batch.py): plan, render one mesh's
// views, record. Specs and jobs cross as dicts of plain values, which Ray pickles to its
// workers; the rendering is the library's (include/fastshade/batch.h), the same as the
// command line's.
#include <string>
#include <utility>
#include <vector>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bindings.h"
#include "fastshade/batch.h"
#include "fastshade/error.h"

namespace nb = nanobind;

namespace fastshade::python {

namespace {

BatchSpec spec_of(const nb::dict& d) {
  BatchSpec s;
  s.inputs = nb::cast<std::vector<std::string>>(d["inputs"]);
  s.outdir = nb::cast<std::string>(d["outdir"]);
  s.scene = nb::cast<std::string>(d["scene"]);
  s.width = nb::cast<int>(d["width"]);
  s.height = nb::cast<int>(d["height"]);
  s.views = nb::cast<int>(d["views"]);
  s.shard_index = nb::cast<int>(d["shard_index"]);
  s.shard_count = nb::cast<int>(d["shard_count"]);
  s.format = nb::cast<std::string>(d["format"]);
  s.aovs = AovSet{nb::cast<bool>(d["depth"]), nb::cast<bool>(d["normal"]), nb::cast<bool>(d["triangle_id"]),
                  nb::cast<bool>(d["object_id"])};
  s.options = render_options(nb::cast<nb::dict>(d["options"]));
  return s;
}

nb::dict dict_of(const MeshJob& job) {
  nb::dict mesh;
  mesh["path"] = job.mesh.path.string();
  mesh["key"] = job.mesh.key;
  mesh["name"] = job.mesh.name;
  mesh["file_bytes"] = job.mesh.file_bytes;
  nb::list images;
  for (const BatchImage& i : job.images) {
    nb::dict image;
    image["view"] = i.view;
    image["angle_deg"] = i.angle_deg;
    image["output"] = i.output;
    image["aov_output"] = i.aov_output;
    image["fingerprint"] = i.fingerprint;
    images.append(image);
  }
  nb::dict d;
  d["mesh"] = mesh;
  d["images"] = images;
  return d;
}

MeshJob job_of(const nb::dict& d) {
  MeshJob job;
  const nb::dict mesh = nb::cast<nb::dict>(d["mesh"]);
  job.mesh.path = nb::cast<std::string>(mesh["path"]);
  job.mesh.key = nb::cast<std::string>(mesh["key"]);
  job.mesh.name = nb::cast<std::string>(mesh["name"]);
  job.mesh.file_bytes = nb::cast<std::uintmax_t>(mesh["file_bytes"]);
  for (nb::handle h : nb::cast<nb::list>(d["images"])) {
    const nb::dict i = nb::cast<nb::dict>(h);
    job.images.push_back({nb::cast<int>(i["view"]), nb::cast<double>(i["angle_deg"]), nb::cast<std::string>(i["output"]),
                          nb::cast<std::string>(i["aov_output"]), nb::cast<std::string>(i["fingerprint"])});
  }
  return job;
}

// The library checks a spec as the command line's flags ("--views: expected 1 to 360, got 0"):
// from Python the message names the keyword ("views: ..."), with the library's limits.
[[noreturn]] void rethrow_with_keywords(const InputError& e) {
  const std::string message = e.what();
  for (const auto& [flag, keyword] : {std::pair{"--views: ", "views"}, std::pair{"--size: ", "size"},
                                      std::pair{"--format: ", "format"}, std::pair{"--shard: ", "shard"}})
    if (message.starts_with(flag)) throw InputError(keyword, message.substr(std::string(flag).size()));
  throw e;
}

}  // namespace

void bind_batch(nb::module_& m) {
  m.def("_batch_plan", [](const nb::dict& spec) {
    const BatchSpec s = spec_of(spec);
    BatchPlan plan;
    try {
      nb::gil_scoped_release unlocked;
      plan = plan_batch(s);
    } catch (const InputError& e) {
      rethrow_with_keywords(e);
    }
    nb::list jobs;
    for (const MeshJob& job : plan.jobs) jobs.append(dict_of(job));
    return nb::make_tuple(jobs, plan.skipped);
  });
  m.def("_batch_render_mesh", [](const nb::dict& spec, const nb::dict& job) {
    const BatchSpec s = spec_of(spec);
    const MeshJob j = job_of(job);
    nb::gil_scoped_release unlocked;
    return render_mesh_job(s, j);
  });
  m.def("_batch_failed", [](const nb::dict& spec, const nb::dict& job, const std::string& error) {
    return failed_job_lines(spec_of(spec), job_of(job), error);
  });
  m.def("_batch_record", [](const std::string& outdir, const std::vector<std::string>& lines) {
    nb::gil_scoped_release unlocked;
    append_batch_results(outdir, lines);
  });
}

}  // namespace fastshade::python
