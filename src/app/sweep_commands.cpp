#include "app/sweep_commands.h"

#include "eval/sweep.h"
#include "gl/context.h"

#include <iostream>
#include <unistd.h>

namespace vct {

namespace {

struct SweepOptions {
    std::string specPath;
    std::string outDir;
    std::string shard = "0/1";
    bool noImages = false;
    bool dryRun = false;
    std::string glDevice = "auto";
};

struct MergeOptions {
    std::vector<std::string> dirs;
    std::string outDir;
};

SweepOptions gSweep;
MergeOptions gMerge;
CLI::App* gSweepCmd = nullptr;
CLI::App* gMergeCmd = nullptr;

int runSweepCli(const SweepOptions& o) {
    SweepSpec spec = loadSweepSpec(o.specPath);
    SweepRunOptions run;
    run.outDir = o.outDir;
    run.shard = parseShard(o.shard);
    run.writeImages = !o.noImages;
    const auto cases = enumerateSweepCases(spec);
    const auto mine = casesOfShard(cases, run.shard);
    std::cout << "vct sweep: " << o.specPath << ": " << cases.size() << " cases, shard " << o.shard << " runs "
              << mine.size() << "\n";
    if (o.dryRun) {
        for (const SweepCase& c : mine) {
            const SweepScene& s = spec.scenes[c.scene];
            std::cout << c.index << " " << c.id << " " << s.path << " (" << s.variants.size() << " variants";
            if (c.camera.isPath()) std::cout << ", path " << c.camera.path.entry << ", " << c.camera.path.frames << " frames";
            std::cout << ")\n";
        }
        return 0;
    }
    run.log = [](const std::string& line) { std::cout << "vct sweep: " << line << std::endl; };
    if (isatty(STDERR_FILENO)) run.progress = [](const std::string& line) { std::cerr << "  " << line << "\n"; };
    GlContext::shared(parseGlDevice(o.glDevice));
    SweepSummary s = runSweep(spec, run);
    std::cout << "vct sweep: ran " << s.ran << ", skipped " << s.skippedDone << " done already and "
              << s.skippedMissing << " with absent scenes; results in " << o.outDir << "/cases\n";
    return 0;
}

int runMergeCli(const MergeOptions& o) {
    nlohmann::json merged = mergeSweepResults(o.dirs, [](const std::string& line) {
        std::cerr << "vct merge: " << line << "\n";
    });
    writeMerged(merged, o.outDir);
    std::cout << "vct merge: " << merged["cases"].size() << " cases, " << merged["records"].size() << " records -> "
              << o.outDir << "/results.json and results.csv\n";
    return 0;
}

}  // namespace

void registerSweepCommands(CLI::App& app) {
    SweepOptions& s = gSweep;
    gSweepCmd = app.add_subcommand("sweep", "Run a grid of comparisons (scenes x cameras x radii x method parameters)");
    gSweepCmd->add_option("spec", s.specPath, "sweep spec (JSON; see docs/sweeps.md)")->required();
    gSweepCmd->add_option("-o,--output", s.outDir, "output directory (cases/<case-id>/ per case; resumable)")
        ->required();
    gSweepCmd->add_option("--shard", s.shard, "run only the cases with index % N == I (0-based I/N)")
        ->capture_default_str();
    gSweepCmd->add_flag("--no-images", s.noImages, "write results only, no per-variant images");
    gSweepCmd->add_flag("--dry-run", s.dryRun, "list this shard's cases and exit");
    gSweepCmd->add_option("--gl-device", s.glDevice, "auto, surfaceless or device")->capture_default_str();

    MergeOptions& m = gMerge;
    gMergeCmd = app.add_subcommand("merge", "Combine sweep (or shard, or compare) directories into one table");
    gMergeCmd->add_option("dirs", m.dirs, "sweep output directories (or `vct compare` directories)")->required();
    gMergeCmd->add_option("-o,--output", m.outDir, "output directory (results.json, results.csv)")->required();
}

int runSweepCommand(CLI::App& app) {
    (void)app;
    if (gSweepCmd && *gSweepCmd) return runSweepCli(gSweep);
    if (gMergeCmd && *gMergeCmd) return runMergeCli(gMerge);
    return -1;
}

}  // namespace vct
