// Small text helpers for writing HTML and SVG by hand (no template engine).
#pragma once

#include <string>

namespace vct {

// Escapes &, <, >, " and ' so the text is safe in element content and quoted attributes.
std::string escapeHtml(const std::string& text);

// Percent-encodes a relative URL path (keeps / . - _ ~ and alphanumerics), so file names with
// brackets, '=' or ';' (variant stems) work as href/src on file:// URLs.
std::string encodeUrlPath(const std::string& path);

// A number for a table cell: %.4g-style with `digits` significant digits; "–" for NaN.
std::string formatNumber(double value, int digits = 4);

// Milliseconds for humans: "0.84 ms", "12.3 ms", "1.25 s".
std::string formatMs(double ms);

// The current time in UTC as "2024-05-01 12:34 UTC".
std::string utcNowString();

// A file's modification time in UTC in the same format; "" when it cannot be read.
std::string fileTimeString(const std::string& path);

}  // namespace vct
