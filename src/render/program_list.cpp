#include "render/program_list.h"

#include "ao/ao_pass.h"
#include "cone/cone_programs.h"
#include "raster/raster_programs.h"
#include "voxelize/voxel_programs.h"

namespace vct {

std::vector<ProgramKey> rendererProgramVariants() {
    std::vector<ProgramKey> all;
    for (auto list : {rasterProgramVariants(), screenSpaceAoProgramVariants(), voxelProgramVariants(),
                      coneProgramVariants()})
        all.insert(all.end(), list.begin(), list.end());
    return all;
}

}  // namespace vct
