// Typed reads of single sweep-spec fields; every error names the field by its path.
#include "eval/sweep_detail.h"

#include "core/errors.h"
#include "core/params.h"
#include "render/renderer.h"

#include <algorithm>

#include <cmath>
#include <stdexcept>

namespace vct::sweep_detail {

using nlohmann::json;

void fail(const std::string& where, const std::string& what) {
    throw UsageError("sweep spec: " + where + ": " + what);
}

std::string join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
}

std::string indexed(const std::string& where, size_t i) { return where + "[" + std::to_string(i) + "]"; }

namespace {

// Fields whose name starts with "_" or is "description"/"comment" are notes, not settings.
bool isNote(const std::string& key) { return key.empty() || key[0] == '_' || key == "description" || key == "comment"; }

}  // namespace

void checkKnownFields(const json& obj, const std::string& where, const std::set<std::string>& known) {
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (!isNote(it.key()) && !known.count(it.key())) {
            std::string all;
            for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
            fail(join(where, it.key()), "unknown field (known: " + all + ")");
        }
}

int intField(const json& j, const std::string& where, int lo, int hi) {
    if (!j.is_number_integer()) fail(where, "expected an integer, got " + j.dump());
    long long v = j.get<long long>();
    if (v < lo || v > hi) fail(where, std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return int(v);
}

float positiveFloat(const json& j, const std::string& where, bool allowZero) {
    if (!j.is_number()) fail(where, "expected a number, got " + j.dump());
    double v = j.get<double>();
    if (!std::isfinite(v) || v < 0 || (!allowZero && v == 0))
        fail(where, "expected a finite number " + std::string(allowZero ? ">= 0" : "> 0") + ", got " + j.dump());
    return float(v);
}

std::string paramValue(const json& j, const std::string& where) {
    if (j.is_string()) return j.get<std::string>();
    if (j.is_boolean()) return j.get<bool>() ? "1" : "0";
    if (j.is_number()) return j.dump();
    fail(where, "expected a string, number or bool, got " + j.dump());
}

void checkParamKey(const std::string& key, const std::string& where) {
    const std::vector<SettingDoc> docs = allSettingDocs();
    if (std::none_of(docs.begin(), docs.end(), [&](const SettingDoc& d) { return d.key == key; }))
        fail(where, "unknown parameter '" + key + "' (see vct render --help-params)");
}

std::map<std::string, std::string> paramsField(const json& j, const std::string& where) {
    if (!j.is_object()) fail(where, "expected an object of KEY: VALUE, got " + j.dump());
    std::map<std::string, std::string> out;
    for (auto it = j.begin(); it != j.end(); ++it) {
        checkParamKey(it.key(), join(where, it.key()));
        out[it.key()] = paramValue(it.value(), join(where, it.key()));
    }
    return out;
}

void sizeField(const json& j, const std::string& where, int& w, int& h) {
    auto check = [&](long long v) {
        if (v < 1 || v > 16384) fail(where, "image size must be in [1, 16384], got " + std::to_string(v));
        return int(v);
    };
    if (j.is_number_integer()) {
        w = h = check(j.get<long long>());
    } else if (j.is_array() && j.size() == 2 && j[0].is_number_integer() && j[1].is_number_integer()) {
        w = check(j[0].get<long long>());
        h = check(j[1].get<long long>());
    } else if (j.is_string()) {
        const std::string s = j.get<std::string>();
        size_t x = s.find('x');
        try {
            size_t used = 0;
            long long a = std::stoll(s.substr(0, x), &used);
            if (used != (x == std::string::npos ? s.size() : x)) throw std::invalid_argument("trailing text");
            long long b = a;
            if (x != std::string::npos) {
                b = std::stoll(s.substr(x + 1), &used);
                if (used != s.size() - x - 1) throw std::invalid_argument("trailing text");
            }
            w = check(a);
            h = check(b);
        } catch (const std::logic_error&) {
            fail(where, "expected N, \"WxH\" or [W, H], got " + j.dump());
        }
    } else {
        fail(where, "expected N, \"WxH\" or [W, H], got " + j.dump());
    }
}

}  // namespace vct::sweep_detail
