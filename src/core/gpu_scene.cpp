#include "core/gpu_scene.h"

#include "common/scene_shared.h"
#include "gl/program_limits.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <stdexcept>

namespace vct {

namespace {

// Every glTF image is resampled to one square size so that all fit one texture array:
// one binding serves any number of materials, in the rasterizer and the voxelizer alike.
std::vector<uint8_t> resampleToLayer(const Texture& t) {
    const int n = gpu::SCENE_TEXTURE_SIZE;
    OIIO::ImageSpec srcSpec(t.width, t.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf src(srcSpec, const_cast<uint8_t*>(t.rgba.data()));
    OIIO::ImageBuf dst;
    if (t.width == n && t.height == n) return t.rgba;
    OIIO::ROI roi(0, n, 0, n, 0, 1, 0, 4);
    if (!OIIO::ImageBufAlgo::resize(dst, src, "", 0.f, roi))
        throw std::runtime_error("texture '" + t.name + "': resize failed: " + dst.geterror());
    std::vector<uint8_t> out(size_t(n) * n * 4);
    dst.get_pixels(roi, OIIO::TypeDesc::UINT8, out.data());
    return out;
}

std::string str3(const glm::vec3& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}


// The loader rejects non-finite files; a Scene built in code reaches the GPU without it, and
// one NaN vertex poisons voxel averages and Embree's BVH. Refuse it here, naming the element.
void validateScene(const Scene& scene) {
    const std::string where = "scene" + (scene.path.empty() ? std::string() : " '" + scene.path + "'");
    for (size_t i = 0; i < scene.positions.size(); ++i)
        if (!finite3(scene.positions[i]))
            throw std::runtime_error(where + ": vertex " + std::to_string(i) + " position is not finite " +
                                     str3(scene.positions[i]));
    for (size_t i = 0; i < scene.normals.size(); ++i)
        if (!finite3(scene.normals[i]))
            throw std::runtime_error(where + ": vertex " + std::to_string(i) + " normal is not finite " +
                                     str3(scene.normals[i]));
    if (!scene.colors.empty() && scene.colors.size() != scene.positions.size())
        throw std::runtime_error(where + ": " + std::to_string(scene.colors.size()) + " vertex colours for " +
                                 std::to_string(scene.positions.size()) + " vertices");
    for (size_t i = 0; i < scene.colors.size(); ++i)
        if (!finite3(glm::vec3(scene.colors[i])) || !std::isfinite(scene.colors[i].a))
            throw std::runtime_error(where + ": vertex " + std::to_string(i) + " colour is not finite");
    for (size_t t = 0; t < scene.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (scene.triangles[t][k] >= scene.positions.size())
                throw std::runtime_error(where + ": triangle " + std::to_string(t) + " index " +
                                         std::to_string(scene.triangles[t][k]) + " out of range [0, " +
                                         std::to_string(scene.positions.size()) + ")");
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const Material& mat = scene.materials[m];
        if (!finite3(glm::vec3(mat.baseColorFactor)) || !finite3(mat.emissiveFactor))
            throw std::runtime_error(where + ": material " + std::to_string(m) + " '" + mat.name +
                                     "': base colour or emission is not finite");
    }
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        if (!finite3(light.color) || !finite3(light.position) || !finite3(light.direction))
            throw std::runtime_error(where + ": light " + std::to_string(l) + " '" + light.name +
                                     "': colour, position or direction is not finite");
    }
}

// GpuMaterial::flags bits of texture `texture`'s wrap modes (none for no texture).
int wrapFlags(const Scene& scene, int texture, int shift) {
    if (texture < 0 || size_t(texture) >= scene.textures.size()) return 0;
    static_assert(int(TextureWrap::Repeat) == gpu::TEXTURE_WRAP_REPEAT &&
                      int(TextureWrap::ClampToEdge) == gpu::TEXTURE_WRAP_CLAMP_TO_EDGE &&
                      int(TextureWrap::MirroredRepeat) == gpu::TEXTURE_WRAP_MIRRORED_REPEAT,
                  "TextureWrap and the shaders' wrap modes share their numbering");
    const Texture& t = scene.textures[size_t(texture)];
    return (int(t.wrapS) << shift) | (int(t.wrapT) << (shift + 2));
}

}  // namespace

namespace {

// The G-buffer's geometric normal of triangle t: Scene::geometricNormal, (0, 1, 0) for a
// degenerate one, whose normal does not exist (the loader drops those, but a scene built in
// code may keep them).
glm::vec3 triangleGeometricNormal(const Scene& scene, size_t t) {
    const glm::vec3 n = scene.geometricNormal(t);
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) ? n : glm::vec3(0.f, 1.f, 0.f);
}

// The lights as the shaders read them; the shadow pass fills in the shadow fields.
std::vector<gpu::GpuLight> gpuLights(const Scene& scene) {
    std::vector<gpu::GpuLight> lights;
    for (const Light& l : scene.lights) {
        gpu::GpuLight gl{};
        gl.color = glm::vec4(l.color, float(int(l.type)));
        gl.position = glm::vec4(l.position, 1.f);
        gl.direction = glm::vec4(glm::normalize(l.direction), 0.f);
        gl.spot = glm::vec4(std::cos(l.outerConeAngle), std::cos(l.innerConeAngle), -1.f, 0.f);
        gl.shadowClipFromWorld = glm::mat4(1.f);
        lights.push_back(gl);
    }
    return lights;
}

}  // namespace

void uploadLights(GpuScene& g, const Scene& scene) {
    if (int(scene.lights.size()) != g.lightCount)
        throw std::invalid_argument("uploadLights: the scene's light count changed");
    validateScene(scene);
    const std::vector<gpu::GpuLight> lights = gpuLights(scene);
    if (!lights.empty())
        glNamedBufferSubData(g.lights.id(), 0, GLsizeiptr(lights.size() * sizeof(gpu::GpuLight)), lights.data());
}

GpuScene uploadScene(const Scene& scene) {
    validateScene(scene);
    GpuScene g;
    g.vertexCount = static_cast<int>(scene.positions.size());
    g.triangleCount = static_cast<int>(scene.triangles.size());
    g.materialCount = static_cast<int>(scene.materials.size());
    g.lightCount = static_cast<int>(scene.lights.size());
    g.bounds = scene.bounds;
    g.hasTextures = !scene.textures.empty();
    for (const Material& m : scene.materials) g.hasAlphaMask |= m.alphaMask;
    g.hasVertexColors = !scene.colors.empty();
    for (const Texture& t : scene.textures)
        g.hasWrapModes |= t.wrapS != TextureWrap::Repeat || t.wrapT != TextureWrap::Repeat;

    // Shaders read the scene's arrays as shader storage blocks, each within the device's
    // block size (GL guarantees 128 MiB: 2.8 million vertices, 11 million triangles).
    const std::string where = "scene" + (scene.path.empty() ? std::string() : " '" + scene.path + "'");
    checkStorageBufferSize(scene.positions.size() * sizeof(gpu::GpuVertex),
                           where + ": " + std::to_string(scene.positions.size()) + " vertices");
    checkStorageBufferSize(scene.triangles.size() * sizeof(glm::uvec3),
                           where + ": " + std::to_string(scene.triangles.size()) + " triangles");
    if (scene.textures.size() > size_t(deviceLimits().arrayTextureLayers))
        throw std::runtime_error(where + ": " + std::to_string(scene.textures.size()) +
                                 " textures, more than the " + std::to_string(deviceLimits().arrayTextureLayers) +
                                 " layers of this GL's texture arrays (GL_MAX_ARRAY_TEXTURE_LAYERS)");

    std::vector<gpu::GpuVertex> vertices(scene.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        vertices[i].position = glm::vec4(scene.positions[i], 1.f);
        vertices[i].normal = glm::vec4(i < scene.normals.size() ? scene.normals[i] : glm::vec3(0, 1, 0), 0.f);
        vertices[i].uv = glm::vec4(i < scene.uvs.size() ? scene.uvs[i] : glm::vec2(0.f), 0.f, 0.f);
        vertices[i].color = g.hasVertexColors ? scene.colors[i] : glm::vec4(1.f);
    }
    g.vertices = createBuffer(vertices.size() * sizeof(gpu::GpuVertex), vertices.data());
    g.indices = createBuffer(scene.triangles.size() * sizeof(glm::uvec3), scene.triangles.data());
    std::vector<uint32_t> triMaterial = scene.triangleMaterial;
    triMaterial.resize(scene.triangles.size(), 0);
    g.triangleMaterial = createBuffer(triMaterial.size() * sizeof(uint32_t), triMaterial.data());
    std::vector<glm::vec4> triNormal(scene.triangles.size());
    for (size_t t = 0; t < triNormal.size(); ++t) triNormal[t] = glm::vec4(triangleGeometricNormal(scene, t), 0.f);
    g.triangleNormal = createBuffer(std::max<size_t>(1, triNormal.size()) * sizeof(glm::vec4),
                                    triNormal.empty() ? nullptr : triNormal.data());

    std::vector<gpu::GpuMaterial> materials;
    for (const Material& m : scene.materials) {
        gpu::GpuMaterial gm{};
        gm.baseColor = m.baseColorFactor;
        gm.emissive = glm::vec4(m.emissiveFactor, 0.f);
        gm.baseColorLayer = m.baseColorTexture;
        gm.emissiveLayer = m.emissiveTexture;
        gm.flags = (m.doubleSided ? gpu::MATERIAL_DOUBLE_SIDED : 0) | (m.alphaMask ? gpu::MATERIAL_ALPHA_MASK : 0) |
                   wrapFlags(scene, m.baseColorTexture, gpu::MATERIAL_BASE_WRAP_SHIFT) |
                   wrapFlags(scene, m.emissiveTexture, gpu::MATERIAL_EMISSIVE_WRAP_SHIFT);
        gm.alphaCutoff = m.alphaCutoff;
        materials.push_back(gm);
    }
    if (materials.empty()) materials.push_back(gpu::GpuMaterial{glm::vec4(0.8f), glm::vec4(0.f), -1, -1, 0, 0.5f});
    g.materials = createBuffer(materials.size() * sizeof(gpu::GpuMaterial), materials.data());

    const std::vector<gpu::GpuLight> lights = gpuLights(scene);
    g.lights = createBuffer(std::max<size_t>(1, lights.size()) * sizeof(gpu::GpuLight),
                            lights.empty() ? nullptr : lights.data(), GL_DYNAMIC_STORAGE_BIT);

    // Texture array: at least one (white) layer so the sampler is always complete.
    const int n = gpu::SCENE_TEXTURE_SIZE;
    const int layers = std::max<int>(1, static_cast<int>(scene.textures.size()));
    const int levels = static_cast<int>(std::log2(n)) + 1;
    GLuint tex = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &tex);
    g.textures = GlTexture(tex);
    glTextureStorage3D(tex, levels, GL_SRGB8_ALPHA8, n, n, layers);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (scene.textures.empty()) {
        std::vector<uint8_t> white(size_t(n) * n * 4, 255);
        glTextureSubImage3D(tex, 0, 0, 0, 0, n, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
    }
    for (size_t i = 0; i < scene.textures.size(); ++i) {
        std::vector<uint8_t> layer = resampleToLayer(scene.textures[i]);
        glTextureSubImage3D(tex, 0, 0, 0, GLint(i), n, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, layer.data());
    }
    glGenerateTextureMipmap(tex);
    glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_REPEAT);

    // Vertex array for rasterization: the same buffer, read as attributes.
    g.vao = createVertexArray();
    GLuint vao = g.vao.id();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, sizeof(gpu::GpuVertex));
    glVertexArrayElementBuffer(vao, g.indices.id());
    const GLuint offsets[4] = {offsetof(gpu::GpuVertex, position), offsetof(gpu::GpuVertex, normal),
                               offsetof(gpu::GpuVertex, uv), offsetof(gpu::GpuVertex, color)};
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 4, GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }
    return g;
}

void bindSceneBuffers(const GpuScene& s) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::SCENE_BINDING_VERTICES, s.vertices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::SCENE_BINDING_INDICES, s.indices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::SCENE_BINDING_TRIMATERIAL, s.triangleMaterial.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::SCENE_BINDING_MATERIALS, s.materials.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::SCENE_BINDING_LIGHTS, s.lights.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::SCENE_BINDING_TRINORMAL, s.triangleNormal.id());
    glBindTextureUnit(gpu::SCENE_UNIT_TEXTURES, s.textures.id());
}

}  // namespace vct
