#include "raster/shadow_pass.h"

#include "common/scene_shared.h"
#include "raster/raster_programs.h"
#include "raster/raster_shared.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace vct {

namespace {

GlTexture makeArray(GLenum target, GLenum format, int size, int layers) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    glTextureStorage3D(id, 1, format, size, size, layers);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (format == GL_DEPTH_COMPONENT32F) {
        glTextureParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTextureParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    return GlTexture(id);
}

glm::vec3 anyPerpendicular(const glm::vec3& d) {
    return std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

}  // namespace

ShadowMaps emptyShadowMaps() {
    ShadowMaps s;
    s.size = 1;
    s.maps = makeArray(GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, 1, 1);
    s.cubes = makeArray(GL_TEXTURE_CUBE_MAP_ARRAY, GL_R32F, 1, 6);
    return s;
}

void bindShadowMaps(const ShadowMaps& s) {
    glBindTextureUnit(gpu::SHADOW_UNIT_MAPS, s.maps.id());
    glBindTextureUnit(gpu::SHADOW_UNIT_CUBES, s.cubes.id());
}

ShadowMaps renderShadowMaps(const GpuScene& gpuScene, const Scene& scene, int size, PassTimer& timer) {
    if (scene.lights.empty()) return emptyShadowMaps();
    auto scope = timer.scope("shadow", true, Reruns::WhenSceneChanges);
    const GLuint program = cachedProgram(shadowProgramKey(rasterFeaturesOf(gpuScene)));

    ShadowMaps s;
    s.size = size;
    for (const Light& l : scene.lights) (l.type == LightType::Point ? s.cubeCount : s.mapCount)++;
    s.maps = makeArray(GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, s.mapCount ? size : 1, std::max(1, s.mapCount));
    s.cubes = makeArray(GL_TEXTURE_CUBE_MAP_ARRAY, GL_R32F, s.cubeCount ? size : 1, 6 * std::max(1, s.cubeCount));
    GlTexture cubeDepth = createTexture2D(GL_DEPTH_COMPONENT32F, size, size);

    const glm::vec3 center = scene.bounds.center();
    const float radius = std::max(0.5f * glm::length(scene.bounds.extent()), 1e-30f);
    // Normal offset of about 1.5 texels of the widest map: removes acne on the Cornell box
    // floor without visibly detaching contact shadows at 1024^2.
    const float normalBias = 1.5f * 2.f * radius / float(size);

    GlFramebuffer fbo = createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glUseProgram(program);
    GLint locClip = glGetUniformLocation(program, "clipFromWorld");
    GLint locLightPos = glGetUniformLocation(program, "lightPos");
    GLint locStore = glGetUniformLocation(program, "storeDistance");
    bindSceneBuffers(gpuScene);  // the alpha test's materials, triangles and textures
    glBindVertexArray(gpuScene.vao.id());

    auto draw = [&](const glm::mat4& clipFromWorld) {
        glUniformMatrix4fv(locClip, 1, GL_FALSE, glm::value_ptr(clipFromWorld));
        glDrawElements(GL_TRIANGLES, 3 * gpuScene.triangleCount, GL_UNSIGNED_INT, nullptr);
    };

    std::vector<gpu::GpuLight> lights(scene.lights.size());
    glGetNamedBufferSubData(gpuScene.lights.id(), 0, GLsizeiptr(lights.size() * sizeof(gpu::GpuLight)), lights.data());
    int mapLayer = 0, cubeLayer = 0;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        gpu::GpuLight& gl = lights[i];
        gl.spot.w = normalBias;
        if (l.type == LightType::Point) {
            const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
            float far = glm::length(l.position - center) + radius;
            float near = std::max(far * 1e-5f, 1e-30f);
            glm::mat4 proj = glm::perspective(glm::radians(90.f), 1.f, near, far);
            glUniform3fv(locLightPos, 1, glm::value_ptr(l.position));
            glUniform1i(locStore, 1);
            for (int f = 0; f < 6; ++f) {
                glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, s.cubes.id(), 0, 6 * cubeLayer + f);
                glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, cubeDepth.id(), 0);
                glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
                const float big[4] = {3.0e38f, 0, 0, 0};
                const float one = 1.f;
                glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, big);
                glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
                draw(proj * glm::lookAt(l.position, l.position + dirs[f], ups[f]));
            }
            gl.spot.z = float(cubeLayer++);
        } else {
            glm::vec3 dir = glm::normalize(l.direction);
            glm::mat4 clipFromWorld;
            if (l.type == LightType::Directional) {
                glm::mat4 view = glm::lookAt(center - dir * (2.f * radius), center, anyPerpendicular(dir));
                clipFromWorld = glm::ortho(-radius, radius, -radius, radius, 0.f, 4.f * radius) * view;
            } else {
                float far = glm::length(l.position - center) + radius;
                float near = std::max(far * 1e-4f, 1e-30f);
                float fov = std::min(2.f * l.outerConeAngle + 0.05f, glm::radians(170.f));
                clipFromWorld = glm::perspective(fov, 1.f, near, far) *
                                glm::lookAt(l.position, l.position + dir, anyPerpendicular(dir));
            }
            glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, 0, 0);
            glNamedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, s.maps.id(), 0, mapLayer);
            const float one = 1.f;
            glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
            glUniform1i(locStore, 0);
            draw(clipFromWorld);
            gl.shadowClipFromWorld = clipFromWorld;
            gl.spot.z = float(mapLayer++);
        }
    }
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    glNamedBufferSubData(gpuScene.lights.id(), 0, GLsizeiptr(lights.size() * sizeof(gpu::GpuLight)), lights.data());
    return s;
}

}  // namespace vct
