// G-buffer vertex stage: world-space attributes straight from the scene's vertex buffer.
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;
layout(location = 2) in vec4 inUv;
#ifndef SCENE_NO_VERTEX_COLORS
layout(location = 3) in vec4 inColor;
out vec4 vColor;
#endif
uniform mat4 clipFromWorld;
out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
void main() {
    vWorldPos = inPosition.xyz;
    vNormal = inNormal.xyz;
    vUv = inUv.xy;
#ifndef SCENE_NO_VERTEX_COLORS
    vColor = inColor;
#endif
    gl_Position = clipFromWorld * vec4(inPosition.xyz, 1.0);
}
