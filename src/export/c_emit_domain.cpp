// The fitted domain in exported C code: the ranges of the model file's info.domain, widened by
// kDomainMargin as the library's checks widen them, and functions that count the inputs (and
// inverse targets) beyond them. The step functions are unchanged: a controller calls the check
// beside them where it wants the count, and pays nothing where it does not.

#include <fmt/format.h>

#include "c_emitters.hpp"

namespace hyst::detail {

void add_c_domain(const CWriter& writer, const FittedDomain& domain, CModelCode& code) {
  const double input_margin = kDomainMargin * (domain.input_max - domain.input_min);
  const double output_margin = kDomainMargin * (domain.output_max - domain.output_min);
  code.description += fmt::format(
      " * Fitted domain (the model file's info.domain): inputs [{:.6g}, {:.6g}], outputs [{:.6g}, "
      "{:.6g}]; @_check_input{} count the samples beyond it by more than {:g} % of its width.\n",
      domain.input_min, domain.input_max, domain.output_min, domain.output_max,
      code.has_inverse ? " and @_check_target" : "", 100.0 * kDomainMargin);
  code.header += R"(
/* The domain the model was fitted on, widened by the margin of the library's checks: inputs
 * (and inverse targets) beyond it are extrapolation. The checks count them in a status the
 * caller keeps (status may be NULL); the step functions do not depend on them. */
typedef struct {
  @_real input_low, input_high;   /* fitted input range +- margin */
  @_real target_low, target_high; /* fitted output range +- margin: the targets of an inverse */
} @_domain;
extern const @_domain @_DOMAIN;

typedef struct {
  unsigned long samples;       /* checked so far */
  unsigned long outside;       /* of them beyond the domain (NaN too) */
  unsigned long first_outside; /* index of the first of them; valid when outside > 0 */
} @_domain_status;

void @_domain_status_reset(@_domain_status *status);
/* 1 when input lies in the domain, else 0; counted in status. */
int @_check_input(const @_domain *domain, @_domain_status *status, @_real input);
)";
  if (code.has_inverse) {
    code.header += R"(/* 1 when target lies among the fitted outputs, else 0; counted in status. */
int @_check_target(const @_domain *domain, @_domain_status *status, @_real target);
)";
  }
  code.source += CWriter::fill(R"(
const @_domain @_DOMAIN = {%IL%, %IH%, %TL%, %TH%};

void @_domain_status_reset(@_domain_status *status) {
  status->samples = 0;
  status->outside = 0;
  status->first_outside = 0;
}

static int @_count_inside(@_domain_status *status, int inside) {
  if (status) {
    if (!inside && status->outside++ == 0) status->first_outside = status->samples;
    ++status->samples;
  }
  return inside;
}

int @_check_input(const @_domain *domain, @_domain_status *status, @_real input) {
  return @_count_inside(status, input >= domain->input_low && input <= domain->input_high);
}
)",
                               {{"IL", writer.number(domain.input_min - input_margin)},
                                {"IH", writer.number(domain.input_max + input_margin)},
                                {"TL", writer.number(domain.output_min - output_margin)},
                                {"TH", writer.number(domain.output_max + output_margin)}});
  if (code.has_inverse) {
    code.source += R"(
int @_check_target(const @_domain *domain, @_domain_status *status, @_real target) {
  return @_count_inside(status, target >= domain->target_low && target <= domain->target_high);
}
)";
  }
}

}  // namespace hyst::detail
