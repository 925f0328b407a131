// `--param KEY=VALUE` settings as the user gave them. The typed getters parse and check one
// key against its range (a UsageError naming the key); methods read them through their
// settings tables (core/settings.h), which hold each key's default, range and doc line.
// Keys nobody read are an error (pbrt's ReportUnused), so a typo never silently does nothing.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace vct {

class ParamMap {
public:
    ParamMap() = default;
    // Parses "key=value"; throws UsageError on malformed input.
    void set(const std::string& keyEqualsValue);
    void set(const std::string& key, const std::string& value) { mValues[key] = value; }
    bool has(const std::string& key) const { return mValues.count(key) != 0; }

    // Typed reads with range checks; throw UsageError naming the key and range.
    float getFloat(const std::string& key, float def, float min, float max) const;
    int getInt(const std::string& key, int def, int min, int max) const;
    bool getBool(const std::string& key, bool def) const;
    std::string getChoice(const std::string& key, const std::string& def, const std::vector<std::string>& choices) const;

    // Keys set but never read; call after the render to reject typos.
    std::vector<std::string> unusedKeys() const;
    const std::map<std::string, std::string>& values() const { return mValues; }

private:
    std::map<std::string, std::string> mValues;
    mutable std::set<std::string> mRead;
};

}  // namespace vct
