// Tests for proceduray/shader/layout.hpp: the rules by hand, and the proof that they (and the C++
// layout of every test type) equal what glslang assigns to the generated GLSL.
#include <proceduray/shader/layout.hpp>

#include "test_types.hpp"

#include <proceduray/shader/glsl_codegen.hpp>

#include <doctest/doctest.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <cstddef>
#include <map>
#include <string>

using proceduray::LayoutRule;
using proceduray::type_ops;
using namespace shader_test;

namespace {

constexpr LayoutRule all_rules[] = {LayoutRule::scalar, LayoutRule::std430, LayoutRule::std140};

// Leaf name -> offset, named the way glslang's reflection names buffer variables.
struct Leaf {
  std::size_t offset = 0;
  std::size_t stride = 0;  // array stride of a leaf array, else 0
};
using Leaves = std::map<std::string, Leaf>;

// Offsets of every leaf: from C++ (offsetof/sizeof) when host is true, else from the rule.
void flatten(const proceduray::TypeOps& s, LayoutRule rule, bool host, const std::string& prefix, std::size_t base,
             Leaves& out) {
  for (std::size_t i = 0; i < s.field_count; ++i) {
    const proceduray::Field& f = s.fields[i];
    const std::size_t at = base + (host ? f.offset : proceduray::field_offset(s, i, rule));
    const std::string name = prefix + "." + std::string(f.name);
    const proceduray::TypeOps& t = *f.type;
    if (t.kind == proceduray::TypeKind::structure) {
      flatten(t, rule, host, name, at, out);
    } else if (t.kind == proceduray::TypeKind::array) {
      const std::size_t stride = host ? t.element->cpp_size : proceduray::array_stride(t, rule);
      const proceduray::TypeOps& e = *t.element;
      for (std::uint32_t k = 0; k < t.count; ++k) {
        const std::string item = name + "[" + std::to_string(k) + "]";
        if (e.kind == proceduray::TypeKind::structure) {
          flatten(e, rule, host, item, at + k * stride, out);
        } else if (e.kind == proceduray::TypeKind::array) {  // glslang lists [k][0] with the inner stride
          out[item + "[0]"] = {at + k * stride, host ? e.element->cpp_size : proceduray::array_stride(e, rule)};
        } else if (k == 0) {
          out[item] = {at, stride};
        }
      }
    } else {
      out[name] = {at, 0};
    }
  }
}

struct Reflected {
  Leaves leaves;
  std::size_t block_size = 0;
  std::string log;
};

// Compiles `source` as `stage` and returns glslang's offsets of the variables of the block named `block`.
Reflected reflect(const std::string& source, EShLanguage stage, const std::string& block) {
  Reflected r;
  glslang::TShader shader(stage);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 460, false, messages)) {
    r.log = std::string(shader.getInfoLog()) + "\n" + source;
    return r;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages) || !program.buildReflection(EShReflectionAllBlockVariables | EShReflectionSeparateBuffers | EShReflectionBasicArraySuffix)) {
    r.log = program.getInfoLog();
    return r;
  }
  for (int i = 0; i < program.getNumBufferVariables(); ++i) {
    const glslang::TObjectReflection& v = program.getBufferVariable(i);
    if (v.name.rfind(block + ".", 0) == 0) {
      r.leaves[v.name.substr(block.size())] = {static_cast<std::size_t>(v.offset),
                                               static_cast<std::size_t>(v.arrayStride)};
    }
  }
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {  // push-constant and uniform blocks
    const glslang::TObjectReflection& v = program.getUniform(i);
    if (v.name.rfind(block + ".", 0) == 0) {
      r.leaves[v.name.substr(block.size())] = {static_cast<std::size_t>(v.offset),
                                               static_cast<std::size_t>(v.arrayStride)};
    }
  }
  for (int i = 0; i < program.getNumBufferBlocks(); ++i) {
    if (program.getBufferBlock(i).name == block) r.block_size = static_cast<std::size_t>(program.getBufferBlock(i).size);
  }
  for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
    if (program.getUniformBlock(i).name == block) {
      r.block_size = static_cast<std::size_t>(program.getUniformBlock(i).size);
    }
  }
  return r;
}

struct Glslang {
  Glslang() { glslang::InitializeProcess(); }
  ~Glslang() { glslang::FinalizeProcess(); }
};

// Compiles T's declarations and a compute-shader block of T under `rule`; checks glslang's offsets
// equal the rule's, and equal C++'s wherever the rule matches the host layout.
template <class T>
void prove(LayoutRule rule) {
  static const Glslang process;
  const proceduray::TypeOps& t = type_ops<T>;
  const proceduray::TypeOps* roots[] = {&t};
  const std::string first(t.fields[0].name);
  const std::string source = "#version 460\n#extension GL_EXT_scalar_block_layout : enable\n" +
                             proceduray::glsl_declarations(roots, false) +
                             proceduray::glsl_block(t, rule, "binding = 0", "Proof", "proof") +
                             "layout(local_size_x = 1) in;\nvoid main() { proof." + first + " = proof." + first +
                             "; }\n";
  const Reflected glsl = reflect(source, EShLangCompute, "Proof");
  INFO(t.glsl_name, " under ", proceduray::to_string(rule));
  REQUIRE_MESSAGE(glsl.log.empty(), glsl.log);
  Leaves predicted, host;
  flatten(t, rule, false, "", 0, predicted);
  flatten(t, rule, true, "", 0, host);
  REQUIRE(!glsl.leaves.empty());
  for (const auto& member : glsl.leaves) {
    const std::string& name = member.first;  // not a structured binding: clang 14 cannot capture one
    const auto& leaf = member.second;
    INFO("member ", name);
    REQUIRE(predicted.count(name) == 1);
    CHECK(predicted[name].offset == leaf.offset);
    CHECK(predicted[name].stride == leaf.stride);
  }
  CHECK(glsl.leaves.size() == predicted.size());
  // glslang reports the block's size without trailing padding; std430/std140 round it up, scalar does not.
  const proceduray::Extent extent = proceduray::extent_of(t, rule);
  CHECK((rule == LayoutRule::scalar ? glsl.block_size : proceduray::round_up(glsl.block_size, extent.align)) ==
        extent.size);
  if (proceduray::matches_host(t, rule)) {
    for (const auto& member : glsl.leaves) {
      const std::string& name = member.first;  // not a structured binding: clang 14 cannot capture one
      const auto& leaf = member.second;
      INFO("member ", name);
      CHECK(host[name].offset == leaf.offset);
      CHECK(host[name].stride == leaf.stride);
    }
    CHECK(proceduray::round_up(glsl.block_size, alignof(T)) == sizeof(T));
  }
}

template <class... Ts>
void prove_all() {
  for (LayoutRule rule : all_rules) (prove<Ts>(rule), ...);
}

}  // namespace

TEST_CASE("scalar rule aligns to components") {
  constexpr auto r = LayoutRule::scalar;
  static_assert(proceduray::extent_of(type_ops<glm::vec3>, r).align == 4);
  static_assert(proceduray::extent_of(type_ops<glm::mat4x3>, r).size == 48);
  static_assert(proceduray::field_offset(type_ops<ScalarMix>, 7, r) == 80);
  CHECK(proceduray::extent_of(type_ops<double>, r).align == 8);
  CHECK(proceduray::array_stride(type_ops<glm::vec3[4]>, r) == 12);
}

TEST_CASE("scalar rule leaves struct and array tails unpadded") {
  constexpr auto r = LayoutRule::scalar;
  // TailPadded without its pad would end at 12: the next member would sit there, not at 16.
  static_assert(proceduray::field_offset(type_ops<TailPadded>, 2, r) == 12);
  CHECK(proceduray::extent_of(type_ops<TailPadded>, r).size == 16);
  CHECK(proceduray::extent_of(type_ops<TailPadded>, r).align == 8);
  CHECK(proceduray::extent_of(type_ops<TailHolder>, r).size == 40);
  CHECK(proceduray::extent_of(type_ops<TailHolder>, LayoutRule::std430).size == 40);
}

TEST_CASE("std430 rule aligns vec3 to 16 and keeps scalar array strides") {
  constexpr auto r = LayoutRule::std430;
  static_assert(proceduray::extent_of(type_ops<glm::vec3>, r).align == 16);
  static_assert(proceduray::extent_of(type_ops<glm::vec2>, r).align == 8);
  CHECK(proceduray::array_stride(type_ops<float[4]>, r) == 4);
  CHECK(proceduray::array_stride(type_ops<glm::vec3[2]>, r) == 16);
  CHECK(proceduray::matrix_stride(type_ops<glm::mat4x3>, r) == 16);
  CHECK(proceduray::extent_of(type_ops<glm::mat4x3>, r).size == 64);
  CHECK(proceduray::extent_of(type_ops<Light>, r).size == 48);
}

TEST_CASE("std140 rule rounds arrays and structs to 16") {
  constexpr auto r = LayoutRule::std140;
  CHECK(proceduray::array_stride(type_ops<float[4]>, r) == 16);
  CHECK(proceduray::extent_of(type_ops<Inner140>, r).align == 16);
  CHECK(proceduray::field_offset(type_ops<Outer140>, 2, r) == 32);
  CHECK(proceduray::extent_of(type_ops<Sphere>, r).size == 16);
}

TEST_CASE("matches_host tells which rules a C++ struct satisfies") {
  CHECK(proceduray::matches_host(type_ops<Sphere>, LayoutRule::scalar));
  CHECK(proceduray::matches_host(type_ops<Sphere>, LayoutRule::std430));
  CHECK(proceduray::matches_host(type_ops<Light>, LayoutRule::std140));
  CHECK_FALSE(proceduray::matches_host(type_ops<Basis>, LayoutRule::std430));  // mat4x3 columns pad to 16
  CHECK_FALSE(proceduray::matches_host(type_ops<Material430>, LayoutRule::std140));  // uint[4] strides 16
  CHECK_FALSE(proceduray::matches_host(type_ops<ScalarMix>, LayoutRule::std430));
}

TEST_CASE("layout_mismatch names the struct member and rule") {
  CHECK(proceduray::layout_mismatch(type_ops<Sphere>, LayoutRule::scalar).empty());
  CHECK(proceduray::layout_mismatch(type_ops<Material430>, LayoutRule::std140) ==
        "shader_test::Material430::flags: array stride is 4 in C++ but 16 under std140");
  CHECK(proceduray::layout_mismatch(type_ops<ScalarMix>, LayoutRule::std430) ==
        "shader_test::ScalarMix::v: offset is 8 in C++ but 16 under std430");
  CHECK(proceduray::layout_mismatch(type_ops<Basis>, LayoutRule::std430) ==
        "shader_test::Basis::frame: size is 48 in C++ but 64 under std430");
}

TEST_CASE("glslang offsets equal the computed and C++ offsets for scalar test types") {
  prove_all<Sphere, Basis, ScalarMix, TailPadded, TailHolder>();
}

TEST_CASE("glslang offsets equal the computed and C++ offsets for std430 test types") {
  prove_all<Light, Material430, ListNode>();
}

TEST_CASE("glslang offsets equal the computed and C++ offsets for std140 test types") {
  prove_all<Camera140, Inner140, Outer140>();
}

TEST_CASE("glslang offsets equal the computed and C++ offsets for the interface types") {
  prove_all<RadiancePayload, ShadowPayload, SphereRecord, SphereHit>();
}

TEST_CASE("the shaderRecordEXT block of a closest-hit shader has the C++ offsets") {
  static const Glslang process;
  const std::string source =
      "#version 460\n" + proceduray::glsl_declarations(Interface::types) +
      proceduray::glsl_ray_payload(Interface::payload_location<RadiancePayload>(), type_ops<RadiancePayload>, "payload", true) +
      proceduray::glsl_ray_payload(Interface::payload_location<ShadowPayload>(), type_ops<ShadowPayload>, "shadow") +
      proceduray::glsl_hit_attribute(type_ops<SphereHit>, "hit") +
      proceduray::glsl_root_arguments(type_ops<SphereRecord>, "arguments") +
      "void main() {\n"
      "    payload.color = arguments.albedo.rgb * hit.normal * arguments.spheres.data[arguments.count - 1].radius;\n"
      "    shadow.occluded = 0;\n"
      "}\n";
  const Reflected glsl = reflect(source, EShLangClosestHit, "SphereRecordRootArguments");
  REQUIRE_MESSAGE(glsl.log.empty(), glsl.log);
  Leaves host;
  flatten(type_ops<SphereRecord>, LayoutRule::scalar, true, "", 0, host);
  // glslang also reflects what the shader reads through the buffer reference: arguments.spheres.data[i].radius.
  host[".spheres.radius"] = {offsetof(Sphere, radius), 0};
  REQUIRE(glsl.leaves.size() == host.size());
  for (const auto& member : glsl.leaves) {
    const std::string& name = member.first;  // not a structured binding: clang 14 cannot capture one
    const auto& leaf = member.second;
    INFO("member ", name);
    REQUIRE(host.count(name) == 1);
    CHECK(host[name].offset == leaf.offset);
  }
  CHECK(glsl.block_size == sizeof(SphereRecord));
}

TEST_CASE("a push-constant block has the C++ offsets") {
  static const Glslang process;
  const proceduray::TypeOps* roots[] = {&type_ops<Camera140>};
  const std::string source = "#version 460\n" + proceduray::glsl_declarations(roots, false) +
                             proceduray::glsl_push_constant<Camera140>("camera") +
                             "layout(local_size_x = 1) in;\nvoid main() { float f = camera.fov; }\n";
  const Reflected glsl = reflect(source, EShLangCompute, "Camera140PushConstants");
  REQUIRE_MESSAGE(glsl.log.empty(), glsl.log);
  Leaves host;
  flatten(type_ops<Camera140>, LayoutRule::std140, true, "", 0, host);
  REQUIRE(glsl.leaves.size() == host.size());
  for (const auto& member : glsl.leaves) {
    const std::string& name = member.first;  // not a structured binding: clang 14 cannot capture one
    const auto& leaf = member.second;
    INFO("member ", name);
    REQUIRE(host.count(name) == 1);
    CHECK(host[name].offset == leaf.offset);
  }
  CHECK(glsl.block_size == sizeof(Camera140));
}
