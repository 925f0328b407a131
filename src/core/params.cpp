#include "core/params.h"

#include "core/errors.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vct {

namespace {

template <typename T>
std::string str(T v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

void ParamMap::set(const std::string& kv) {
    size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == kv.size())
        throw UsageError("--param '" + kv + "': expected KEY=VALUE");
    mValues[kv.substr(0, eq)] = kv.substr(eq + 1);
}

float ParamMap::getFloat(const std::string& key, float def, float min, float max) const {
    auto it = mValues.find(key);
    if (it == mValues.end()) return def;
    mRead.insert(key);
    size_t used = 0;
    float v = 0.f;
    try { v = std::stof(it->second, &used); } catch (...) { used = 0; }
    if (used != it->second.size() || !std::isfinite(v))
        throw UsageError("--param " + key + "=" + it->second + ": not a finite number");
    if (v < min || v > max)
        throw UsageError("--param " + key + "=" + it->second + ": out of range [" + str(min) +
                                    ", " + str(max) + "]");
    return v;
}

int ParamMap::getInt(const std::string& key, int def, int min, int max) const {
    auto it = mValues.find(key);
    if (it == mValues.end()) return def;
    mRead.insert(key);
    size_t used = 0;
    long v = 0;
    try { v = std::stol(it->second, &used); } catch (...) { used = 0; }
    if (used != it->second.size())
        throw UsageError("--param " + key + "=" + it->second + ": not an integer");
    if (v < min || v > max)
        throw UsageError("--param " + key + "=" + it->second + ": out of range [" + str(min) +
                                    ", " + str(max) + "]");
    return static_cast<int>(v);
}

bool ParamMap::getBool(const std::string& key, bool def) const {
    auto it = mValues.find(key);
    if (it == mValues.end()) return def;
    mRead.insert(key);
    const std::string& s = it->second;
    if (s == "1" || s == "true" || s == "on") return true;
    if (s == "0" || s == "false" || s == "off") return false;
    throw UsageError("--param " + key + "=" + s + ": expected 0 or 1");
}

std::string ParamMap::getChoice(const std::string& key, const std::string& def,
                                const std::vector<std::string>& choices) const {
    std::string range;
    for (const auto& c : choices) range += (range.empty() ? "" : "|") + c;
    auto it = mValues.find(key);
    if (it == mValues.end()) return def;
    mRead.insert(key);
    for (const auto& c : choices)
        if (c == it->second) return c;
    throw UsageError("--param " + key + "=" + it->second + ": expected one of " + range);
}

std::vector<std::string> ParamMap::unusedKeys() const {
    std::vector<std::string> out;
    for (const auto& [k, v] : mValues)
        if (!mRead.count(k)) out.push_back(k);
    return out;
}

}  // namespace vct
