#include "app/gallery_command.h"

#include "gallery/gallery.h"

#include <iostream>
#include <unistd.h>

namespace vct {

namespace {

GallerySettings gGallery;
CLI::App* gGalleryCmd = nullptr;

}  // namespace

void registerGalleryCommand(CLI::App& app) {
    GallerySettings& s = gGallery;
    gGalleryCmd = app.add_subcommand(
        "gallery", "Make a static web site (no server, no network) from compare or sweep result directories");
    gGalleryCmd->add_option("dirs", s.inputs, "vct compare output dirs, or vct sweep dirs (their cases/*/)")
        ->required()
        ->check(CLI::ExistingDirectory);
    gGalleryCmd->add_option("-o,--output", s.outputDir, "site directory (created; open SITE/index.html)")
        ->required();
    gGalleryCmd->add_option("--title", s.title, "title of the index page")->capture_default_str();
    gGalleryCmd->add_option("--thumb-width", s.thumbnailWidth, "max thumbnail width in px (>= 16)")
        ->capture_default_str()
        ->check(CLI::Range(16, 4096));
}

int runGalleryCommand(CLI::App& app) {
    (void)app;
    if (!gGalleryCmd || !*gGalleryCmd) return -1;
    GallerySettings s = gGallery;
    if (isatty(STDERR_FILENO))
        s.progress = [](const std::string& line) { std::cerr << "vct gallery: " << line << "\n"; };
    const GallerySummary summary = writeGallery(s);
    std::cout << "wrote " << s.outputDir << "/index.html: " << summary.caseCount << " case(s), "
              << summary.pages.size() << " page(s), " << summary.imageCount << " image(s)\n";
    return 0;
}

}  // namespace vct
