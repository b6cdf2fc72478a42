// The bodies of proceduray/scene/sbt_printer.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/sbt_printer.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::detail {

PROCEDURAY_DECL std::string format_table(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width;
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()));
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line;
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      const std::string& cell = rows[r][c];
      const bool number = r != 0 && !cell.empty() && (std::isdigit(static_cast<unsigned char>(cell[0])) != 0);
      const std::string pad(width[c] - cell.size(), ' ');
      line += (c == 0 ? "" : " | ") + (number ? pad + cell : cell + pad);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + '\n';
    if (r == 0) {
      std::string rule;
      for (std::size_t c = 0; c < width.size(); ++c) rule += (c == 0 ? "" : "-+-") + std::string(width[c], '-');
      out += rule + '\n';
    }
  }
  return out;
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL std::string format_sbt(const Plan& sbt, const SbtLayout& layout, std::size_t max_records) {
  const PipelinePlan& plan = sbt.pipeline();
  std::string out = std::string("SBT: ") + std::to_string(layout.size) + " bytes; handle " +
                    std::to_string(layout.properties.handle_size) + ", handle alignment " +
                    std::to_string(layout.properties.handle_alignment) + ", base alignment " +
                    std::to_string(layout.properties.base_alignment) + "; sbtRecordStride (ray types) " +
                    std::to_string(sbt.ray_count()) + "\n";
  std::vector<std::vector<std::string>> regions{{"region", "offset", "stride", "size", "records"}};
  for (std::uint32_t k = 0; k < 4; ++k) {
    const SbtRegion& r = layout.regions[k];
    regions.push_back({to_string(static_cast<SbtRegionKind>(k)), std::to_string(r.offset), std::to_string(r.stride),
                       std::to_string(r.size), std::to_string(r.count)});
  }
  out += detail::format_table(regions) + '\n';
  auto name_or_dash = [](const std::string& s) { return s.empty() ? std::string("-") : s; };
  std::vector<std::vector<std::string>> records{
      {"region", "record", "offset", "group", "ray", "geometry", "instance", "arguments at", "arguments bytes"}};
  for (std::uint32_t k = 0; k < 4; ++k) {
    const auto kind = static_cast<SbtRegionKind>(k);
    const auto list = sbt.records(kind);
    for (std::uint32_t i = 0; i < list.size() && i < max_records; ++i) {
      const SbtRecord& r = list[i];
      const Entry* e = sbt.entry(r);
      records.push_back(
          {to_string(kind), std::to_string(i), std::to_string(layout.record_offset(kind, i)),
           r.group == no_index ? std::string("(null)") : plan.groups[r.group].name,
           r.ray == no_index ? "-" : name_or_dash(sbt.ray_name(r.ray)),
           r.geometry == no_index ? "-" : sbt.geometries()[r.geometry].name,
           kind != SbtRegionKind::hit ? "-" : (r.instance == no_index ? "*" : std::to_string(r.instance)),
           std::to_string(layout.arguments_offset(kind, i)), std::to_string(e ? e->arguments_size : 0)});
    }
    if (list.size() > max_records) {
      records.push_back({to_string(kind), "...", "", std::string("(") + std::to_string(list.size() - max_records) + " more)"});
    }
  }
  out += detail::format_table(records) + '\n';
  std::vector<std::vector<std::string>> instances{{"TLAS instance", "BLAS", "instance", "sbt offset", "mask"}};
  auto hex = [](std::uint8_t m) {
    const char digits[] = "0123456789abcdef";
    return std::string("0x") + digits[m >> 4] + digits[m & 15];
  };
  const auto tlas = sbt.instances();
  for (std::size_t i = 0; i < tlas.size() && i < max_records; ++i) {
    instances.push_back({std::to_string(i), sbt.blases()[tlas[i].blas].name, std::to_string(tlas[i].instance),
                         std::to_string(tlas[i].sbt_offset), hex(tlas[i].mask)});
  }
  if (tlas.size() > max_records) instances.push_back({"...", std::string("(") + std::to_string(tlas.size() - max_records) + " more)"});
  out += detail::format_table(instances);
  return out;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
