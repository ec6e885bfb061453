#pragma once
// The parameters every tracker node shares (track management and association), declared once so
// that kalman_tracker and particle_tracker cannot drift apart.
#include "kestrel/messages/detections.hpp"
#include "kestrel/node.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/track_manager.hpp"

namespace kestrel::tracking {

/// Adds max_misses, selection and associator to a tracker's spec.
NodeSpec& add_track_management_params(NodeSpec& spec);

/// A TrackManager configured from those parameters, with the tracker's filter factory.
TrackManager make_track_manager(NodeInit& init, FilterFactory factory);

/// One frame of detections through the manager, as a Tracks message in the detections' frame.
msg::Tracks track(TrackManager& manager, const msg::Detections& detections);

}  // namespace kestrel::tracking
