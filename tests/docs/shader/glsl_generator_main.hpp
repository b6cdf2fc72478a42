// The block's my_types.hpp: registers a type and defines my::Interface.
// @skip-include "my_types.hpp"
#include <proceduray/shader/categories.hpp>
#include "tests/docs/doc_types.hpp"
namespace my {
using Interface = proceduray::ShaderInterface<proceduray::Payload<doc_types::RadiancePayload>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<>, proceduray::Attributes<>>;
}  // namespace my
// @declarations
