// The components the aim planner ships: its guidance laws (kestrel/guidance/*.hpp), the
// predictor of the target's futures, the fire policies and the searches for a lost target; a
// plugin can register more.
#include <kestrel/guidance/fast_response_pn.hpp>
#include <kestrel/guidance/hold_aim.hpp>
#include <kestrel/guidance/intercept_search.hpp>
#include <kestrel/guidance/predictive.hpp>
#include <kestrel/guidance/proportional_navigation.hpp>
#include <kestrel/guidance/pursuit.hpp>
#include <kestrel/guidance/run_in.hpp>
#include <kestrel/guidance/target_futures.hpp>
#include <kestrel/plugin.hpp>

#include "fire_policy.hpp"
#include "search.hpp"

KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::HoldAim)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::Pursuit)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::ProportionalNavigation)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::FastResponsePn)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::Predictive)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::RunIn)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Guidance, kestrel::guidance::InterceptSearch)
KESTREL_REGISTER_COMPONENT(kestrel::guidance::Predictor, kestrel::guidance::ImmSamples)
KESTREL_REGISTER_COMPONENT(kestrel::aim::FirePolicy, kestrel::aim::ThresholdFire)
KESTREL_REGISTER_COMPONENT(kestrel::aim::FirePolicy, kestrel::aim::CaptureValue)
KESTREL_REGISTER_COMPONENT(kestrel::aim::Search, kestrel::aim::HoldSearch)
KESTREL_REGISTER_COMPONENT(kestrel::aim::Search, kestrel::aim::TurnSearch)
KESTREL_REGISTER_COMPONENT(kestrel::aim::Search, kestrel::aim::BackOffSearch)
