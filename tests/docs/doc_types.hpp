// Types the usage blocks use without declaring them (each prelude brings them in with
// `using namespace doc_types;`); a block's own declaration of a name hides the one here.
#pragma once

#include <proceduray/shader/camera.hpp>
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/device_address.hpp>
#include <proceduray/shader/field_list.hpp>

#include <cstdint>

namespace doc_types {
using std::uint32_t;
struct Sphere { glm::vec3 center; float radius; };
PROCEDURAY_STRUCT(Sphere, scalar, center, radius);
struct RadiancePayload { glm::vec3 colour; std::uint32_t depth; };
PROCEDURAY_STRUCT(RadiancePayload, scalar, colour, depth);
using RayPayload = RadiancePayload;
using Payload = RadiancePayload;
struct ShadowPayload { std::uint32_t hit; };
PROCEDURAY_STRUCT(ShadowPayload, scalar, hit);
struct Material { glm::vec4 albedo; };
PROCEDURAY_STRUCT(Material, scalar, albedo);
using MaterialRecord = Material;
struct SphereRecord { proceduray::DeviceAddress<Sphere> spheres; std::uint32_t count; std::uint32_t pad; };
PROCEDURAY_STRUCT(SphereRecord, scalar, spheres, count, pad);
struct BoxRecord { glm::vec4 colour; };
PROCEDURAY_STRUCT(BoxRecord, scalar, colour);
struct SphereHit { glm::vec3 normal; float t; };
PROCEDURAY_STRUCT(SphereHit, scalar, normal, t);
using Attributes = SphereHit;
using PacmanAttributes = SphereHit;
using ProceduralHit = SphereHit;
using Hit = SphereHit;
struct ProceduralArgs { glm::vec4 albedo; std::uint32_t instance; };
PROCEDURAY_STRUCT(ProceduralArgs, scalar, albedo, instance);
using Arguments = ProceduralArgs;
using TriangleArgs = ProceduralArgs;
using SkyArgs = BoxRecord;
struct TintCall { glm::vec3 colour; };
PROCEDURAY_STRUCT(TintCall, scalar, colour);
struct TintArgs { glm::vec4 tint; };
PROCEDURAY_STRUCT(TintArgs, scalar, tint);
using Tint = TintArgs;
struct SceneConstants { proceduray::Camera camera; glm::vec4 light; float time; };
PROCEDURAY_STRUCT(SceneConstants, scalar, camera, light, time);
struct FrameKnobs { float exposure; std::uint32_t frame; };
PROCEDURAY_STRUCT(FrameKnobs, scalar, exposure, frame);
using Frame = FrameKnobs;
using Radiance = RadiancePayload;
using Shadow = ShadowPayload;
/// The interface the blocks' scenes are declared from: every type above in its category.
using DocInterface = proceduray::ShaderInterface<
    proceduray::Payload<RadiancePayload, ShadowPayload, TintCall>, proceduray::RootComponent<SceneConstants, TintArgs, FrameKnobs>,
    proceduray::RootArguments<Material, SphereRecord, BoxRecord, ProceduralArgs, TintArgs>, proceduray::Attributes<SphereHit>>;
}  // namespace doc_types
