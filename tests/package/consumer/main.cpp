// Renders the embedded default scene through the installed public API with typed options, one
// of them read from its spelling, and checks the image: the right size, and objects drawn over
// the background (pixels unlike the corner's).
#include <cstdio>

#include <fastshade/render.h>
#include <fastshade/scene.h>

int main() {
  const fastshade::Scene scene = fastshade::parse_scene(fastshade::default_scene_json(), "default scene", ".");
  fastshade::RenderOptions options;
  options.threads = 2;
  options.method = fastshade::ShadingMethod::Phong;
  options.brdf = fastshade::parse_option<fastshade::BrdfChoice>("cosk:3", "brdf");
  const fastshade::Image image = fastshade::render(scene, options);
  if (image.width != scene.width || image.height != scene.height ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    std::fprintf(stderr, "consumer: image of %dx%d for a %dx%d scene\n", image.width, image.height, scene.width,
                 scene.height);
    return 1;
  }
  std::size_t drawn = 0;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    drawn += image.rgb[i] != image.rgb[0] || image.rgb[i + 1] != image.rgb[1] || image.rgb[i + 2] != image.rgb[2];
  std::printf("consumer: %dx%d, %zu pixels unlike the background\n", image.width, image.height, drawn);
  return drawn > 0 ? 0 : 1;
}
