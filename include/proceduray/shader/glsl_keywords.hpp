// GLSL reserved words: names a generated member or struct must not take.
//
//   proceduray::is_glsl_reserved("sample");   // true: a GLSL keyword
//   proceduray::is_glsl_reserved("gl_Foo");   // true: the gl_ prefix is reserved
//   proceduray::is_glsl_reserved("radius");   // false
#pragma once

#include <algorithm>
#include <array>
#include <string_view>

namespace proceduray {

/// GLSL 4.60 keywords, reserved words, basic type names (incl. explicit-arithmetic and ray-tracing
/// extensions) and `main`, sorted so lookups are a binary search.
inline constexpr std::array<std::string_view, 246> glsl_reserved_words = {{
    "accelerationStructureEXT", "active", "asm", "atomic_uint", "attribute", "bool", "break", "buffer",
    "bvec2", "bvec3", "bvec4", "callableDataEXT", "callableDataInEXT", "case", "cast", "centroid", "class",
    "coherent", "common", "const", "continue", "default", "discard", "dmat2", "dmat2x2", "dmat2x3", "dmat2x4",
    "dmat3", "dmat3x2", "dmat3x3", "dmat3x4", "dmat4", "dmat4x2", "dmat4x3", "dmat4x4", "do", "double",
    "dvec2", "dvec3", "dvec4", "else", "enum", "extern", "external", "f16vec2", "f16vec3", "f16vec4", "false",
    "filter", "fixed", "flat", "float", "float16_t", "float32_t", "float64_t", "for", "fvec2", "fvec3",
    "fvec4", "goto", "half", "highp", "hitAttributeEXT", "hvec2", "hvec3", "hvec4", "i64vec2", "i64vec3",
    "i64vec4", "if", "ignoreIntersectionEXT", "iimage1D", "iimage1DArray", "iimage2D", "iimage2DArray",
    "iimage2DMS", "iimage2DMSArray", "iimage2DRect", "iimage3D", "iimageBuffer", "iimageCube",
    "iimageCubeArray", "image1D", "image1DArray", "image2D", "image2DArray", "image2DMS", "image2DMSArray",
    "image2DRect", "image3D", "imageBuffer", "imageCube", "imageCubeArray", "in", "inline", "inout", "input",
    "int", "int16_t", "int32_t", "int64_t", "int8_t", "interface", "invariant", "isampler1D",
    "isampler1DArray", "isampler2D", "isampler2DArray", "isampler2DMS", "isampler2DMSArray", "isampler2DRect",
    "isampler3D", "isamplerBuffer", "isamplerCube", "isamplerCubeArray", "isubpassInput", "ivec2", "ivec3",
    "ivec4", "layout", "long", "lowp", "main", "mat2", "mat2x2", "mat2x3", "mat2x4", "mat3", "mat3x2",
    "mat3x3", "mat3x4", "mat4", "mat4x2", "mat4x3", "mat4x4", "mediump", "namespace", "noinline",
    "noperspective", "out", "output", "partition", "patch", "precise", "precision", "public", "rayPayloadEXT",
    "rayPayloadInEXT", "rayQueryEXT", "readonly", "resource", "restrict", "return", "sample", "sampler",
    "sampler1D", "sampler1DArray", "sampler1DArrayShadow", "sampler1DShadow", "sampler2D", "sampler2DArray",
    "sampler2DArrayShadow", "sampler2DMS", "sampler2DMSArray", "sampler2DRect", "sampler2DRectShadow",
    "sampler2DShadow", "sampler3D", "sampler3DRect", "samplerBuffer", "samplerCube", "samplerCubeArray",
    "samplerCubeArrayShadow", "samplerCubeShadow", "samplerShadow", "shaderRecordEXT", "shared", "short",
    "sizeof", "smooth", "static", "struct", "subpassInput", "subpassInputMS", "subroutine", "superp",
    "switch", "template", "terminateRayEXT", "texture1D", "texture1DArray", "texture2D", "texture2DArray",
    "texture2DMS", "texture3D", "textureBuffer", "textureCube", "this", "true", "typedef", "u64vec2",
    "u64vec3", "u64vec4", "uimage1D", "uimage1DArray", "uimage2D", "uimage2DArray", "uimage2DMS",
    "uimage2DMSArray", "uimage2DRect", "uimage3D", "uimageBuffer", "uimageCube", "uimageCubeArray", "uint",
    "uint16_t", "uint32_t", "uint64_t", "uint8_t", "uniform", "union", "unsigned", "usampler1D",
    "usampler1DArray", "usampler2D", "usampler2DArray", "usampler2DMS", "usampler2DMSArray", "usampler2DRect",
    "usampler3D", "usamplerBuffer", "usamplerCube", "usamplerCubeArray", "using", "usubpassInput", "uvec2",
    "uvec3", "uvec4", "varying", "vec2", "vec3", "vec4", "void", "volatile", "while", "writeonly",
}};

/// Whether `name` cannot be a GLSL identifier we declare: a reserved word, a gl_ prefix, or a double underscore.
constexpr bool is_glsl_reserved(std::string_view name) {
  if (name.starts_with("gl_") || name.find("__") != std::string_view::npos) return true;
  return std::binary_search(glsl_reserved_words.begin(), glsl_reserved_words.end(), name);
}

}  // namespace proceduray
