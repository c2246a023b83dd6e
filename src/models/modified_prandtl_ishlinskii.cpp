#include "hyst/models/modified_prandtl_ishlinskii.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

template <class Part>
Part validated(typename Part::Params params, std::string_view prefix) {
  try {
    return Part(std::move(params));
  } catch (const Error& error) {
    throw Error(fmt::format("modified PI {}: {}", prefix, error.what()),
                fmt::format("{}.{}", prefix, error.field()));
  }
}

}  // namespace

ModifiedPrandtlIshlinskii::ModifiedPrandtlIshlinskii(Params params)
    : params_(std::move(params)),
      pi_(validated<PrandtlIshlinskii>(params_.pi, "pi")),
      dead_zone_(validated<DeadZoneSuperposition>(params_.dead_zone, "dead_zone")) {
  if (!std::isfinite(params_.offset)) {
    throw Error(fmt::format("modified PI offset = {} is not finite", params_.offset), "offset");
  }
  if (!(params_.output_min < params_.output_max)) {
    throw Error(fmt::format("modified PI output_min = {} must be < output_max = {}",
                            params_.output_min, params_.output_max),
                "output_min");
  }
}

}  // namespace hyst
