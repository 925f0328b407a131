// `--param KEY=VALUE` settings. Every consumer reads its keys through the typed getters,
// which check the documented range; keys nobody read are an error (pbrt's ReportUnused),
// so a typo never silently does nothing. Each getter also records the key's default,
// range and doc line so `vct render --help-params` can list them all.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace vct {

struct ParamDoc {
    std::string key;
    std::string defaultValue;
    std::string range;
    std::string doc;
};

class ParamMap {
public:
    ParamMap() = default;
    // Parses "key=value"; throws std::invalid_argument on malformed input.
    void set(const std::string& keyEqualsValue);
    void set(const std::string& key, const std::string& value) { mValues[key] = value; }
    bool has(const std::string& key) const { return mValues.count(key) != 0; }

    // Typed reads with range checks; throw std::invalid_argument naming the key and range.
    float getFloat(const std::string& key, float def, float min, float max, const std::string& doc = "") const;
    int getInt(const std::string& key, int def, int min, int max, const std::string& doc = "") const;
    bool getBool(const std::string& key, bool def, const std::string& doc = "") const;
    std::string getChoice(const std::string& key, const std::string& def,
                          const std::vector<std::string>& choices, const std::string& doc = "") const;

    // Keys set but never read; call after the render to reject typos.
    std::vector<std::string> unusedKeys() const;
    const std::map<std::string, std::string>& values() const { return mValues; }

    // Documentation of every key read so far in this process (for --help-params).
    static const std::map<std::string, ParamDoc>& documented();

private:
    std::map<std::string, std::string> mValues;
    mutable std::set<std::string> mRead;
};

}  // namespace vct
