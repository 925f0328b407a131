// The convergence of voxel cone tracing on the closed-form AO families (eval/convergence.h):
// for each case and voxel resolution, the cone error (cone model - exact), the voxel error
// (VCT - cone model) and the total error (VCT - exact), RMS over the case's 25 points.
//
//   bench_convergence [--res 32,64,128,256] [--backend gl|vdb] [--param KEY=VALUE ...]
//                     [--cases SUBSTRING] [--markdown FILE]
//
// --markdown writes the tables as a Markdown section (docs/convergence.md is made of them).
#include "eval/convergence.h"
#include "gl/context.h"
#include "util/atomic_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>

using namespace vct;

int main(int argc, char** argv) {
    CLI::App app{"VCT convergence on closed-form AO cases"};
    std::string resList = "32,64,128,256", backend = "gl", filter, markdown;
    bool detail = false;
    std::vector<std::string> params;
    app.add_option("--res", resList, "voxel resolutions, comma-separated")->capture_default_str();
    app.add_option("--backend", backend, "gl or vdb")->capture_default_str();
    app.add_option("--param", params, "KEY=VALUE for VCT (repeatable)");
    app.add_option("--cases", filter, "only cases whose name contains this");
    app.add_option("--markdown", markdown, "write the tables as Markdown to this file");
    app.add_flag("--detail", detail, "print every point: exact, cone model, VCT at each resolution");
    CLI11_PARSE(app, argc, argv);
    std::vector<int> resolutions;
    std::stringstream ss(resList);
    for (std::string item; std::getline(ss, item, ',');) resolutions.push_back(std::stoi(item));
    ParamMap pm;
    for (const auto& p : params) pm.set(p);
    GlContext::shared();

    std::ostringstream md;
    md << "| case | cone error |";
    for (int res : resolutions) md << " voxel " << res << "^3 |";
    for (int res : resolutions) md << " total " << res << "^3 |";
    md << "\n|---|---|";
    for (size_t i = 0; i < 2 * resolutions.size(); ++i) md << "---|";
    md << "\n";
    std::printf("%-28s %8s", "case", "cone");
    for (int res : resolutions) std::printf("  vox%-5d", res);
    for (int res : resolutions) std::printf("  tot%-5d", res);
    std::printf("\n");
    for (const AoConvergenceCase& c : aoConvergenceCases()) {
        if (!filter.empty() && c.name.find(filter) == std::string::npos) continue;
        const std::vector<double> exact = exactAoAt(c), model = coneModelAoAt(c, pm);
        const double coneErr = pointError(model, exact).rms;
        std::vector<double> vox, tot;
        for (int res : resolutions) {
            const std::vector<double> v = vctAoAt(c, res, backend, pm);
            if (detail)
                for (size_t i = 0; i < v.size(); ++i)
                    std::printf("  %s res %d point %zu (%.2f, %.2f): exact %.4f model %.4f vct %.4f\n", c.name.c_str(),
                                res, i, c.points[i].x, c.points[i].z, exact[i], model[i], v[i]);
            vox.push_back(pointError(v, model).rms);
            tot.push_back(pointError(v, exact).rms);
        }
        std::printf("%-28s %8.4f", c.name.c_str(), coneErr);
        md << "| " << c.name << " | " << coneErr << " |";
        for (double e : vox) { std::printf("  %8.4f", e); md << " " << e << " |"; }
        for (double e : tot) { std::printf("  %8.4f", e); md << " " << e << " |"; }
        std::printf("\n");
        md << "\n";
        std::fflush(stdout);
    }
    if (!markdown.empty()) writeTextFileAtomic(markdown, md.str());
    return 0;
}
