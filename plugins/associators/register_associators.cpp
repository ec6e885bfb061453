// Registers the associator components: `associator: hungarian` or `associator: greedy`.
#include <kestrel/plugin.hpp>

#include "associators.hpp"

KESTREL_REGISTER_COMPONENT(kestrel::tracking::Associator, kestrel::tracking::HungarianAssociator)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Associator, kestrel::tracking::GreedyAssociator)
