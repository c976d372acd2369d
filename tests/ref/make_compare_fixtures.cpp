// Writes the small images the `proxygi compare` CLI tests read (tests/ref/CMakeLists.txt):
// gray.png / gray.exr (16x16, linear 0.2), white.png (16x16), small.png (8x8), half_mask.png
// (left half white) and garbage.png (not an image).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "image/image.h"

int main(int argc, char** argv) {
  using proxygi::image::ImageF;
  if (argc != 2) return 2;
  const std::filesystem::path directory = argv[1];
  std::filesystem::create_directories(directory);
  const ImageF gray(16, 16, glm::vec4(0.2f, 0.2f, 0.2f, 1.0f));
  ImageF mask(16, 16, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 8; ++x) mask.at(x, y) = glm::vec4(1.0f);
  bool ok = proxygi::image::write_png(directory / "gray.png", gray).ok() &&
            proxygi::image::write_exr(directory / "gray.exr", gray).ok() &&
            proxygi::image::write_png(directory / "white.png", ImageF(16, 16, glm::vec4(1.0f))).ok() &&
            proxygi::image::write_png(directory / "small.png", ImageF(8, 8, glm::vec4(1.0f))).ok() &&
            proxygi::image::write_png(directory / "half_mask.png", mask).ok();
  std::ofstream(directory / "garbage.png") << "not an image";
  if (!ok) std::fprintf(stderr, "make_compare_fixtures: a write failed\n");
  return ok ? 0 : 1;
}
