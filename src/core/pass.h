// Typed names of passes and of the resources they read and write, and the plan that says
// which passes run. A pass or resource is declared once as a constant by the layer that
// owns it (the shared ones below; a method's own in its folder), so a misspelt name does
// not compile, where a string would silently match nothing.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vct {

struct PassId {
    std::string_view name;
    bool operator==(const PassId& o) const { return name == o.name; }
    bool operator!=(const PassId& o) const { return name != o.name; }
    bool operator<(const PassId& o) const { return name < o.name; }
};

struct ResourceId {
    std::string_view name;
    bool operator==(const ResourceId& o) const { return name == o.name; }
    bool operator!=(const ResourceId& o) const { return name != o.name; }
    bool operator<(const ResourceId& o) const { return name < o.name; }
};

// The passes every render may run, whatever its methods: rasterization and lighting.
inline constexpr PassId kPassGBuffer{"gbuffer"};
inline constexpr PassId kPassShadow{"shadow"};
inline constexpr PassId kPassDirect{"direct"};
inline constexpr PassId kPassComposite{"composite"};

// The resources the renderer composes and reads back. An AO method writes kAo, a GI
// method kGiIndirect; a method that lights the image itself (a path tracer) also writes
// kBeauty and kDirect.
inline constexpr ResourceId kGBuffer{"gbuffer"};
// The G-buffer's surface alone (position, normals, depth): a pass that reads no albedo or
// emission declares this, and a render whose passes all do draws no material
// (RenderPlan::gbufferMaterials).
inline constexpr ResourceId kGBufferSurface{"gbuffer_surface"};
inline constexpr ResourceId kShadowMaps{"shadowmaps"};
inline constexpr ResourceId kDirect{"direct"};
inline constexpr ResourceId kAo{"ao"};
inline constexpr ResourceId kGiIndirect{"gi_indirect"};
inline constexpr ResourceId kBeauty{"beauty"};
inline constexpr ResourceId kAmbient{"ambient"};

struct PassDecl {
    PassId id;
    std::vector<ResourceId> reads;
    std::vector<ResourceId> writes;
    std::string why;         // why it exists in this request
    bool alwaysRun = false;  // runs whenever declared (the reference always reports its noise)
};

struct SkippedPass {
    PassId id;
    std::string reason;
};

struct RenderPlan {
    std::vector<PassDecl> run;        // in declaration order, each with the reason it runs
    std::vector<SkippedPass> skipped; // every known pass that does not run, with the reason
    std::vector<std::string> notes;   // shader variants and other choices made from the scene
    bool gbufferMaterials = true;     // a kept pass or a requested AOV reads the G-buffer's albedo or emission
    bool runs(PassId pass) const;
    std::vector<std::string> runNames() const;
};

}  // namespace vct
