// The guidance laws the aim planner ships (kestrel/guidance/*.hpp); a plugin can register more.
#include <kestrel/guidance/fast_response_pn.hpp>
#include <kestrel/guidance/hold_aim.hpp>
#include <kestrel/guidance/predictive.hpp>
#include <kestrel/guidance/proportional_navigation.hpp>
#include <kestrel/guidance/pursuit.hpp>
#include <kestrel/guidance/run_in.hpp>
#include <kestrel/plugin.hpp>

KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::HoldAim)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::Pursuit)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::ProportionalNavigation)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::FastResponsePn)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::Predictive)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::RunIn)
