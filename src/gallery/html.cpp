#include "gallery/html.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>

namespace vct {

std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string encodeUrlPath(const std::string& path) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_' || c == '~') {
            out += char(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

std::string formatNumber(double value, int digits) {
    if (!std::isfinite(value)) return "\xE2\x80\x93";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    return buf;
}

std::string formatMs(double ms) {
    if (!std::isfinite(ms)) return "\xE2\x80\x93";
    char buf[64];
    if (ms >= 1000.0)
        std::snprintf(buf, sizeof buf, "%.3g s", ms / 1000.0);
    else
        std::snprintf(buf, sizeof buf, "%.3g ms", ms);
    return buf;
}

namespace {

std::string formatUtc(std::time_t t) {
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[64];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
    return buf;
}

}  // namespace

std::string utcNowString() { return formatUtc(std::time(nullptr)); }

std::string fileTimeString(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    auto ft = fs::last_write_time(path, ec);
    if (ec) return "";
    // file_clock -> system_clock without C++20's clock_cast: shift by the two clocks' "now".
    auto sys = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
        ft - fs::file_time_type::clock::now() + std::chrono::system_clock::now());
    return formatUtc(std::chrono::system_clock::to_time_t(sys));
}

}  // namespace vct
