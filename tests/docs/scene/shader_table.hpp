#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;

// @declarations
void usage(proceduray::Scene& scene, const proceduray::DeviceLimits& limits, proceduray::RayId<RadiancePayload> radiance, proceduray::RayId<ShadowPayload> shadow,
           proceduray::LocalSignatureId<SkyArgs> sky_signature, proceduray::HitGroupId plane_group,
           proceduray::LocalSignatureId<TriangleArgs> triangle_sig, proceduray::GeometryId plane, proceduray::HitGroupId pacman_group,
           proceduray::LocalSignatureId<ProceduralArgs> procedural_sig, proceduray::GeometryId pacman,
           proceduray::HitGroupId pacman_shadow, proceduray::HitGroupId plane_shadow, proceduray::CallableId<TintCall> tint, proceduray::LocalSignatureId<TintArgs> tint_signature) {
  // @statements
}
