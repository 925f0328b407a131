// A bare fetch loop: per pixel, exactly the number of trilinear 3D-texture fetches the cone
// pass made at that pixel (read from an r32ui image written by bench/cone_count.glsl), and
// nothing else but the address arithmetic. The fetches follow cone-like paths so the cache
// behaviour resembles the real pass: six directions (one along +z, five at 60 degrees), a
// 60-degree footprint, lod = log2(max(1, 2 t tan 30)), step = 0.5 * 2^lod, from a start point
// that moves with the pixel; a path that leaves the volume hands over to the next direction.
// The sum of the fetched values is written so the compiler cannot drop the fetches.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler3D fetch_volume;                  // RGBA16F, mipmapped
layout(r32ui, binding = 1) uniform readonly uimage2D fetch_counts;   // fetches per pixel
layout(r32f, binding = 0) uniform writeonly image2D fetch_out;

layout(location = 0) uniform ivec4 fetch_image;  // x = width, y = height, z = volume size, w = max lod

const float kTanHalf = 0.57735027;  // tan(30 degrees)

vec3 fetch_direction(uint c) {
    if (c == 0u) return vec3(0.0, 0.0, 1.0);
    float phi = 6.2831853 * float(c - 1u) / 5.0;
    return vec3(0.8660254 * cos(phi), 0.8660254 * sin(phi), 0.5);
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= fetch_image.x || pix.y >= fetch_image.y) return;
    uint count = imageLoad(fetch_counts, pix).r;
    float size = float(fetch_image.z);
    vec3 origin = vec3((vec2(pix) + 0.5) / vec2(fetch_image.xy), 0.25) * size;
    uint cone = 0u;
    vec3 d = fetch_direction(cone);
    float t = 1.5;
    vec4 sum = vec4(0.0);
    for (uint i = 0u; i < count; ++i) {
        float lod = min(log2(max(1.0, 2.0 * t * kTanHalf)), float(fetch_image.w));
        float dt = 0.5 * exp2(lod);
        vec3 p = origin + d * (t + 0.5 * dt);
        sum += textureLod(fetch_volume, p / size, lod);
        t += dt;
        if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(size)))) {
            cone = (cone + 1u) % 6u;
            d = fetch_direction(cone);
            t = 1.5;
        }
    }
    imageStore(fetch_out, pix, vec4(sum.x + sum.y + sum.z + sum.w, 0.0, 0.0, 0.0));
}
