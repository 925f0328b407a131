#include "core/method.h"

namespace vct {

const char* toString(MethodKind k) { return k == MethodKind::AO ? "ao" : "gi"; }

void FrameOutputs::setTexture(ResourceId id, GlTexture texture, int channels) {
    FrameResource& r = mResources[std::string(id.name)];
    r.texture = std::move(texture);
    r.textureChannels = channels;
}

void FrameOutputs::setImage(ResourceId id, Image image) { mResources[std::string(id.name)].image = std::move(image); }

const FrameResource* FrameOutputs::find(ResourceId id) const {
    auto it = mResources.find(id.name);
    return it == mResources.end() ? nullptr : &it->second;
}

FrameResource* FrameOutputs::find(ResourceId id) {
    auto it = mResources.find(id.name);
    return it == mResources.end() ? nullptr : &it->second;
}

}  // namespace vct
