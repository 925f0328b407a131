// Shadow map vertex stage: depth from a light (directional/spot: clip space; point: one
// cube face, with world position passed on to store the distance).
layout(location = 0) in vec4 inPosition;
uniform mat4 clipFromWorld;
out vec3 vWorldPos;
void main() {
    vWorldPos = inPosition.xyz;
    gl_Position = clipFromWorld * vec4(inPosition.xyz, 1.0);
}
