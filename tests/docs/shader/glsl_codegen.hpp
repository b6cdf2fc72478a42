#include <proceduray/shader/shader.hpp>
#include "tests/docs/doc_types.hpp"
using namespace doc_types;
using Interface = proceduray::ShaderInterface<proceduray::Payload<RadiancePayload, ShadowPayload>,
    proceduray::RootComponent<>, proceduray::RootArguments<SphereRecord>, proceduray::Attributes<SphereHit>>;
using proceduray::Camera;
// @declarations
void usage(const std::string& user_shader_text) {
  // @statements
}
