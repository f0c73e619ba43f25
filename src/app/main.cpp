// fastshade: command-line parsing and dispatch. Bad input of any kind ends here as one line on
// stderr and exit code 2.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/option_flags.h"
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
  r->add_option("--tile", render.options.tile_px,
                "tile size in pixels, a power of two 8..256 (default 64), or 0: the largest of 128, 64, 32, 16 that gives each thread 32 tiles");
  add_option_flag(r, "--method", render.options.method, methods_help);
  r->add_option("--frames", render.frames, "timed frames after one warm-up (medians reported)");
  r->add_option("--stats", render.stats_path, "write statistics as JSON");
  add_option_flag(r, "--isa", render.options.isa, "SIMD target: scalar, sse4, avx2, avx512, best");
  r->add_flag("--srgb", render.options.srgb, "encode with the sRGB curve (default: linear)");
  r->add_option("--max-error", render.options.max_error,
                "error budget in 8-bit steps, 0 to 255 (default 1). Without --method (and --config): "
                "renders with the fastest configuration whose error against reference on this scene "
                "stays within it, found by a calibration pass that says what it picked (docs/TUNING.md); "
                "with --method: the budget of auto, hybrid and --normals adaptive");
  add_option_flag(r, "--gouraud", render.options.gouraud,
                "gouraud: increments, or sierpinski (large triangles split at edge midpoints)");
  add_option_flag(r, "--normals", render.options.normals,
                "phong: per-pixel normals by normalize, adaptive (eq. 6) or equal-angle (eq. 7)");
  r->add_option("--spec-threshold", render.options.spec_threshold,
                "auto: largest specular term (colour units) a triangle may leave out (default 1/510)");
  add_option_flag(r, "--spec-method", render.options.spec_method,
                "auto: kernel for triangles that may show a highlight: hybrid (default) or phong");
  add_option_flag(r, "--classifier", render.options.classifier,
                "auto: cost (the classifier where it pays on this frame and ISA, else phong; default), bound "
                "(the error-checked classifier always) or paper (highlight -> specular, rest -> Gouraud)");
  r->add_option("--classify-min-px", render.options.classify_min_px,
                "auto: blocks of triangles whose screen boxes average fewer pixels than this take the "
                "specular path unclassified, as classifying costs more than it saves there (default 80; "
                "0: classify every triangle)");
  add_option_flag(r, "--hidden-faces", render.options.hidden_faces,
                "skip (default): cull back faces their own closed mesh provably hides; draw: draw every face");
  r->add_option("--aov", render.aov,
                "also write per-pixel outputs: a comma list of depth, normal, triangle_id, object_id, or "
                "all; into OUT if it is .exr, else into OUT's stem + .aov.exr beside it (docs/PIPELINE.md)")
      ->type_name("LIST");
  r->add_flag("--explain", render.explain, "print the shading plan: paths, and what was left out");
  r->add_option("--config", "render options from a JSON file (fastshade tune writes one); flags given "
                            "here override its keys")
      ->type_name("FILE");
  add_option_flag(r, "--brdf", render.options.brdf,
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

  Isa table_isa = Isa::Best;
  CLI::App* b = app.add_subcommand("brdf-table", "error and cost of every BRDF approximation");
  add_option_flag(b, "--isa", table_isa, "SIMD target: scalar, sse4, avx2, avx512, best");

  ReportCommand report;
  CLI::App* rep = app.add_subcommand("report", "error against time of every method on every scene");
  rep->add_option("scenes", report.scenes,
                  "scene files, meshes, or directories of them; default: scenes/ and ../shared/models");
  rep->add_option("--out", report.out, "output directory: results.csv/json, summary.md, plots/, heatmaps/")
      ->capture_default_str();
  rep->add_option("--threads", report.threads, "worker threads (0 = all)")->capture_default_str();
  rep->add_option("--frames", report.frames, "timed frames per configuration after one warm-up")
      ->capture_default_str();
  add_option_list_flag(rep, "--isa", report.isas,
                       "SIMD targets, comma-separated: scalar, sse4, avx2, avx512, best (each a table)");
  rep->add_option("--models", report.models, "the shared meshes' directory, for the default set");
  rep->add_option("--config", report.configs,
                  "measure this instead of the built-in list, repeatable: --config \"hybrid --max-error 2\"")
      ->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  rep->add_option("--heat-maps", report.heat_maps, "heat maps of the worst configurations per scene")
      ->capture_default_str();
  rep->add_flag("--no-plots", report.no_plots, "no Python plots: CSV, JSON and summary only");
  rep->add_flag("--list-configs", report.list_configs, "print what would be measured, and exit");
  report.parse_render_flags = render_flags_parser(*r, render.options);

  TuneCommand tune;
  CLI::App* t = app.add_subcommand("tune", "the fastest configuration within an error budget, as a config file");
  t->add_option("scenes", tune.scenes, "scene files, meshes, or directories of them; default: scenes/");
  t->add_option("-o,--output", tune.output, "config file to write (JSON, for render --config)")->required();
  t->add_option("--max-error", tune.max_error, "budget: max error against reference on every scene, 8-bit steps")
      ->capture_default_str();
  t->add_option("--max-pct-over-1lsb", tune.max_pct_over_1lsb,
                "budget: % of covered pixels off by more than 1 LSB on every scene (100: no limit)")
      ->capture_default_str();
  t->add_option("--min-gain", tune.min_gain_pct,
                "keep render's defaults unless the fastest within budget beats them by more than this %")
      ->capture_default_str();
  t->add_option("--methods", tune.methods, "methods swept")->delimiter(',')->capture_default_str();
  t->add_option("--tiles", tune.tiles, "tile sizes swept")->delimiter(',')->capture_default_str();
  t->add_option("--thresholds", tune.thresholds,
                "auto: --spec-threshold values swept (default: 0.5, 1 and 2 x --max-error / 255)")->delimiter(',');
  t->add_option("--spec-methods", tune.spec_methods, "auto: --spec-method values swept")->delimiter(',')
      ->capture_default_str();
  t->add_option("--classifiers", tune.classifiers, "auto: --classifier values swept")->delimiter(',')
      ->capture_default_str();
  t->add_option("--classify-min-pxs", tune.classify_min_pxs, "auto: --classify-min-px values swept")
      ->delimiter(',')->capture_default_str();
  t->add_option("--threads", tune.threads, "worker threads (0 = all)")->capture_default_str();
  t->add_option("--frames", tune.frames, "timed frames per candidate and scene after one warm-up")
      ->capture_default_str();
  add_option_flag(t, "--isa", tune.isa, "SIMD target: scalar, sse4, avx2, avx512, best");
  ScalingCommand scaling;
  CLI::App* bench = app.add_subcommand("bench", "benchmarks")->require_subcommand(1);
  CLI::App* sc = bench->add_subcommand(
      "scaling", "speed-up per stage over thread counts and tile sizes, and a load-balance model");
  sc->add_option("scene", scaling.scene, "scene JSON; omitted: the default scene");
  sc->add_option("--max-threads", scaling.max_threads,
                 "most threads (default: hardware threads + 1, one oversubscribed point)");
  sc->add_option("--tiles", scaling.tiles, "tile sizes, comma-separated (default 16,32,64,128)");
  sc->add_option("--frames", scaling.frames, "timed frames per point after one warm-up (default 10)");
  add_option_flag(sc, "--method", scaling.method, "shading method (default phong)");
  sc->add_option("--out", scaling.out_dir, "directory for scaling.csv, .json, .png (default .)");
  sc->add_flag("--no-plot", scaling.no_plot, "skip scaling.png");
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
  add_option_flag(bt, "--method", batch.options.method, "shading method (see render --help)");
  bt->add_option("--format", batch.format, "image format: png, exr or tif");
  bt->add_option("--aov", batch.aov, "per-pixel outputs as render --aov: beside each image, or in it (exr)")
      ->type_name("LIST");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "fastshade: %s (see --help)\n", e.what());
    return 2;
  } catch (const InputError& e) {  // a typed flag's value (app/option_flags.h)
    std::fprintf(stderr, "fastshade: %s\n", e.what());
    return 2;
  }
  try {
    if (*r) {
      // A copy: the calibration reads its candidates through *r's parser, which rewrites `render`.
      RenderCommand cmd = render;
      cmd.options = resolve_render_options(*r, render.options);
      cmd.calibrate = calibration_requested(*r);
      cmd.parse_render_flags = report.parse_render_flags;
      return run_render(cmd);
    }
    if (*c) return run_compare(image_a, image_b, compare_json);
    if (*i) return run_info(mesh, info_json);
    if (*b) return run_brdf_table(table_isa);
    if (*rep) return run_report(report);
    if (*t) return run_tune(tune);
    if (*sc) return run_bench_scaling(scaling);
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
