#include "profile_command.h"

#include <iostream>

#include "model/core_parameters.h"

namespace rastersim {

CLI::App* add_profile_command(CLI::App& app, ProfileCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "profile", "print the resolved hardware profile as JSON, or the rastersim_core parameters it needs");
  cmd->add_flag("--core-parameters", options.core_parameters,
                "print rastersim_core's build parameters for the profile, NAME=value a line");
  cmd->add_flag("--largest", options.largest,
                "with --core-parameters: the largest latencies and FIFO the run-time keys allow (the cores "
                "the co-simulation builds) instead of the profile's own");
  cmd->add_flag("--keys-markdown", options.keys_markdown, "print the key table of docs/formats.md");
  add_profile_options(*cmd, options.profile);
  return cmd;
}

int run_profile(const ProfileCommandOptions& options) {
  const Profile profile = resolve_profile(options.profile);
  if (options.keys_markdown) {
    std::cout << profile_table_markdown();
  } else if (options.core_parameters) {
    for (const CoreParameter& c : core_parameters(profile, options.largest ? CoreBounds::Largest : CoreBounds::Profile))
      std::cout << c.name << "=" << c.value << "\n";
  } else {
    std::cout << profile_to_json(profile) << "\n";
  }
  return 0;
}

}  // namespace rastersim
