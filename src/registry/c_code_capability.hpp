#pragma once
// The C export capability of an entry (ModelEntry::c_code): the emitter of its concrete model
// (../export/c_emitters.hpp, found by overload on the model type) with the files' preamble.

#include <functional>

#include "../export/c_emitters.hpp"
#include "model_adapter.hpp"

namespace hyst::detail {

template <class... Codecs>
std::function<CCode(const DynamicModel&, const CExportOptions&)> c_code_of() {
  return [](const DynamicModel& model, const CExportOptions& options) {
    const CWriter writer(options.prefix, options.scalar);
    return with_concrete<Codecs...>(model, [&](const auto& concrete, const auto& state) {
      auto code = emit_c(concrete, state, writer, options);
      if (options.domain) add_c_domain(writer, *options.domain, code);
      return assemble_c_files(writer, code, options.source);
    });
  };
}

}  // namespace hyst::detail
