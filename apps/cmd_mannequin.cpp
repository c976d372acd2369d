// proxygi mannequin -o FILE.glb|FILE.gltf: writes the built-in procedural mannequin
// (anim/mannequin.h), the file committed as assets/mannequin.glb.
#include <cstdio>
#include <memory>
#include <string>

#include "anim/gltf_writer.h"
#include "anim/mannequin.h"
#include "apps/commands.h"

namespace proxygi::app {

void add_mannequin_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("mannequin", "Write the built-in procedural mannequin (walk, run, wave) as glTF");
  auto output = std::make_shared<std::string>();
  command->add_option("-o,--output", *output, "Output file: .glb or .gltf")->required();
  add_quiet_flag(*command);
  command->callback([&runner, output] {
    runner = [output] {
      const std::string extension = std::filesystem::path(*output).extension().string();
      if (extension != ".glb" && extension != ".gltf") {
        return fail_bad_input("mannequin: output '" + *output + "' must end in .glb or .gltf");
      }
      const anim::Character mannequin = anim::build_mannequin();
      if (Status status = anim::write_character(mannequin, *output); !status) {
        return fail_runtime("mannequin: " + status.message());
      }
      std::printf("wrote %s\n", output->c_str());
      return kExitOk;
    };
  });
}

}  // namespace proxygi::app
