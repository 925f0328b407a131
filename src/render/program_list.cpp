#include "render/program_list.h"

#include "methods/registry.h"
#include "raster/raster_programs.h"

#include <set>

namespace vct {

std::vector<ProgramKey> rendererProgramVariants() {
    std::vector<ProgramKey> all = rasterProgramVariants();
    std::set<std::string> seen;
    for (const ProgramKey& k : all) seen.insert(k.id());
    for (const Method* m : registeredMethods())
        if (m->programs)
            for (const ProgramKey& k : m->programs())
                if (seen.insert(k.id()).second) all.push_back(k);
    return all;
}

}  // namespace vct
