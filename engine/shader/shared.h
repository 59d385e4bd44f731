// Host/device bridge: include from C++ and GLSL alike. In C++ the GLSL vector types map to glm and
// every struct lives in ppr::gpu; in GLSL the macros vanish. Structs use scalar block layout
// (GL_EXT_scalar_block_layout on the GLSL side), so sizes match C++ exactly; static_asserts check it.
// Functions written once for both sides (the PPR encoding, the display mapping) use PPR_INLINE and
// PPR_OUT(T) and the GLSL spelling of types and built-ins (glm provides the same names in C++).
#ifndef PPR_SHARED_H
#define PPR_SHARED_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>  // unpackUnorm2x16 and friends, as GLSL has them
#include <cstdint>
#define PPR_BEGIN namespace ppr::gpu { using vec2 = glm::vec2; using vec3 = glm::vec3; using vec4 = glm::vec4; \
    using mat4 = glm::mat4; using uint = uint32_t; using uvec2 = glm::uvec2; using uvec4 = glm::uvec4; \
    using ivec2 = glm::ivec2; using mat2 = glm::mat2; using namespace glm;
#define PPR_END }
#define PPR_INLINE inline
#define PPR_OUT(T) T&
#define PPR_INOUT(T) T&
#define PPR_SIZE_CHECK(T, bytes) static_assert(sizeof(ppr::gpu::T) == (bytes), #T " size mismatch with GLSL")
#define PPR_CONST(type, name, value) namespace ppr::gpu { using uint = uint32_t; inline constexpr type name = value; }
#else
#define PPR_BEGIN
#define PPR_END
#define PPR_INLINE
#define PPR_OUT(T) out T
#define PPR_INOUT(T) inout T  // GLSL `out` starts undefined: use this to update a caller's value
#define PPR_SIZE_CHECK(T, bytes)
#define PPR_CONST(type, name, value) const type name = value;
#endif

#endif
