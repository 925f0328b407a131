// Finding one record of a `vct compare` results document in tests.
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace vcttest {

// The record whose label is `label`; throws when there is none, so a test fails naming it.
inline const nlohmann::json& record(const nlohmann::json& doc, const std::string& label) {
    for (const auto& r : doc["records"])
        if (r["label"] == label) return r;
    throw std::runtime_error("no record " + label);
}

}  // namespace vcttest
