#include "util/atomic_file.h"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace vct {

std::string temporaryPathFor(const std::string& path) {
    static std::atomic<int> counter{0};
    std::filesystem::path p(path);
    std::string stem = p.stem().string() + ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    return (p.parent_path() / (stem + p.extension().string())).string();
}

void writeTextFileAtomic(const std::string& path, const std::string& text) {
    std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    const std::string tmp = temporaryPathFor(path);
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw std::runtime_error(path + ": cannot write");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot rename into place: " + ec.message());
    }
}

}  // namespace vct
