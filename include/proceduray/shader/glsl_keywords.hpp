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

/// GLSL 4.60 keywords, reserved words, basic type names (incl. explicit-arithmetic, texture, subpass,
/// memory-model, mesh, ray-tracing and SPIR-V-intrinsics extensions, as glslang's scanner knows them)
/// and `main`, sorted so lookups are a binary search. tests/vk/glsl_keywords_glslang_test.cpp
/// checks that every word of these families that glslang refuses as a name is here.
inline constexpr std::array<std::string_view, 435> glsl_reserved_words = {{
    "accelerationStructureEXT", "accelerationStructureNV", "active", "asm", "atomic_uint", "attachmentEXT",
    "attribute", "bool", "break", "buffer", "bvec2", "bvec3", "bvec4", "callableDataEXT", "callableDataInEXT",
    "callableDataInNV", "callableDataNV", "case", "cast", "centroid", "class", "coherent", "common", "const",
    "continue", "coopmat", "default", "demote", "devicecoherent", "discard", "dmat2", "dmat2x2", "dmat2x3",
    "dmat2x4", "dmat3", "dmat3x2", "dmat3x3", "dmat3x4", "dmat4", "dmat4x2", "dmat4x3", "dmat4x4", "do",
    "double", "dvec2", "dvec3", "dvec4", "else", "enum", "explicitInterpAMD", "extern", "external",
    "f16image1D", "f16image1DArray", "f16image2D", "f16image2DArray", "f16image2DMS", "f16image2DMSArray",
    "f16image2DRect", "f16image3D", "f16imageBuffer", "f16imageCube", "f16imageCubeArray", "f16mat2",
    "f16mat2x2", "f16mat2x3", "f16mat2x4", "f16mat3", "f16mat3x2", "f16mat3x3", "f16mat3x4", "f16mat4",
    "f16mat4x2", "f16mat4x3", "f16mat4x4", "f16sampler1D", "f16sampler1DArray", "f16sampler1DArrayShadow",
    "f16sampler1DShadow", "f16sampler2D", "f16sampler2DArray", "f16sampler2DArrayShadow", "f16sampler2DMS",
    "f16sampler2DMSArray", "f16sampler2DRect", "f16sampler2DRectShadow", "f16sampler2DShadow", "f16sampler3D",
    "f16samplerBuffer", "f16samplerCube", "f16samplerCubeArray", "f16samplerCubeArrayShadow",
    "f16samplerCubeShadow", "f16texture1D", "f16texture1DArray", "f16texture2D", "f16texture2DArray",
    "f16texture2DMS", "f16texture2DMSArray", "f16texture2DRect", "f16texture3D", "f16textureBuffer",
    "f16textureCube", "f16textureCubeArray", "f16vec2", "f16vec3", "f16vec4", "f32mat2", "f32mat2x2",
    "f32mat2x3", "f32mat2x4", "f32mat3", "f32mat3x2", "f32mat3x3", "f32mat3x4", "f32mat4", "f32mat4x2",
    "f32mat4x3", "f32mat4x4", "f32vec2", "f32vec3", "f32vec4", "f64mat2", "f64mat2x2", "f64mat2x3",
    "f64mat2x4", "f64mat3", "f64mat3x2", "f64mat3x3", "f64mat3x4", "f64mat4", "f64mat4x2", "f64mat4x3",
    "f64mat4x4", "f64vec2", "f64vec3", "f64vec4", "false", "fcoopmatNV", "filter", "fixed", "flat", "float",
    "float16_t", "float32_t", "float64_t", "for", "fvec2", "fvec3", "fvec4", "goto", "half", "highp",
    "hitAttributeEXT", "hitAttributeNV", "hitObjectAttributeNV", "hitObjectNV", "hvec2", "hvec3", "hvec4",
    "i16vec2", "i16vec3", "i16vec4", "i32vec2", "i32vec3", "i32vec4", "i64vec2", "i64vec3", "i64vec4",
    "i8vec2", "i8vec3", "i8vec4", "iattachmentEXT", "icoopmatNV", "if", "ignoreIntersectionEXT",
    "ignoreIntersectionNV", "iimage1D", "iimage1DArray", "iimage2D", "iimage2DArray", "iimage2DMS",
    "iimage2DMSArray", "iimage2DRect", "iimage3D", "iimageBuffer", "iimageCube", "iimageCubeArray", "image1D",
    "image1DArray", "image2D", "image2DArray", "image2DMS", "image2DMSArray", "image2DRect", "image3D",
    "imageBuffer", "imageCube", "imageCubeArray", "in", "inline", "inout", "input", "int", "int16_t",
    "int32_t", "int64_t", "int8_t", "interface", "invariant", "isampler1D", "isampler1DArray",
    "isampler1DArrayShadow", "isampler1DShadow", "isampler2D", "isampler2DArray", "isampler2DArrayShadow",
    "isampler2DMS", "isampler2DMSArray", "isampler2DRect", "isampler2DRectShadow", "isampler2DShadow",
    "isampler3D", "isamplerBuffer", "isamplerCube", "isamplerCubeArray", "isamplerCubeArrayShadow",
    "isamplerCubeShadow", "isubpassInput", "isubpassInputMS", "itexture1D", "itexture1DArray", "itexture2D",
    "itexture2DArray", "itexture2DMS", "itexture2DMSArray", "itexture2DRect", "itexture3D", "itextureBuffer",
    "itextureCube", "itextureCubeArray", "ivec2", "ivec3", "ivec4", "layout", "long", "lowp", "main", "mat2",
    "mat2x2", "mat2x3", "mat2x4", "mat3", "mat3x2", "mat3x3", "mat3x4", "mat4", "mat4x2", "mat4x3", "mat4x4",
    "mediump", "namespace", "noinline", "nonprivate", "nonuniformEXT", "noperspective", "out", "output",
    "packed", "partition", "patch", "perprimitiveEXT", "perprimitiveNV", "pervertexEXT", "pervertexNV",
    "perviewNV", "precise", "precision", "public", "queuefamilycoherent", "rayPayloadEXT", "rayPayloadInEXT",
    "rayPayloadInNV", "rayPayloadNV", "rayQueryEXT", "readonly", "resource", "restrict", "return", "sample",
    "sampler", "sampler1D", "sampler1DArray", "sampler1DArrayShadow", "sampler1DShadow", "sampler2D",
    "sampler2DArray", "sampler2DArrayShadow", "sampler2DMS", "sampler2DMSArray", "sampler2DRect",
    "sampler2DRectShadow", "sampler2DShadow", "sampler3D", "sampler3DRect", "samplerBuffer", "samplerCube",
    "samplerCubeArray", "samplerCubeArrayShadow", "samplerCubeShadow", "samplerExternalOES", "samplerShadow",
    "shaderRecordEXT", "shadercallcoherent", "shared", "short", "sizeof", "smooth", "spirv_by_reference",
    "spirv_decorate", "spirv_decorate_id", "spirv_decorate_string", "spirv_execution_mode",
    "spirv_execution_mode_id", "spirv_instruction", "spirv_literal", "spirv_storage_class", "spirv_type",
    "static", "struct", "subgroupcoherent", "subpassInput", "subpassInputMS", "subroutine", "superp",
    "switch", "taskNV", "taskPayloadSharedEXT", "template", "tensorLayoutNV", "tensorViewNV",
    "terminateRayEXT", "terminateRayNV", "texture1D", "texture1DArray", "texture2D", "texture2DArray",
    "texture2DMS", "texture2DMSArray", "texture2DRect", "texture3D", "textureBuffer", "textureCube",
    "textureCubeArray", "this", "tileImageEXT", "true", "typedef", "u16vec2", "u16vec3", "u16vec4", "u32vec2",
    "u32vec3", "u32vec4", "u64vec2", "u64vec3", "u64vec4", "u8vec2", "u8vec3", "u8vec4", "uattachmentEXT",
    "ucoopmatNV", "uimage1D", "uimage1DArray", "uimage2D", "uimage2DArray", "uimage2DMS", "uimage2DMSArray",
    "uimage2DRect", "uimage3D", "uimageBuffer", "uimageCube", "uimageCubeArray", "uint", "uint16_t",
    "uint32_t", "uint64_t", "uint8_t", "uniform", "union", "unsigned", "usampler1D", "usampler1DArray",
    "usampler1DArrayShadow", "usampler1DShadow", "usampler2D", "usampler2DArray", "usampler2DArrayShadow",
    "usampler2DMS", "usampler2DMSArray", "usampler2DRect", "usampler2DRectShadow", "usampler2DShadow",
    "usampler3D", "usamplerBuffer", "usamplerCube", "usamplerCubeArray", "usamplerCubeArrayShadow",
    "usamplerCubeShadow", "using", "usubpassInput", "usubpassInputMS", "utexture1D", "utexture1DArray",
    "utexture2D", "utexture2DArray", "utexture2DMS", "utexture2DMSArray", "utexture2DRect", "utexture3D",
    "utextureBuffer", "utextureCube", "utextureCubeArray", "uvec2", "uvec3", "uvec4", "varying", "vec2",
    "vec3", "vec4", "void", "volatile", "while", "workgroupcoherent", "writeonly",
}};

/// Whether `name` cannot be a GLSL identifier we declare: a reserved word, a gl_ prefix, or a double underscore.
constexpr bool is_glsl_reserved(std::string_view name) {
  if (name.starts_with("gl_") || name.find("__") != std::string_view::npos) return true;
  return std::binary_search(glsl_reserved_words.begin(), glsl_reserved_words.end(), name);
}

}  // namespace proceduray
