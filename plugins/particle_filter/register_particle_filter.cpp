// The `particle` filter component of the tracker (filter: {type: particle, ...}).
#include <kestrel/plugin.hpp>

#include "particle_filter.hpp"

KESTREL_REGISTER_COMPONENT(kestrel::tracking::Filter, kestrel::tracking::ParticleFilter)
