#include "util/progress.h"

#include <unistd.h>

#include <cstdio>

namespace vct {

ProgressBar::ProgressBar(std::string label, uint64_t total, bool wanted)
    : mEnabled(wanted && isatty(STDERR_FILENO)), mLabel(std::move(label)), mTotal(total ? total : 1),
      mStart(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (!mEnabled) return;
    draw(mTotal);
    std::fputc('\n', stderr);
}

void ProgressBar::setTotal(uint64_t total, const std::string& note) {
    std::lock_guard<std::mutex> lock(mMutex);
    mTotal = total ? total : 1;
    mNote = note;
    mLastPermille = -1;
}

void ProgressBar::advance(uint64_t work) {
    uint64_t done = mDone.fetch_add(work) + work;
    if (!mEnabled) return;
    std::lock_guard<std::mutex> lock(mMutex);
    draw(done);
}

void ProgressBar::draw(uint64_t done) {
    int permille = int(std::min<uint64_t>(1000, done * 1000 / mTotal));
    if (permille / 10 == mLastPermille / 10 && permille != 1000) return;
    mLastPermille = permille;
    constexpr int kWidth = 30;
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < permille * kWidth / 1000 ? '#' : ' ';
    bar[kWidth] = 0;
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    std::fprintf(stderr, "\r%s [%s] %5.1f%% %s %.1fs ", mLabel.c_str(), bar, permille / 10.0, mNote.c_str(),
                 seconds);
    std::fflush(stderr);
}

}  // namespace vct
