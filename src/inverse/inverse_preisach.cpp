#include "hyst/inverse/inverse_preisach.hpp"

namespace hyst {

template class BasicInversePreisach<RelayGridEverett>;
template class BasicInversePreisach<GaussianEverett>;
template class BasicInversePreisach<LorentzianEverett>;
template class BasicInversePreisach<TabulatedEverett>;

}  // namespace hyst
