// Files appear whole or not at all: write to a temporary name beside the target, then
// rename (atomic on POSIX within one file system).
#pragma once

#include <string>

namespace vct {

// Throws std::runtime_error naming the path if the write or the rename fails; leaves no
// temporary file behind.
void writeTextFileAtomic(const std::string& path, const std::string& text);
// A unique temporary name in the same directory as `path`, keeping its extension.
std::string temporaryPathFor(const std::string& path);

}  // namespace vct
