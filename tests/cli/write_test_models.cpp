// Writes the mannequin three ways with the glTF writer, for the CLI checks of own characters
// (own_character_check.cmake): DIR/named.glb (as built), DIR/unnamed.glb (every node name empty)
// and DIR/duplicate.glb (left_/right_ prefixes dropped, so both sides share names; the rest "bone");
// and DIR/defects.glb with DIR/defects.expected for `info --validate` (write_defects.h).
#include <cstdio>
#include <filesystem>
#include <string>

#include "anim/gltf_writer.h"
#include "anim/mannequin.h"
#include "tests/cli/write_defects.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_test_models DIR\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const proxygi::anim::Character named = proxygi::anim::build_mannequin();
  proxygi::anim::Character unnamed = named, duplicate = named;
  for (auto& node : unnamed.nodes) node.name.clear();
  for (auto& node : duplicate.nodes) {
    std::string name = "bone";
    for (const char* side : {"left_", "right_"})
      if (node.name.rfind(side, 0) == 0) name = node.name.substr(std::string(side).size());
    node.name = name;
  }
  for (const auto& [file, character] : {std::pair{"named.glb", &named}, {"unnamed.glb", &unnamed}, {"duplicate.glb", &duplicate}})
    if (auto written = proxygi::anim::write_glb(*character, dir / file); !written) {
      std::fprintf(stderr, "%s\n", written.message().c_str());
      return 1;
    }
  if (const std::string failed = write_defects(dir); !failed.empty()) {
    std::fprintf(stderr, "defects.glb: %s\n", failed.c_str());
    return 1;
  }
  return 0;
}
