#pragma once
// The model-file fields the modified PI models share (modified_pi, modified_pi_creep): the
// dead-zone map, the output limits, and the file's flat names of the nested parts' fields.

#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "field_table.hpp"
#include "hyst/core/error.hpp"
#include "hyst/operators/dead_zone_superposition.hpp"

namespace hyst::detail {

// "dead_zone_thresholds" and "dead_zone_weights" of S.
inline FieldTable<DeadZoneSuperposition::Params> dead_zone_fields() {
  using DeadZone = DeadZoneSuperposition::Params;
  return FieldTable<DeadZone>()
      .add("dead_zone_thresholds", &DeadZone::thresholds, "output units",
           "d_i, increasing, one of them 0")
      .add("dead_zone_weights", &DeadZone::weights, "",
           "g_i; invertible iff outward partial sums > 0");
}

// The table of the dead zones for a model's description.
inline std::string describe_dead_zones(const DeadZoneSuperposition::Params& p) {
  std::string text = "   i   dead zone d_i      weight g_i\n";
  for (std::size_t i = 0; i < p.thresholds.size(); ++i)
    text += fmt::format("{:4}  {:14.8g}  {:14.8g}\n", i, p.thresholds[i], p.weights[i]);
  return text;
}

// "output_min" and "output_max": infinite (no clamp) by default and then left out of the file, as
// JSON has no infinity.
template <class P>
void add_output_limit(FieldTable<P>& table, const std::string& key, double P::*member,
                      std::string_view side) {
  table.add_custom(
      {key,
       "number",
       "output units",
       fmt::format("{} limit the output is clamped to (default: none; a fit sets the record's {})",
                   side, side == "lower" ? "minimum" : "maximum"),
       {}},
      Presence::optional,
      [key, member](JsonFields& fields, P& params) { params.*member = fields.number(key); },
      [key, member](const P& params, nlohmann::json& json) {
        if (std::isfinite(params.*member)) json[key] = params.*member;
      });
}

template <class P>
void add_output_limits(FieldTable<P>& table) {
  add_output_limit(table, "output_min", &P::output_min, "lower");
  add_output_limit(table, "output_max", &P::output_max, "upper");
}

// The fit options of the dead-zone map and the output limits.
template <class O>
FieldTable<O> add_dead_zone_fit_options(FieldTable<O> table) {
  return table.add("dead_zones", &O::dead_zones, "", "dead zones per side of the inverse map")
      .add("dead_zone_thresholds", &O::dead_zone_thresholds, "output units",
           "thresholds of the inverse dead-zone map around the offset, containing 0")
      .add("output_offset", &O::output_offset, "output units",
           "y_off (default: mid-range of the output)")
      .add("min_weight", &O::min_weight, "", "relative lower bound of p_0 and of the map's slopes")
      .add("clamp_output", &O::clamp_output, "",
           "limit the output to the fitted record's output range; false = no limits")
      .add("output_margin", &O::output_margin, "",
           "widen those limits by this fraction of the output range on each side");
}

// What follows the hysteresis part of a modified PI model: the dead zones, the output offset
// y_off and the output limits.
template <class P>
FieldTable<P>& add_output_shaping_fields(FieldTable<P>& table) {
  table.add_all(&P::dead_zone, dead_zone_fields())
      .add("offset", &P::offset, "output units", "y_off added after the dead zones",
           Presence::optional);
  add_output_limits(table);
  return table;
}

// A model's validation error ("params.pi.weights[0] ...") with the file's flat name of the field
// ("params.weights[0] ..."): `renames` maps a nested prefix to its flat form, the first match wins.
inline Error with_file_field_names(
    const Error& error,
    std::initializer_list<std::pair<std::string_view, std::string_view>> renames) {
  const std::string message = error.what();
  if (message.rfind("params.", 0) != 0) return error;
  const std::string field = message.substr(7);
  for (const auto& [from, to] : renames) {
    if (field.rfind(from, 0) == 0) {
      return Error("params." + std::string(to) + field.substr(from.size()), error.field());
    }
  }
  return error;
}

}  // namespace hyst::detail
