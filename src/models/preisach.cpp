#include "hyst/models/preisach.hpp"

namespace hyst {

template class BasicPreisach<RelayGridEverett>;
template class BasicPreisach<GaussianEverett>;
template class BasicPreisach<LorentzianEverett>;
template class BasicPreisach<TabulatedEverett>;

}  // namespace hyst
