#pragma once
// The comparison page's own script (src/plot/comparison_page.js, embedded at build time) and
// where the plotting library it needs is read from.

namespace hyst::plot::detail {

extern const char* const kComparisonPageScript;

}  // namespace hyst::plot::detail
