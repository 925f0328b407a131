// Lets a header of plain structs and constants compile both as C++ (with GLM) and as GLSL.
// Shared structs use only vec4/ivec4/uvec4/mat4 members, float/int/uint scalars, and
// explicit padding, so std430 and C++ layouts agree; shared functions may use every type below.
#pragma once
#ifdef __cplusplus
#include <glm/glm.hpp>
#include <glm/integer.hpp>
#include <cstdint>
#define VCT_CONST static constexpr
namespace vct { namespace gpu {
using vec2 = glm::vec2; using vec3 = glm::vec3; using vec4 = glm::vec4;
using ivec3 = glm::ivec3; using ivec4 = glm::ivec4; using uvec2 = glm::uvec2; using uvec4 = glm::uvec4; using bvec3 = glm::bvec3;
using mat3 = glm::mat3; using mat4 = glm::mat4;
using uint = std::uint32_t;
// GLSL's built-ins for the inline functions of shared headers (scalars and vectors alike).
using glm::abs; using glm::any; using glm::clamp; using glm::dot; using glm::exp2; using glm::floor; using glm::greaterThan;
using glm::length; using glm::lessThan; using glm::log2; using glm::max; using glm::min; using glm::mix; using glm::normalize;
using glm::asin; using glm::sign; using glm::sqrt; using glm::findLSB; using glm::findMSB;
}}  // namespace vct::gpu
#define VCT_BEGIN_NAMESPACE namespace vct { namespace gpu {
#define VCT_END_NAMESPACE }}
#else
#define VCT_CONST const
#define VCT_BEGIN_NAMESPACE
#define VCT_END_NAMESPACE
#endif
