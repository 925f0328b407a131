#include "eval/image_io.h"

#include "core/errors.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "eval/validate.h"
#include "util/atomic_file.h"

namespace vct {

namespace {

enum class FileKind { Exr, Png };

std::string lowercaseExtension(const std::string& path) {
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot);
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext;
}

FileKind fileKindOf(const std::string& path) {
    std::string ext = lowercaseExtension(path);
    if (ext == ".exr") return FileKind::Exr;
    if (ext == ".png") return FileKind::Png;
    throw InternalError("writeImage", "unsupported extension '" + ext + "' in " + path + " (use .exr or .png)");
}

std::vector<std::string> defaultChannelNames(int channels) {
    if (channels == 1) return {"Y"};
    static const char* rgba[] = {"R", "G", "B", "A"};
    std::vector<std::string> names;
    for (int c = 0; c < channels; ++c) names.push_back(c < 4 ? rgba[c] : "channel" + std::to_string(c));
    return names;
}

[[noreturn]] void failWrite(const std::string& path, const std::string& tmp, const std::string& why) {
    std::remove(tmp.c_str());
    throw std::runtime_error("writeImage: cannot write " + path + ": " + why);
}

}  // namespace

void writeImage(const std::string& path, const Image& image, const std::vector<std::string>& channelNames) {
    requireFinite(image, "writeImage(" + path + ")");
    FileKind kind = fileKindOf(path);
    if (!channelNames.empty() && int(channelNames.size()) != image.channels)
        throw InternalError("writeImage(" + path + ")", std::to_string(channelNames.size()) + " channel names for " +
                                                           std::to_string(image.channels) + " channels");
    if (kind == FileKind::Png && image.channels > 4)
        throw InternalError("writeImage(" + path + ")",
                            "PNG holds at most 4 channels, image has " + std::to_string(image.channels));

    OIIO::TypeDesc format = kind == FileKind::Exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(image.width, image.height, image.channels, format);
    spec.channelnames = channelNames.empty() ? defaultChannelNames(image.channels) : channelNames;
    spec.alpha_channel = -1;
    for (int c = 0; c < image.channels; ++c)
        if (spec.channelnames[c] == "A") spec.alpha_channel = c;
    if (kind == FileKind::Exr) spec.attribute("compression", "zip");
    // Our PNG alpha is straight (unassociated); stop OIIO from un-premultiplying the colours.
    if (kind == FileKind::Png) spec.attribute("oiio:UnassociatedAlpha", 1);

    // PNG: quantize here, so the rounding rule is ours and documented, not the plugin's.
    std::vector<uint8_t> bytes;
    const void* data = image.pixels.data();
    if (kind == FileKind::Png) {
        bytes.resize(image.pixels.size());
        for (size_t i = 0; i < bytes.size(); ++i)
            bytes[i] = uint8_t(std::lround(std::clamp(image.pixels[i], 0.f, 1.f) * 255.f));
        data = bytes.data();
    }

    std::string tmp = temporaryPathFor(path);
    auto out = OIIO::ImageOutput::create(path);
    if (!out) failWrite(path, tmp, OIIO::geterror());
    if (!out->open(tmp, spec)) failWrite(path, tmp, out->geterror());
    bool ok = out->write_image(format, data);
    ok = out->close() && ok;
    if (!ok) failWrite(path, tmp, out->geterror());
    if (std::rename(tmp.c_str(), path.c_str()) != 0) failWrite(path, tmp, "rename from " + tmp + " failed");
}

Image readImage(const std::string& path) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // return PNG colours as stored
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) throw std::runtime_error("readImage: cannot open " + path + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.depth > 1) throw std::runtime_error("readImage: " + path + " is a volume image");
    Image image(spec.width, spec.height, spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw std::runtime_error("readImage: cannot read " + path + ": " + in->geterror());
    in->close();
    return image;
}

std::vector<std::string> channelNamesOf(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("channelNamesOf: cannot open " + path + ": " + OIIO::geterror());
    std::vector<std::string> names = in->spec().channelnames;
    in->close();
    return names;
}

float srgbFromLinear(float linear) {
    // !(x > 0) also catches the NaN of 0 * inf when a huge exposure overflows the scale.
    if (!(linear > 0.f)) return 0.f;
    if (linear >= 1.f) return 1.f;  // exact: 1.055f - 0.055f rounds to 0.99999994f
    float v = linear;
    float encoded = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f;
    return std::clamp(encoded, 0.f, 1.f);
}

Image toneMapToSrgb(const Image& linear, float exposure) {
    requireFinite(linear, "toneMapToSrgb input");
    if (!std::isfinite(exposure))
        throw InternalError("toneMapToSrgb", "exposure must be finite, got " + std::to_string(exposure));
    float scale = std::exp2(exposure);
    Image out = linear;
    int colorChannels = linear.channels == 4 ? 3 : linear.channels;
    for (size_t i = 0; i < out.pixels.size(); ++i)
        if (int(i % size_t(linear.channels)) < colorChannels)
            out.pixels[i] = srgbFromLinear(linear.pixels[i] * scale);
    return out;
}

}  // namespace vct
