// fastshade: command-line parsing and dispatch. Bad input of any kind ends here as one line on
// stderr and exit code 2.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "fastshade/error.h"

int main(int argc, char** argv) {
  using namespace fastshade;
  CLI::App app{"fastshade: a multicore tiled software renderer for fast Gouraud and Phong shading"};
  app.require_subcommand(1);

  RenderCommand render;
  std::string methods_help = "shading method:";
  for (const MethodDescription& m : list_methods()) methods_help += "\n  " + m.name + ": " + m.summary;
  CLI::App* r = app.add_subcommand("render", "render a scene file (or the embedded default scene)");
  r->add_option("scene", render.scene, "scene JSON (docs/scene-format.md); omitted: the default scene");
  r->add_option("-o,--output", render.output, "output image; the extension picks the format")->required();
  r->add_option("--threads", render.options.threads, "worker threads (0 = all)");
  r->add_option("--tile", render.options.tile_px, "tile size in pixels, a power of two 8..256");
  r->add_option("--method", render.options.method, methods_help);
  r->add_option("--frames", render.frames, "timed frames after one warm-up (medians reported)");
  r->add_option("--stats", render.stats_path, "write statistics as JSON");
  r->add_option("--isa", render.options.isa, "SIMD target: scalar, sse4, avx2, avx512, best");
  r->add_flag("--srgb", render.options.srgb, "encode with the sRGB curve (default: linear)");
  r->add_option("--max-error", render.options.max_error,
                "hybrid: error budget in 8-bit steps (default 1)");
  r->add_option("--gouraud", render.options.gouraud,
                "gouraud: increments, or sierpinski (large triangles split at edge midpoints)");
  r->add_option("--normals", render.options.normals,
                "phong: per-pixel normals by normalize, adaptive (eq. 6) or equal-angle (eq. 7)");
  r->add_option("--brdf", render.options.brdf,
                "specular lobe: exact, cosk:K, schlick, schlick-pow2, quadratic, quadratic-fit, "
                "poly2, poly3 (docs/KERNELS.md)");

  std::string image_a, image_b, mesh;
  bool compare_json = false, info_json = false;
  CLI::App* c = app.add_subcommand("compare", "error between two images of equal size, in 8-bit steps");
  c->add_option("a", image_a, "first image (png, exr, ...)")->required();
  c->add_option("b", image_b, "second image")->required();
  c->add_flag("--json", compare_json, "print JSON");

  CLI::App* i = app.add_subcommand("info", "counts and quirks of a mesh file");
  i->add_option("mesh", mesh, "mesh file (obj, off, ply, stl)")->required();
  i->add_flag("--json", info_json, "print JSON");

  std::string table_isa = "best";
  CLI::App* b = app.add_subcommand("brdf-table", "error and cost of every BRDF approximation");
  b->add_option("--isa", table_isa, "SIMD target: scalar, sse4, avx2, avx512, best");

  BatchCommand batch;
  CLI::App* bt = app.add_subcommand("batch", "render every mesh of files, directories or list files "
                                             "(docs/BATCH.md)");
  bt->add_option("inputs", batch.inputs, "mesh files, directories (searched recursively), list files "
                                         "(.txt, .lst, .list: one path a line)")->required();
  bt->add_option("-o,--output", batch.outdir, "output directory (created if missing)")->required();
  bt->add_option("--scene", batch.scene, "template scene: image, lights, materials, fit camera");
  bt->add_option("--size", batch.size, "image size WxH (default: the template's)");
  bt->add_option("--views", batch.views, "views per mesh, turned 360/K degrees about the vertical");
  bt->add_option("--shard", batch.shard, "render part I of N (I from 0) of the sorted meshes");
  bt->add_option("--threads", batch.options.threads, "worker threads (0 = all)");
  bt->add_option("--method", batch.options.method, "shading method (see render --help)");
  bt->add_option("--format", batch.format, "image format: png, exr or tif");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "fastshade: %s (see --help)\n", e.what());
    return 2;
  }
  try {
    if (*r) return run_render(render);
    if (*c) return run_compare(image_a, image_b, compare_json);
    if (*i) return run_info(mesh, info_json);
    if (*b) return run_brdf_table(table_isa);
    if (*bt) return run_batch(batch);
  } catch (const InputError& e) {
    std::fprintf(stderr, "fastshade: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fastshade: internal error: %s\n", e.what());
    return 1;
  }
  return 2;
}
