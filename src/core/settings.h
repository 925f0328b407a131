// Typed settings: a method lists each `--param` key it reads once, in a table of its
// settings struct (key, default, range, one doc line, the field it fills), and reads the
// table into the struct. The table is the one place a range is written: reading checks it
// (a UsageError naming the key), and `vct render --help-params` prints it.
//
//   struct GtaoSettings { int slices = 2; ... };
//   const SettingsTable<GtaoSettings>& gtaoSettings() {
//       static const auto t = SettingsTable<GtaoSettings>()
//           .integer("gtao.slices", &GtaoSettings::slices, 1, 64, "slices per pixel");
//       return t;
//   }
//   GtaoSettings s = gtaoSettings().read(request.params);
//
// The default of a field is the struct's initializer, or a function of the fields read
// before it (a preset's slice count), shown in the help with its own text.
#pragma once

#include "core/errors.h"
#include "core/params.h"

#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace vct {

struct SettingDoc {
    std::string key;
    std::string defaultValue;
    std::string range;
    std::string doc;
};

template <class T>
class SettingsTable {
public:
    SettingsTable& integer(const std::string& key, int T::*field, int min, int max, const std::string& doc) {
        return integer(key, field, fieldDefault(field), text(T{}.*field), min, max, doc);
    }
    SettingsTable& integer(const std::string& key, int T::*field, std::function<int(const T&)> def,
                           const std::string& defaultText, int min, int max, const std::string& doc) {
        mDocs.push_back({key, defaultText, "[" + text(min) + ", " + text(max) + "]", doc});
        mReaders.push_back([=](T& s, const ParamMap& p) { s.*field = p.getInt(key, def(s), min, max); });
        return *this;
    }
    SettingsTable& real(const std::string& key, float T::*field, float min, float max, const std::string& doc) {
        return real(key, field, fieldDefault(field), text(T{}.*field), min, max, doc);
    }
    SettingsTable& real(const std::string& key, float T::*field, std::function<float(const T&)> def,
                        const std::string& defaultText, float min, float max, const std::string& doc) {
        mDocs.push_back({key, defaultText, "[" + text(min) + ", " + text(max) + "]", doc});
        mReaders.push_back([=](T& s, const ParamMap& p) { s.*field = p.getFloat(key, def(s), min, max); });
        return *this;
    }
    SettingsTable& flag(const std::string& key, bool T::*field, const std::string& doc) {
        mDocs.push_back({key, T{}.*field ? "1" : "0", "0 or 1", doc});
        mReaders.push_back([=](T& s, const ParamMap& p) { s.*field = p.getBool(key, s.*field); });
        return *this;
    }
    // One of named values; V is the field's type (a string, an enum, an int).
    template <class V>
    SettingsTable& choice(const std::string& key, V T::*field, std::vector<std::pair<std::string, V>> options,
                          const std::string& doc) {
        std::string range, def;
        std::vector<std::string> names;
        for (const auto& [name, value] : options) {
            range += (range.empty() ? "" : "|") + name;
            names.push_back(name);
            if (value == T{}.*field) def = name;
        }
        mDocs.push_back({key, def, range, doc});
        mReaders.push_back([=](T& s, const ParamMap& p) {
            std::string current;
            for (const auto& [name, value] : options)
                if (value == s.*field) current = name;
            const std::string chosen = p.getChoice(key, current, names);
            for (const auto& [name, value] : options)
                if (name == chosen) s.*field = value;
        });
        return *this;
    }
    // A key of a type the builders above do not cover: its doc line and how to read it.
    SettingsTable& custom(SettingDoc doc, std::function<void(T&, const ParamMap&)> reader) {
        mDocs.push_back(std::move(doc));
        mReaders.push_back(std::move(reader));
        return *this;
    }
    // A reader with no key of its own, run where it stands among the others: it sets fields
    // from keys another table documents (a preset's values, which the keys read after it
    // then override), or checks fields against what the user gave. No doc line.
    SettingsTable& derive(std::function<void(T&, const ParamMap&)> reader) {
        mReaders.push_back(std::move(reader));
        return *this;
    }
    // A rule across fields, checked after every key is read; throws UsageError.
    SettingsTable& check(std::function<void(const T&)> rule) {
        mReaders.push_back([rule](T& s, const ParamMap&) { rule(s); });
        return *this;
    }

    // The settings with every key of the table read from `params` (the others as `base`).
    T read(const ParamMap& params, T base = T{}) const {
        for (const auto& r : mReaders) r(base, params);
        return base;
    }
    const std::vector<SettingDoc>& docs() const { return mDocs; }

private:
    template <class V>
    static std::function<V(const T&)> fieldDefault(V T::*field) {
        return [field](const T& s) { return s.*field; };
    }
    template <class V>
    static std::string text(V v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }

    std::vector<SettingDoc> mDocs;
    std::vector<std::function<void(T&, const ParamMap&)>> mReaders;
};

}  // namespace vct
