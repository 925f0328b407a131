// `vct gallery DIR... -o SITE`: the static comparison site (src/gallery/gallery.h).
#pragma once

#include <CLI/CLI.hpp>

namespace vct {

// Adds the "gallery" subcommand to the app.
void registerGalleryCommand(CLI::App& app);
// Runs it when it was parsed and returns its exit code; returns -1 when it was not parsed.
int runGalleryCommand(CLI::App& app);

}  // namespace vct
