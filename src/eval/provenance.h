// Where a number came from, so any record in a table can be reproduced: the commit the binary
// was built from, a hash of the scene file, the seed, and every parameter of the method with
// its default (what `--help-params` lists, with the record's own values over it).
#pragma once

#include "core/method.h"
#include "core/params.h"

#include <nlohmann/json.hpp>

#include <string>

namespace vct {

// HEAD of the checkout the binary was built from ("-dirty" when tracked files differed from
// it; "unknown" outside a git checkout).
std::string buildCommit();

// SHA-256 of the file's bytes as 64 hex digits; an std::runtime_error naming the file when
// it cannot be read.
std::string fileSha256(const std::string& path);

// Every setting of `method` (kind, name): the value `params` gives, else the value a preset
// in `params` gives it (Method::presetValues), else its default as `--help-params` states it.
nlohmann::json resolvedParams(MethodKind kind, const std::string& method, const ParamMap& params);

// {commit, scene, scene_sha256, seed}: what every record of one comparison shares
// (scene_sha256 null for a scene without a file).
nlohmann::json runProvenance(const std::string& scenePath, uint32_t seed);

}  // namespace vct
