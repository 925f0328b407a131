// Image files: bit-exact EXR floats with channel names, 8-bit PNG, atomic writes, sRGB encoding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

#include "core/errors.h"
#include "eval/image_io.h"

namespace fs = std::filesystem;

namespace vct {
namespace {

class EvalImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "vct_eval_io_XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir = pattern;
    }
    void TearDown() override { fs::remove_all(dir); }
    size_t fileCount() const {
        return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
    }
    fs::path dir;
};

Image randomImage(int w, int h, int channels, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-2.f, 2.f);
    Image img(w, h, channels);
    for (float& v : img.pixels) v = u(rng);
    return img;
}

TEST_F(EvalImageIo, ExrRoundTripIsBitExactWithNames) {
    Image img = randomImage(37, 21, 2, 5);
    // Values half-floats would mangle: tiny, huge, and many significant digits.
    img.at(0, 0, 0) = 1e-30f;
    img.at(1, 0, 0) = 3e38f;
    img.at(2, 0, 1) = 0.123456789f;
    img.at(3, 0, 1) = -0.f;
    std::string path = (dir / "ao.exr").string();
    writeImage(path, img, {"ao", "stderr"});
    Image back = readImage(path);
    ASSERT_EQ(back.width, img.width);
    ASSERT_EQ(back.height, img.height);
    ASSERT_EQ(back.channels, img.channels);
    EXPECT_EQ(std::memcmp(back.pixels.data(), img.pixels.data(), img.pixels.size() * sizeof(float)), 0);
    EXPECT_EQ(channelNamesOf(path), (std::vector<std::string>{"ao", "stderr"}));
    EXPECT_EQ(fileCount(), 1u);  // no temporary left behind

    Image grey = randomImage(5, 3, 1, 6);
    writeImage((dir / "y.exr").string(), grey);
    EXPECT_EQ(channelNamesOf((dir / "y.exr").string()), (std::vector<std::string>{"Y"}));
    EXPECT_EQ(readImage((dir / "y.exr").string()).pixels, grey.pixels);
}

// OpenEXR stores channels sorted by name; the data must follow its name, whatever the order.
TEST_F(EvalImageIo, ExrChannelDataFollowsNames) {
    Image img(3, 2, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) img.at(x, y, 0) = 0.01f * x, img.at(x, y, 1) = 0.5f + 0.1f * y;
    std::string path = (dir / "sorted.exr").string();
    writeImage(path, img, {"stderr", "ao"});
    std::vector<std::string> names = channelNamesOf(path);
    Image back = readImage(path);
    ASSERT_EQ(names.size(), 2u);
    int ao = names[0] == "ao" ? 0 : 1, se = 1 - ao;
    ASSERT_EQ(names[se], "stderr");
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            EXPECT_EQ(back.at(x, y, ao), img.at(x, y, 1));
            EXPECT_EQ(back.at(x, y, se), img.at(x, y, 0));
        }
}

TEST_F(EvalImageIo, PngRoundTripWithinOneStep) {
    Image img(19, 11, 4);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.f, 1.f);
    for (float& v : img.pixels) v = u(rng);
    img.at(0, 0, 0) = 1.7f;   // clamped to 1
    img.at(0, 0, 1) = -0.3f;  // clamped to 0
    img.at(4, 2, 3) = 0.f;    // transparent pixel: colour must survive (no premultiplication)
    std::string path = (dir / "fig.png").string();
    writeImage(path, img);
    Image back = readImage(path);
    ASSERT_EQ(back.channels, 4);
    ASSERT_EQ(back.pixels.size(), img.pixels.size());
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        float expected = std::min(1.f, std::max(0.f, img.pixels[i]));
        ASSERT_NEAR(back.pixels[i], expected, 0.5f / 255.f + 1e-6f) << "sample " << i;
    }
    EXPECT_EQ(back.at(0, 0, 0), 1.f);
    EXPECT_EQ(back.at(0, 0, 1), 0.f);
}

TEST_F(EvalImageIo, FailedWriteLeavesNoFile) {
    Image img = randomImage(4, 4, 1, 1);
    std::string missing = (dir / "no_such_dir" / "a.exr").string();
    try {
        writeImage(missing, img);
        FAIL() << "write into a missing directory succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(missing));
    EXPECT_EQ(fileCount(), 0u);

    // The final rename fails (the target is a directory): the finished temporary must go.
    fs::create_directory(dir / "taken.png");
    EXPECT_THROW(writeImage((dir / "taken.png").string(), img), std::runtime_error);
    EXPECT_EQ(fileCount(), 1u);  // just the directory
    EXPECT_TRUE(fs::is_directory(dir / "taken.png"));
}

TEST_F(EvalImageIo, RejectsBadInput) {
    Image img = randomImage(4, 4, 1, 2);
    img.at(2, 3) = std::numeric_limits<float>::quiet_NaN();
    std::string path = (dir / "nan.exr").string();
    try {
        writeImage(path, img);
        FAIL() << "NaN written";
    } catch (const InternalError& e) {
        EXPECT_NE(std::string(e.what()).find("(2, 3)"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path));
    Image ok = randomImage(4, 4, 2, 3);
    EXPECT_THROW(writeImage((dir / "a.exr").string(), ok, {"only_one"}), InternalError);
    EXPECT_THROW(writeImage((dir / "a.bmp").string(), ok), InternalError);
    EXPECT_THROW(readImage((dir / "missing.exr").string()), std::runtime_error);
    EXPECT_EQ(fileCount(), 0u);
}

TEST(EvalToneMap, SrgbOetfAndExposure) {
    // sRGB OETF closed forms: 1.055 * 0.5^(1/2.4) - 0.055 and the linear toe 12.92 x.
    EXPECT_NEAR(srgbFromLinear(0.5f), 1.055 * std::pow(0.5, 1 / 2.4) - 0.055, 1e-6);
    EXPECT_NEAR(srgbFromLinear(0.001f), 0.01292, 1e-7);
    EXPECT_EQ(srgbFromLinear(0.f), 0.f);
    EXPECT_NEAR(srgbFromLinear(1.f), 1.f, 1e-6);

    Image linear(2, 1, 4);
    linear.at(0, 0, 0) = 0.25f, linear.at(0, 0, 1) = 4.f;
    linear.at(0, 0, 2) = -1.f, linear.at(0, 0, 3) = 0.3f;
    Image out = toneMapToSrgb(linear, 1.f);  // +1 stop: 0.25 -> 0.5
    EXPECT_NEAR(out.at(0, 0, 0), srgbFromLinear(0.5f), 1e-6);
    EXPECT_EQ(out.at(0, 0, 1), 1.f);
    EXPECT_EQ(out.at(0, 0, 2), 0.f);
    EXPECT_EQ(out.at(0, 0, 3), 0.3f);  // alpha untouched

    Image grey(1, 1, 1, 0.25f);
    EXPECT_NEAR(toneMapToSrgb(grey, 1.f).at(0, 0), srgbFromLinear(0.5f), 1e-6);  // 1 channel: encoded
    EXPECT_EQ(toneMapToSrgb(grey, 1000.f).at(0, 0), 1.f);  // overflowing exposure stays finite
    grey.at(0, 0) = std::numeric_limits<float>::infinity();
    EXPECT_THROW(toneMapToSrgb(grey, 0.f), InternalError);
}

}  // namespace
}  // namespace vct
