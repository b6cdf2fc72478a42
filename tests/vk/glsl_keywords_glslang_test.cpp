// shader/glsl_keywords.hpp against glslang itself: every word of the families glslang reserves
// (texture, image and sampler types, explicit-arithmetic vectors and matrices, memory-model and
// mesh qualifiers, ray-tracing and SPIR-V-intrinsics keywords) that glslang refuses as a member
// name must be in the list, so a scene id never becomes a GLSL name that fails to compile.
#include <proceduray/shader/glsl_keywords.hpp>
#include <proceduray/vk/shader_compiler.hpp>

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <vector>

using namespace proceduray;

namespace {

/// Whether glslang refuses `word` as the name of a struct member in a raygen shader.
bool glslang_refuses(const std::string& word) {
  const std::string code = "#version 460\n#extension GL_EXT_ray_tracing : require\nstruct S { float " + word +
                           "; };\nvoid main() { S s; s." + word + " = 1.0; }\n";
  try {
    vk::compile_glsl({.stage = ShaderStage::raygen, .name = "keyword.rgen", .code = code});
    return false;
  } catch (const vk::ShaderCompileError&) {
    return true;
  }
}

/// Words of the families glslang knows, generated here (not from the list under test).
std::set<std::string> candidates() {
  std::set<std::string> out(glsl_reserved_words.begin(), glsl_reserved_words.end());
  const char* dims[] = {"1D", "1DArray", "2D", "2DArray", "2DMS", "2DMSArray", "2DRect", "3D", "Buffer", "Cube", "CubeArray"};
  for (const char* pre : {"", "i", "u", "f16"}) {
    for (const char* kind : {"texture", "image", "sampler"}) {
      for (const char* d : dims) out.insert(std::string(pre) + kind + d);
    }
    for (const char* s : {"subpassInput", "subpassInputMS", "attachmentEXT"}) out.insert(std::string(pre) + s);
  }
  for (const char* e : {"i", "u", "f"}) {
    for (const char* bits : {"8", "16", "32", "64"}) {
      for (const char* n : {"2", "3", "4"}) {
        out.insert(std::string(e) + bits + "vec" + n);
        out.insert(std::string(e) + bits + "mat" + n);
        for (const char* m : {"2", "3", "4"}) out.insert(std::string(e) + bits + "mat" + n + "x" + m);
      }
    }
  }
  for (const char* w : {"devicecoherent", "queuefamilycoherent", "workgroupcoherent", "subgroupcoherent", "nonprivate",
                        "shadercallcoherent", "pervertexEXT", "pervertexNV", "perprimitiveNV", "perprimitiveEXT",
                        "perviewNV", "taskNV", "taskPayloadSharedEXT", "rayPayloadNV", "hitAttributeNV",
                        "callableDataNV", "accelerationStructureNV", "hitObjectNV", "spirv_instruction", "spirv_type",
                        "spirv_decorate", "spirv_literal", "spirv_by_reference", "spirv_storage_class",
                        "samplerExternalOES", "nonuniformEXT", "rayQueryEXT", "demote", "fcoopmatNV"}) {
    out.insert(w);
  }
  return out;
}

}  // namespace

TEST_CASE("glsl_keywords every word glslang refuses as a name is reserved") {
  REQUIRE_FALSE(glslang_refuses("radius"));  // the probe accepts an ordinary name
  std::vector<std::string> missing;
  std::size_t refused = 0;
  const std::set<std::string> words = candidates();
  for (const std::string& word : words) {
    if (!glslang_refuses(word)) continue;
    ++refused;
    if (!is_glsl_reserved(word)) missing.push_back(word);
  }
  std::string list;
  for (const std::string& m : missing) list += m + " ";
  CAPTURE(list);
  CHECK(missing.empty());
  MESSAGE("glslang refuses ", refused, " of ", words.size(), " candidates as names");
  CHECK(refused > 200);  // the probe does refuse: the families are real keywords
}

TEST_CASE("glsl_keywords the words the issue found are refused by glslang and reserved here") {
  for (const char* word : {"texture2DRect", "itexture2D", "utexture3D", "devicecoherent", "pervertexEXT"}) {
    CAPTURE(word);
    CHECK(glslang_refuses(word));
    CHECK(is_glsl_reserved(word));
  }
}
