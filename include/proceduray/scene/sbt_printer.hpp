// ASCII printer of a compiled scene's shader binding table as laid out for a device, for
// debugging and docs.
//
//   const proceduray::Plan plan = proceduray::compile(scene);
//   std::cout << proceduray::format_sbt(plan, plan.layout(limits));
//
// It prints the regions (offset, stride, size, count), every record (region, index, byte
// offset, group, ray, geometry, instance, arguments offset and size; instance "*" = the block
// shared by instances without their own entries), and the TLAS instances' SBT offsets and masks.
#pragma once

#include <proceduray/config.hpp>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "proceduray/scene/plan.hpp"

namespace proceduray {

namespace detail {
/// Renders rows as a table with columns separated by " | ", numbers right-aligned.
PROCEDURAY_DECL std::string format_table(const std::vector<std::vector<std::string>>& rows);
}  // namespace detail

/// The table as text: regions, records (at most `max_records` per region), TLAS instances (at most `max_records`).
PROCEDURAY_DECL std::string format_sbt(const Plan& sbt, const SbtLayout& layout, std::size_t max_records = 1000);

}  // namespace proceduray

#include "proceduray/scene/sbt_printer-inl.hpp"  // the bodies (config.hpp)
