#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/device_address.hpp>
// @declarations
void usage() {
  // @statements
}
