// A one-line progress bar on stderr, drawn only when stderr is a terminal (so logs and
// test output stay clean). advance() is thread-safe and redraws at most once per percent.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace vct {

class ProgressBar {
  public:
    ProgressBar(std::string label, uint64_t total, bool wanted);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void advance(uint64_t work);
    // Changes the work expected (e.g. the sample budget of the next pass) and the note.
    void setTotal(uint64_t total, const std::string& note);
    bool enabled() const { return mEnabled; }

  private:
    void draw(uint64_t done);
    bool mEnabled = false;
    std::string mLabel, mNote;
    std::atomic<uint64_t> mDone{0};
    uint64_t mTotal = 1;
    int mLastPermille = -1;
    std::mutex mMutex;
    std::chrono::steady_clock::time_point mStart;
};

}  // namespace vct
