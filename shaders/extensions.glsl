// extensions.glsl — the GLSL extensions every pass declares, included right after #version: 64-bit
// integers and atomics and 8-bit storage only where the shader is built for devices that have
// them; the 32-bit key path's builds (PHONGVK_KEYS32) declare none of them and use no such type.
#ifndef PHONGVK_KEYS32
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#endif
