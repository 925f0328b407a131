// What the sweep's spec files share and callers never see: the located spec error and the
// typed reads of one JSON field, each naming the field by its path ("scenes[1].size").
#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>

namespace vct::sweep_detail {

// Throws UsageError("sweep spec: <where>: <what>").
[[noreturn]] void fail(const std::string& where, const std::string& what);

// Field paths: join("scenes[1]", "size") = "scenes[1].size", indexed("radius", 2) = "radius[2]".
std::string join(const std::string& where, const std::string& key);
std::string indexed(const std::string& where, size_t i);

// Fails on a field of `obj` that is neither in `known` nor a note ("_...", "description",
// "comment"), listing the known ones.
void checkKnownFields(const nlohmann::json& obj, const std::string& where, const std::set<std::string>& known);

int intField(const nlohmann::json& j, const std::string& where, int lo, int hi);
// A finite number > 0, or >= 0 with allowZero.
float positiveFloat(const nlohmann::json& j, const std::string& where, bool allowZero);
// A parameter value as --param would receive it: strings as written, bools as "1"/"0".
std::string paramValue(const nlohmann::json& j, const std::string& where);
// Fails unless `key` is a documented method parameter.
void checkParamKey(const std::string& key, const std::string& where);
// An object of documented KEY: VALUE parameters.
std::map<std::string, std::string> paramsField(const nlohmann::json& j, const std::string& where);
// N, "WxH" or [W, H], each in [1, 16384].
void sizeField(const nlohmann::json& j, const std::string& where, int& w, int& h);

}  // namespace vct::sweep_detail
