#include "app/commands.h"

#include "render/params.h"
#include "render/plan.h"
#include "render/method_params.h"

#include <sstream>

namespace vct {

void registerResearchCommands(CLI::App& app) { (void)app; }

int runResearchCommand(CLI::App& app) {
    (void)app;
    return 2;
}

std::string paramsHelpText() {
    documentAllMethodParams();
    std::ostringstream out;
    out << "--param keys (KEY=VALUE):\n";
    for (const auto& [key, d] : ParamMap::documented())
        out << "  " << key << "  default " << d.defaultValue << "  range " << d.range
            << (d.doc.empty() ? "" : "  " + d.doc) << "\n";
    return out.str();
}

}  // namespace vct
